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
// pre-asymptotic with 4 cells across the ring; 64 -> 128 stalls). Cause
// (session 21): the staircase of the seeded curved faces dominates (the
// conforming-seeding test below cuts the error 10x), and what is left is the
// fixed-ppc quadrature error (docs/mpm-convergence.md "ExpandingRing,
// conforming seeding").
// The bounds bracket the observed orders less 0.1-0.2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/grid/Loop.h"
#include "tests/support/MmsRun.h"
#include "tests/support/TestPaths.h"

namespace tephra::test {
namespace {

// The quarter ring deck with cpdi, 2 particles per cell direction, to t = 0.005 s on `cells` cells per side.
MmsRunOptions ring_options(int cells) {
  MmsRunOptions o;
  o.deck = source_dir() + "/inputs/mpm/expanding_ring_mms.ups";
  o.planar = true;
  o.interpolator = "cpdi";
  o.cells = cells;
  o.end_time = 0.005;
  o.particles_per_cell_dir = 2;
  return o;
}

TEST(MpmMmsConvergence, ExpandingRingCpdi) {
  const int saved = thread_count();
  set_thread_count(1);
  const int cells[3] = {16, 32, 64};
  double e[3];
  for (int k = 0; k < 3; ++k) {
    const MmsRunOptions o = ring_options(cells[k]);
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


// The conforming-seeding experiment (session 21, issue 3): the same runs
// with the deck's lattice seeding (a staircase along R = 0.4, 0.6) replaced
// by particles seeded in (R, theta), MmsRunOptions::conforming_ring: n_r =
// 0.2 / (h/2) layers, round((pi/2) R_i / (h/2)) sectors per layer, each
// particle the annular sector R_i dR dtheta h_z with a CPDI domain spanned by
// dR e_R and R_i dtheta e_theta, so the curved free faces are particle faces
// at exactly R = 0.4 and 0.6; same 2 ppc spacing and ~ the same count.
// Oracles:
//  * identity: the conforming particles fill the quarter ring exactly,
//    sum V0 = (pi/4)(0.6^2 - 0.4^2) h_z (to round-off);
//  * the staircase error is the face error: measured (16 / 32 / 64 / 128
//    cells) conforming 9.5914e-5, 3.5273e-5, 2.5362e-5, 4.2472e-5 against
//    staircase 1.0397e-3, 4.7941e-4, 1.4294e-4, 1.0644e-4 (ratios 0.092,
//    0.074, 0.18, 0.40), and the face band [0,1) cell no longer stands out
//    (32 cells: 3.19e-5 against 3.25e-5 to 3.84e-5 inside; staircase at 64:
//    4.4 x the interior). Bounds: ratio < 0.15 at 16 and 32 cells; face
//    band below 1.2 x the whole error at 32.
//  * NOT second order: the orders are 1.44, 0.48, -0.74; the error left is
//    a radial error larger where e_R is along a grid axis (theta < 30 or
//    > 60 deg: 2.8e-5 against 1.35e-5 at 45 deg, 64 cells) that does not
//    fall with h at fixed ppc (docs/mpm-convergence.md "ExpandingRing,
//    conforming seeding"). The test asserts only the 16 -> 32 order >= 1.3
//    (observed 1.44). Run time ~1.5 s (16 and 32 cells, both seedings).
TEST(MpmMmsConvergence, ExpandingRingConformingSeedingRemovesTheFaceError) {
  const int saved = thread_count();
  set_thread_count(1);
  const int cells[2] = {16, 32};
  double conforming[2], staircase[2];
  MmsRunResult last;
  for (int k = 0; k < 2; ++k)
    for (bool conform : {false, true}) {
      MmsRunOptions o = ring_options(cells[k]);
      o.ring_inner = 0.4, o.ring_outer = 0.6;
      o.conforming_ring = conform;
      const MmsRunResult r = run_axis_aligned(o);
      (conform ? conforming : staircase)[k] = r.error;
      std::printf("ring cpdi %2d cells %s seeding: L2 error %.4e (%ld particles, face band %.4e, %.2f s)\n", cells[k],
                  conform ? "conforming" : "staircase ", r.error, r.particles, r.band_rms[0], r.seconds);
      if (conform) {
        const double area = 0.25 * std::acos(-1.0) * (0.6 * 0.6 - 0.4 * 0.4), hz = 0.01;  // the deck's z extent
        EXPECT_NEAR(r.volume0, area * hz, 1e-13 * area * hz);
        last = r;
      }
    }
  set_thread_count(saved);
  for (int k = 0; k < 2; ++k) EXPECT_LT(conforming[k], 0.15 * staircase[k]) << cells[k] << " cells";
  EXPECT_LT(last.band_rms[0], 1.2 * last.error);  // 32 cells: the face band is no worse than the rest
  const double order = std::log2(conforming[0] / conforming[1]);
  std::printf("ring cpdi conforming seeding: order 16 -> 32 %.2f\n", order);
  EXPECT_GE(order, 1.3);
}

}  // namespace
}  // namespace tephra::test
