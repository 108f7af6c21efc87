// Spatial convergence of explicit MPM on the ExpandingRing manufactured
// solution (mpm/mms/ExpandingRing.cpp, Vaango MMS.cc initExpandingRing):
// a ring 0.4 <= R <= 0.6 breathing radially with traction-free curved faces,
// u = A sin(omega t) g(R) (X, Y, 0), A = 0.1, omega = 100 pi, run on a quarter
// ring in plane strain (inputs/mpm/expanding_ring_mms.ups; 1 cell in z).
// Error: sqrt(sum V0 |u_p - u(X_p, t)|^2 / sum V0) at t = 0.005 s (a quarter
// period: the largest expansion, s = A), cpdi, 2 particles per cell
// direction in x-y, the deck's 0.2 x stable dt; cells across 0.7 m:
// 14, 28, 56 (h = 0.05, 0.025, 0.0125; 4, 8, 16 cells across the ring).
// Observed order = log2(e_h / e_h/2): 1.0323e-2, 4.0398e-3, 1.5783e-3, orders
// 1.35 and 1.36 (4 s in all). Not second order as on AxisAligned (1.95 with
// cpdi): a likely cause, not yet tested, is the curved free surface. The
// seeded particles (sub-cell centres inside the ring) and their square CPDI
// domains follow the faces R = 0.4, 0.6 only to O(h), so the
// traction-free condition acts on a staircase displaced by O(h) from the
// exact face; an O(h) error in a boundary layer of width O(h) gives an L2
// error O(h^1.5). The bound below is the observed order less 0.1.
// (docs/mpm-convergence.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/grid/Loop.h"
#include "tests/support/MmsRun.h"
#include "tests/support/TestPaths.h"

namespace tephra::test {
namespace {

TEST(MpmMmsConvergence, ExpandingRingCpdi) {
  const int saved = thread_count();
  set_thread_count(1);
  const int cells[3] = {14, 28, 56};
  double e[3];
  for (int k = 0; k < 3; ++k) {
    MmsRunOptions o;
    o.deck = source_dir() + "/inputs/mpm/expanding_ring_mms.ups";
    o.planar = true;
    o.interpolator = "cpdi";
    o.cells = cells[k];
    o.end_time = 0.005;
    o.particles_per_cell_dir = 2;
    const MmsRunResult r = run_axis_aligned(o);
    e[k] = r.error;
    std::printf("ring cpdi %2d cells: L2 error %.4e (%ld particles, %d steps, %.2f s)\n", cells[k], r.error,
                r.particles, r.steps, r.seconds);
  }
  set_thread_count(saved);
  const double p0 = std::log2(e[0] / e[1]), p1 = std::log2(e[1] / e[2]);
  std::printf("ring cpdi orders: %.2f, %.2f\n", p0, p1);
  EXPECT_GE(p1, 1.25);
  EXPECT_GE(p0, 1.25);
  EXPECT_LT(e[2], 2e-3);  // 56 cells: observed 1.58e-3
}

}  // namespace
}  // namespace tephra::test
