// The axisymmetric cylinder-test deck inputs/validation/qm100curs_axisym_long.ups
// (issue 6, Vaango theory manual sec. 26.3.2; the stock MPMICE/QM100CuRS.ups
// made axisymmetric and 300 mm long, its header lists the changes): it
// validates, starts at rest at p0 everywhere, and the 400 m/s whacker drives
// a shock above the JWL++ ThresholdPressure into the explosive within 20
// steps. The long run, the 25 cm wall history and the Gurney comparison are
// tests/bench/qm100curs_long.py (docs/validation/qm100curs.md, session 24).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/TestPaths.h"

namespace fs = std::filesystem;
using tephra::test::run_tephra;

namespace {

std::string deck() { return tephra::test::source_dir() + "/inputs/validation/qm100curs_axisym_long.ups"; }

// (y, press_CC) of a `tephra extract --line` CSV along the axis, or (x, p) across.
std::vector<std::pair<double, double>> column(const std::string& text, int coord) {
  std::vector<std::pair<double, double>> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header: time,i,j,k,x,y,z,press_CC
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::istringstream ls(line);
    std::string s;
    while (std::getline(ls, s, ',')) f.push_back(s);
    if (f.size() == 8) rows.emplace_back(std::stod(f[4 + coord]), std::stod(f[7]));
  }
  return rows;
}

}  // namespace

TEST(Qm100CursLongDeck, Validates) {
  std::string out;
  EXPECT_EQ(run_tephra("--validate " + deck(), &out), 0) << out;
}

TEST(Qm100CursLongDeck, StartsAtRestAndTheWhackerDrivesAShock) {
  fs::path dir = tephra::test::scratch_dir("qm100curs_long_deck");
  std::string text = tephra::test::slurp(deck());
  const std::string every = "<outputInterval>1.00e-6</outputInterval>";
  auto at = text.find(every);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, every.size(), "<outputTimestepInterval> 20 </outputTimestepInterval>");
  std::ofstream(dir / "deck.ups") << text;
  std::string out;
  ASSERT_EQ(run_tephra((dir / "deck.ups").string() + " --output " + (dir / "run").string() +
                           " --max-steps 20 --threads 1 --quiet",
                       &out),
            0)
      << out;
  // Step 0 across the charge, wall and air at y = 100 mm: every cell at the
  // deck's p0 = 101325 Pa (a wall seeded with res z = 2 would carry twice its
  // mass in axisymmetry and start near -88 GPa: K (J - 1/J)/2, J = 1/2).
  ASSERT_EQ(run_tephra("extract " + (dir / "run").string() +
                           " --var press_CC --material 0 --step 0 --line 0.0005,0.1005,0.0005,0.0475,0.1005,0.0005",
                       &out),
            0)
      << out;
  auto across = column(out, 0);
  ASSERT_EQ(across.size(), 48u) << out;
  // The copper's pressure is K = 117 GPa times the round-off of its projected
  // per-radian density (measured 0.34 Pa = 2.9e-12 K): bound 1e-10 K = 11.7 Pa.
  for (auto [r, p] : across) EXPECT_NEAR(p, 101325.0, 1e-10 * 117.0e9) << "r = " << r;
  // Step 20 on the axis: the whacker (y < 1 mm, 400 m/s) has put the
  // explosive just ahead of it above the 200 MPa ThresholdPressure (the
  // acoustic estimate rho c u/2 with c ~ 2.5 km/s: ~0.6 GPa), and the cells
  // 10 mm on are still at p0.
  ASSERT_EQ(run_tephra("extract " + (dir / "run").string() +
                           " --var press_CC --material 0 --step 20 --line 0.0005,-0.0045,0.0005,0.0005,0.0195,0.0005",
                       &out),
            0)
      << out;
  double peak = 0, far = 0;
  for (auto [y, p] : column(out, 1)) {
    if (y > 0 && y < 0.004) peak = std::max(peak, p);
    if (y > 0.012) far = std::max(far, std::abs(p / 101325.0 - 1));
  }
  EXPECT_GT(peak, 2.0e8);
  EXPECT_LT(peak, 2.0e9);
  EXPECT_LT(far, 1e-6);
}
