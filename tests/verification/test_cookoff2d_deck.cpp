// The reduced fast-cookoff deck inputs/validation/cookoff2d.ups (Vaango theory
// manual sec. 26.3.3; issue 6): it validates, runs a few coupled steps with
// exit 0, and ignites the whole outer surface of the explosive at once, the
// manual's idealisation ("the temperature of the container was initialized to
// be 1 K above the ignition temperature ... the entire outer surface of the
// explosive is ignited simultaneously"). The long run and the rupture are
// tests/bench/cookoff2d.py (docs/validation/cookoff.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/TestPaths.h"

namespace fs = std::filesystem;
using tephra::test::run_tephra;

namespace {

std::string deck() { return tephra::test::source_dir() + "/inputs/validation/cookoff2d.ups"; }

// Rows of a `tephra extract` CSV (header first), split on commas.
std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> row;
    std::istringstream ls(line);
    std::string field;
    while (std::getline(ls, field, ',')) row.push_back(field);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST(Cookoff2dDeck, Validates) {
  std::string out;
  EXPECT_EQ(run_tephra("--validate " + deck(), &out), 0) << out;
}

TEST(Cookoff2dDeck, FourStepsIgniteTheWholeInnerSurfaceAtOnce) {
  // The deck with an output every 2 steps, run 4 steps.
  fs::path dir = tephra::test::scratch_dir("cookoff2d_deck");
  std::string text = tephra::test::slurp(deck());
  const std::string every = "<outputInterval> 5.0e-6 </outputInterval>";
  auto at = text.find(every);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, every.size(), "<outputTimestepInterval> 2 </outputTimestepInterval>");
  std::ofstream(dir / "cookoff2d.ups") << text;
  std::string out;
  ASSERT_EQ(run_tephra((dir / "cookoff2d.ups").string() + " --output " + (dir / "run").string() +
                           " --max-steps 4 --threads 1 --quiet",
                       &out),
            0)
      << out;

  // Burning cells after step 4. Oracle: the PBX fills [0, R_I] x [0, L_I],
  // R_I = L_I = 50.8 mm = N h with N = 40 cells of h = 1.27 mm; the steel is
  // at 551 K > IgnitionTemp 550 K, so Steady_Burn's rule (a surface cell of
  // the reactant with a hot neighbour) holds in every PBX cell along the steel
  // and nowhere else: the cells (i, N-1), i < N, and (N-1, j), j < N:
  // 2N - 1 = 79 cells, the whole outer surface of the explosive.
  ASSERT_EQ(run_tephra("extract " + (dir / "run").string() +
                           " --var SteadyBurn.BurningCell --material 0 --step 4",
                       &out),
            0)
      << out;
  auto rows = csv_rows(out);
  ASSERT_GT(rows.size(), 1u);
  ASSERT_EQ(rows[0].back(), "SteadyBurn.BurningCell") << out.substr(0, 200);
  const int N = 40;
  std::set<std::pair<int, int>> burning, expected;
  for (int k = 0; k < N; ++k) {
    expected.insert({k, N - 1});
    expected.insert({N - 1, k});
  }
  for (size_t r = 1; r < rows.size(); ++r)
    if (std::stod(rows[r].back()) > 0.5) burning.insert({std::stoi(rows[r][1]), std::stoi(rows[r][2])});
  EXPECT_EQ(expected.size(), 2u * N - 1);
  EXPECT_EQ(burning, expected);

  // The PBX has lost mass (it burns), and no steel particle has failed yet
  // (4 steps of ~1.7e-7 s: the walls are still elastic).
  auto pbx_mass = [&](int step) {
    std::string text;
    EXPECT_EQ(run_tephra("extract " + (dir / "run").string() + " --var p.mass --material 1 --step " +
                             std::to_string(step),
                         &text),
              0);
    double m = 0.0;
    auto r = csv_rows(text);
    for (size_t k = 1; k < r.size(); ++k) m += std::stod(r[k].back());
    return m;
  };
  const double m0 = pbx_mass(0), m4 = pbx_mass(4);
  // m0 = rho V = 1840 kg/m^3 x (50.8 mm)^2 x 1.27 mm (the slab's depth) = 6.0304e-3 kg.
  EXPECT_NEAR(m0, 1840.0 * 0.0508 * 0.0508 * 1.27e-3, 1e-9 * m0);
  EXPECT_LT(m4, m0);
  ASSERT_EQ(run_tephra("extract " + (dir / "run").string() + " --var p.localized --material 0 --step 4", &out), 0);
  rows = csv_rows(out);
  ASSERT_GT(rows.size(), 1700u);  // 1700 steel particles: (45^2 - 40^2) cells x 4
  for (size_t r = 1; r < rows.size(); ++r) EXPECT_EQ(std::stod(rows[r].back()), 0.0) << "particle " << rows[r][1];
}
