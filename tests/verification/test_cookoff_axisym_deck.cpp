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
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include "tests/support/TestPaths.h"

namespace fs = std::filesystem;
using tephra::test::run_tephra;

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
