// Spatial convergence of explicit MPM on the ExpandingRing manufactured
// solution (mpm/mms/ExpandingRing.cpp, Vaango MMS.cc initExpandingRing):
// a ring 0.4 <= R <= 0.6 breathing radially with traction-free curved faces,
// u = A sin(omega t) g(R) (X, Y, 0), A = 0.1, omega = 100 pi, run on a quarter
// ring in plane strain (inputs/mpm/expanding_ring_mms.ups; 1 cell in z).
// Error: sqrt(sum V0 |u_p - u(X_p, t)|^2 / sum V0) at t = 0.005 s (a quarter
// period: the largest expansion, s = A; the outer face reaches R = 0.7 and
// the inner one 0.504), cpdi, 2 particles per cell direction in x-y, the
// deck's 0.2 x stable dt; cells across the 0.8 m domain: 16, 32, 64
// (h = 0.05, 0.025, 0.0125; 4, 8, 16 cells across the ring).
// Observed: 1.0401e-3, 4.8128e-4, 1.4085e-4, orders 1.11 and 1.77 (6 s).
// Not established as second order: one level finer (128 cells, 16087
// particles, 26 s, not run here) gives 1.0759e-4, order 0.39 (16 -> 32 is
// pre-asymptotic with 4 cells across the ring; 64 -> 128 stalls). Cause not
// found yet; candidates: the curved free faces, which the seeded particles
// and their square CPDI domains follow only to O(h) (a staircase), and the
// large strain (26% hoop stretch at the inner face). docs/mpm-convergence.md.
// The bounds bracket the observed orders less 0.1-0.2.
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
  const int cells[3] = {16, 32, 64};
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
  EXPECT_GE(p1, 1.6);
  EXPECT_GE(p0, 1.0);
  EXPECT_LT(e[2], 1.6e-4);  // 64 cells: observed 1.41e-4
}

}  // namespace
}  // namespace tephra::test
