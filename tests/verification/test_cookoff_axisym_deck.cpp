// The axisymmetric fast-cookoff deck inputs/validation/cookoff_axisym.ups
// (issue 6, docs/validation/cookoff.md "Session 24") runs past its old
// failure point: up to session 23 it stopped at step 159 (t = 25 us, exit 4:
// the product gas's trace in PBX cell (32,6) at 2.6 GPa with sp_vol < 0),
// because the axisymmetric projection's side rule moved 7/8 of a particle's
// x weight through a face in the step the particle crossed a node
// (mpmice/AxisymmetricShare.h). 200 steps (t ~ 31 us), exit 0, and the
// pressure inside stays below 1 GPa (the run's largest cell pressure to
// 0.4 ms is 0.21 GPa; the failing run had 2.6 GPa). The long run is
// tests/bench/cookoff2d.py --axisym.
//
// OuterSurfaceLayerStaysElasticTo80us (session 25, docs/validation/cookoff.md
// "Session 25"): to 80 us the steel's outer surface layer (particles within
// 1 mm of r = R_O = 57.15 mm or z = L_O = 57.15 mm) has no plastic strain.
// Before session 25 the MUSL/USL choice read a per-radian node volume against
// h_x h_y h_z, so the light node layer just outside the end cap (r ~ 10-13 mm,
// a tenth of a full node) kept USL's v*_g, which ran away (190 m/s against
// v_g = 8 m/s) from 74 us on: the cap's outer particle reached eps_p = 0.18 at
// 80 us (0.30 by 83 us) while the layers below stayed elastic. Measured with
// the fix: 0 in all 384 outer-layer particles (the largest eps_p in the steel,
// 0.0036, is at the inner corner).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>
#include <filesystem>
#include <sstream>
#include <string>

#include "tests/support/TestPaths.h"

namespace fs = std::filesystem;
using tephra::test::run_tephra;

namespace {

// Column `name` of an extract CSV with the x and y columns: rows of (x, y, value).
std::vector<std::array<double, 3>> extract_rows(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::size_t col = 0, cx = 0, cy = 0;
  {
    std::istringstream h(line);
    std::string field;
    for (std::size_t c = 0; std::getline(h, field, ','); ++c) {
      if (field == name) col = c;
      if (field == "x") cx = c;
      if (field == "y") cy = c;
    }
  }
  std::vector<std::array<double, 3>> rows;
  if (col == 0 || cx == 0 || cy == 0) return rows;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string field;
    std::array<double, 3> r{};
    for (std::size_t c = 0; std::getline(ls, field, ','); ++c) {
      if (c == cx) r[0] = std::stod(field);
      if (c == cy) r[1] = std::stod(field);
      if (c == col) r[2] = std::stod(field);
    }
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST(CookoffAxisymDeck, OuterSurfaceLayerStaysElasticTo80us) {
  const fs::path dir = tephra::test::scratch_dir("cookoff_axisym_outer_layer");
  const std::string deck = tephra::test::source_dir() + "/inputs/validation/cookoff_axisym.ups";
  std::string out;
  ASSERT_EQ(run_tephra(deck + " --output " + (dir / "run").string() + " --end-time 8.0e-5 --threads 1 --quiet", &out), 0)
      << out;
  ASSERT_EQ(run_tephra("extract " + (dir / "run").string() + " --var p.eqPlasticStrain --material 0 --step last", &out),
            0)
      << out;
  const auto rows = extract_rows(out, "p.eqPlasticStrain");
  const double R_O = 0.05715, L_O = 0.05715, band = 1e-3;
  double outer_max = 0, all_max = 0;
  int outer = 0;
  for (const auto& r : rows) {
    all_max = std::max(all_max, r[2]);
    if (r[0] > R_O - band || r[1] > L_O - band) outer_max = std::max(outer_max, r[2]), ++outer;
  }
  std::printf("[cookoff axisym] 80 us: %d outer-layer steel particles, largest eps_p there %.3g; in the steel %.3g\n",
              outer, outer_max, all_max);
  EXPECT_EQ(rows.size(), 1700u);  // the steel particles
  EXPECT_GE(outer, 300);
  EXPECT_LT(outer_max, 1e-4);  // before session 25: 0.18
  EXPECT_LT(all_max, 0.02);    // the inner corner's bending: 0.0036
}

TEST(CookoffAxisymDeck, RunsPastTheOldFailureAtStep159) {
  const fs::path dir = tephra::test::scratch_dir("cookoff_axisym_deck");
  const std::string deck = tephra::test::source_dir() + "/inputs/validation/cookoff_axisym.ups";
  std::string out;
  ASSERT_EQ(run_tephra(deck + " --output " + (dir / "run").string() + " --max-steps 200 --threads 1 --quiet", &out), 0)
      << out;
  // The last output's largest cell pressure.
  ASSERT_EQ(run_tephra("extract " + (dir / "run").string() + " --var press_CC --material 0 --step last", &out), 0)
      << out;
  std::istringstream in(out);
  std::string line;
  std::getline(in, line);  // header
  std::size_t col = 0;
  {
    std::istringstream h(line);
    std::string name;
    for (std::size_t c = 0; std::getline(h, name, ','); ++c)
      if (name == "press_CC") col = c;
  }
  ASSERT_GT(col, 0u) << line;
  double p_max = 0;
  int rows = 0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string field;
    for (std::size_t c = 0; std::getline(ls, field, ','); ++c)
      if (c == col) p_max = std::max(p_max, std::stod(field)), ++rows;
  }
  std::printf("[cookoff axisym] 200 steps: exit 0, largest press_CC at the last output %.4g MPa (%d cells)\n",
              p_max / 1e6, rows);
  EXPECT_GE(rows, 2704);  // 52 x 52 cells
  EXPECT_GT(p_max, 1e7);  // the burn has pressurised the container
  EXPECT_LT(p_max, 1e9);
}
