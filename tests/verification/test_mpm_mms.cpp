// Spatial convergence of explicit MPM on the AxisAligned manufactured
// solution (shared/decks/inputs/MPM/AA.ups; Vaango's study
// orderAccuracy/MPM/gimp_dx.tst runs the same deck at 8, 16, 32 cells per
// side). Exact solution u_i = A sin(pi X_i) sin(c pi t + phi_i) (mpm/mms/);
// error = sqrt(mean over particles |u_p - u(X_p, t)|^2), X_p = x_p - u_p
// (Uintah puda -AA_MMS_2, the norm compare_MPM_AA_MMS.m reads).
//
// Settings (docs/mpm-convergence.md): end time 0.005 s (a quarter period
// instead of the deck's full period 0.02 s) and 1 particle per cell direction
// (the deck has 2), to keep the 32^3 runs within seconds; the deck's step
// rule 0.2 x stable dt. The first step starts from v(-dt/2) (leapfrog), so the
// time error is O(dt^2) and below the spatial error: at 16^3 the error is
// 1.1511e-3, 1.1514e-3, 1.1519e-3, 1.1523e-3 for multipliers 0.2, 0.1, 0.05,
// 0.025. Observed order = log2(e_16 / e_32) (the finest pair), required
// >= 1.8 (second-order interpolators).
//
// One thread per run: ctest runs two tests at once on the 2-core machine.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/grid/Loop.h"
#include "tests/support/MmsRun.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra::test {
namespace {

// AA 8^3, gimp, 2 ppc, t = 0.005 s, Vaango's initial size (GimpTwoPpcSymmetryFold).
constexpr double kGimpTwoPpcVaangoSize8 = 1.9032127740e-3;

struct Study {
  double e[3] = {0, 0, 0};  // 8, 16, 32 cells per side
  double order(int k) const { return std::log2(e[k] / e[k + 1]); }
};

Study run_study(const std::string& interpolator) {
  ThreadCountScope one(1);
  Study s;
  const int cells[3] = {8, 16, 32};
  for (int k = 0; k < 3; ++k) {
    MmsRunOptions o;
    o.interpolator = interpolator;
    o.cells = cells[k];
    o.end_time = 0.005;
    o.particles_per_cell_dir = 1;
    const MmsRunResult r = run_axis_aligned(o);
    s.e[k] = r.error;
    std::printf("AA %-10s %2d^3: L2 error %.4e (%d steps, %.2f s)\n", interpolator.c_str(), cells[k], r.error, r.steps,
                r.seconds);
  }
  std::printf("AA %-10s orders: %.2f (8->16), %.2f (16->32)\n", interpolator.c_str(), s.order(0), s.order(1));
  return s;
}

TEST(MpmMmsConvergence, CpdiSecondOrder) {
  const Study s = run_study("cpdi");
  EXPECT_GE(s.order(1), 1.8);
  EXPECT_GE(s.order(0), 1.6);  // pre-asymptotic pair: observed 1.77
}

// gimp and 3rdorderBS stall at 16 -> 32. Two causes were measured
// (docs/mpm-convergence.md, "Why gimp and 3rdorderBS stall"):
// 1. The symmetry faces (fixed): the supports of these interpolators cross
//    the face, and the node one cell inside it missed the mirrored
//    particles' mass, momentum and force (the wall's reaction, an O(1)
//    relative force error at every h; its waves fill the cube within the run,
//    so it is not a boundary layer). mpm/SymmetryFold.h now folds the
//    extra-cell sums onto their mirror nodes. 1 ppc gimp: 3.323e-3, 1.151e-3,
//    8.102e-4 (orders 1.53, 0.51) -> 2.6383e-3, 7.6560e-4, 6.9419e-4 (1.79,
//    0.14); the deck's 2 ppc: gimp 2.313e-3, 7.533e-4, 3.089e-4 (1.62, 1.29)
//    -> 1.9093e-3, 5.2281e-4, 1.9183e-4 (1.87, 1.45); 3rdorderBS 6.41e-3,
//    2.87e-3 (1.16) -> 2.5349e-3, 7.0259e-4, 2.5208e-4 (1.85, 1.54; the
//    32^3 values with the first version of the fold, see the docs).
// 2. The large deformation with undeformed particle domains (intrinsic to
//    uGIMP and to point-quadrature B-splines): |F_ii - 1| reaches A pi = 0.16
//    at every h, the domains of length l0 stop tiling the body and the
//    quadrature error of the internal force does not fall with h at fixed
//    particles per cell. Evidence: the same runs with A = 0.005 instead of
//    0.05 (a temporary hook, not in the tree) converge, gimp 1 ppc 2.0952e-4,
//    5.3582e-5, 1.4112e-5 (orders 1.97, 1.92), and cpGIMP, the same GIMP
//    convolution with l = l0 F_dd, converges at 1.99, 2.02 at A = 0.05.
// So second order at A = 0.05 is not reachable with Vaango's gimp and
// 3rdorderBS at a fixed number of particles per cell (session 13, docs
// "gimp: error against particles per cell at fixed h": at 16^3 the error
// falls with ppc 1..4 toward e_inf = 4.4e-4, e(ppc) ~ e_inf + C/ppc^2, and
// 8^3 at 2 ppc -> 16^3 at 4 ppc converges at 2.10). The former
// DISABLED_GimpSecondOrder / DISABLED_QuadraticBsplineSecondOrder (order
// >= 1.8 at 16 -> 32, which the method cannot give) are replaced by tests of
// the documented behaviour: the stall itself (if a change lifts the 16 -> 32
// order above 0.6, the cause documented here no longer holds: re-measure,
// update the docs and restore the >= 1.8 test), and the identity that makes
// 3rdorderBS share it (at 1 ppc, l = h/2: the linear hat convolved with a
// box of width h is the quadratic B-spline, so the two runs agree to
// round-off).
TEST(MpmMmsConvergence, GimpOnePpcStallsAt16To32) {
  const Study s = run_study("gimp");  // observed 2.6407e-3, 7.6566e-4, 6.9382e-4 (session 16 BC fixes, = the boundary-free mirror problem; before 2.6383e-3, 7.6560e-4, 6.9419e-4): orders 1.79, 0.14
  EXPECT_GE(s.order(0), 1.6);
  EXPECT_LT(s.order(1), 0.6);
}

// The symmetry faces are the mirror problem without faces. u_i = A sin(pi X_i)
// is odd about X_i = 0 and 1, so AA on the unit cube with symmetry on all
// faces stands for the body [-1, 1]^3 with periodic faces
// (MmsRunOptions::periodic_mirror: 8 times the particles, no extra cells, no
// BCs). With the symmetry fold (mpm/SymmetryFold.h), the face conditions
// before the extra-node mirrors and the mirrors again after the node-wise
// MUSL/USL choice (mpm/GridBoundaryConditions.cpp, MpmComponent::advance),
// the two runs are the same computation: equal L2 errors up to round-off
// (session 16: before the last fix 2.6371e-3 against 2.6407e-3 at 8^3). So
// nothing in the errors of the symmetric runs comes from a boundary.
TEST(MpmMmsConvergence, SymmetryFacesAreTheBoundaryFreeMirrorProblem) {
  ThreadCountScope one(1);
  for (const char* interp : {"gimp", "3rdorderBS"}) {
    MmsRunOptions o;
    o.cells = 8;
    o.end_time = 0.005;
    o.particles_per_cell_dir = 1;
    o.interpolator = interp;
    const double symmetric = run_axis_aligned(o).error;
    o.periodic_mirror = true;
    const double periodic = run_axis_aligned(o).error;
    std::printf("AA 8^3 %s, 1 ppc, t = 0.005: symmetric faces %.12e, periodic [-1,1]^3 %.12e\n", interp, symmetric,
                periodic);
    EXPECT_NEAR(symmetric, periodic, 1e-10 * periodic);
  }
}

// The stall split by amplitude (docs/mpm-convergence.md "Session 24").
// The discrete end error of each particle is a smooth function of the
// amplitude A: e_p(A) = A e1_p + (terms of order A^2 and up). Runs at A =
// 0.05 (the deck) and As = A/20 on the same particles (ids 0..n-1) give the
// linear (small-strain) part L_p = (A/As) e_p(As) and the large-strain rest
// N_p = e_p(A) - L_p. gimp, 1 ppc, t = 0.005 s, 8/16/32 cells: L 2.0765e-3,
// 5.2609e-4, 1.3431e-4 (orders 1.98, 1.97): the small-strain discretisation
// is second order; N 1.1199e-3, 4.0396e-4, 6.6447e-4 (1.47, -0.72): the
// whole stall is the large-strain part (with fixed particle domains, the
// quadrature of the internal force on the deformed, grid-crossing particle
// lattice). If L stops converging, a small-strain defect appeared; if N
// converges, the cause documented here changed.
TEST(MpmMmsConvergence, GimpStallIsTheLargeStrainPart) {
  ThreadCountScope one(1);
  const int cells[3] = {8, 16, 32};
  double L[3], N[3];
  for (int k = 0; k < 3; ++k) {
    MmsRunOptions o;
    o.interpolator = "gimp";
    o.cells = cells[k];
    o.end_time = 0.005;
    o.particles_per_cell_dir = 1;
    o.keep_particle_errors = true;
    o.amplitude = 0.05;
    const MmsRunResult big = run_axis_aligned(o);
    o.amplitude = 0.0025;
    const MmsRunResult small = run_axis_aligned(o);
    ASSERT_EQ(big.particle_errors.size(), small.particle_errors.size());
    double l2 = 0, n2 = 0;
    for (std::size_t i = 0; i < big.particle_errors.size(); ++i) {
      const Vec3 lin = 20.0 * small.particle_errors[i];
      l2 += lin.squaredNorm();
      n2 += (big.particle_errors[i] - lin).squaredNorm();
    }
    const double n = double(big.particle_errors.size());
    L[k] = std::sqrt(l2 / n), N[k] = std::sqrt(n2 / n);
    std::printf("AA gimp 1 ppc %2d^3: L2 error %.4e, linear part %.4e, large-strain part %.4e\n", cells[k], big.error,
                L[k], N[k]);
  }
  EXPECT_GE(std::log2(L[0] / L[1]), 1.9);
  EXPECT_GE(std::log2(L[1] / L[2]), 1.9);
  EXPECT_LT(std::log2(N[1] / N[2]), 0.6);
}

TEST(MpmMmsConvergence, QuadraticBsplineEqualsGimpAtOnePpc) {
  ThreadCountScope one(1);
  for (int cells : {8, 16}) {
    MmsRunOptions o;
    o.cells = cells;
    o.end_time = 0.005;
    o.particles_per_cell_dir = 1;
    o.interpolator = "gimp";
    const double eg = run_axis_aligned(o).error;
    o.interpolator = "3rdorderBS";
    const double eb = run_axis_aligned(o).error;
    std::printf("AA %2d^3, 1 ppc: gimp %.10e, 3rdorderBS %.10e\n", cells, eg, eb);
    EXPECT_NEAR(eb, eg, 1e-9 * eg);
  }
}

// cpGIMP (`<interpolator>cpgimp`, Tephra's name, InterpolatorKind::CpGimp)
// converges: 2.5406e-3, 6.3968e-4, 1.5720e-4 (orders 1.99, 2.02).
TEST(MpmMmsConvergence, CpGimpSecondOrder) {
  const Study s = run_study("cpgimp");
  EXPECT_GE(s.order(1), 1.8);
  EXPECT_GE(s.order(0), 1.8);
}

// The symmetry fold at the deck's 2 particles per cell direction (res
// [2,2,2]), 8^3 -> 16^3: gimp 1.9093e-3 -> 5.2281e-4 (order 1.87) and
// 3rdorderBS 2.5349e-3 -> 7.0259e-4 (1.85); without the fold 1.62 and 1.16
// (3rdorderBS was then less accurate with 2 particles per cell than with 1).
// The 16 -> 32 pair stalls at A = 0.05 (1.45, 1.57 with the committed fold:
// 32^3 1.9170e-4, 2.3727e-4; cause 2 above) and takes minutes, so only the
// first pair is checked.
// cpti and 4thorderBS at 8^3 and 16^3 (the 32^3 runs take 15-16 s each, so
// they stay in docs/mpm-convergence.md: cpti 3.7170e-3 before the symmetry
// fold, 4thorderBS 1.1666e-3). Measured with these settings: cpti 1.1439e-2,
// 6.8348e-3 (order 0.74; before the fold 1.0452e-2, 6.1525e-3, 0.77);
// 4thorderBS 5.6623e-3, 2.4705e-3 (order 1.20; 16 -> 32: 1.08; it uses no
// extra-cell node, so the fold does not change it). Neither is second order here: Vaango's cpti domain is
// ONE tetrahedron spanned by the particle's edge vectors, 1/6 of the volume
// of the cube a regular seeding gives each particle, so the domains do not
// tile the body (the quadrature error that stalls uGIMP); the cubic
// B-spline has no particle domain at all (particles are one-point
// quadrature of its C2 basis) and Vaango's boundary-modified splines are
// not linearly complete within 3 cells of a face (the error is spread over
// the cube, rms 2.9e-3 within one cell of a face, 2.0e-3 beyond three cells
// at 16^3, but in this wave problem a face error travels through the cube
// within the run, so that does not clear the faces). With 2 particles per cell direction (8 -> 16): cpti 5.7177e-3 ->
// 2.8390e-3 (1.01), 4thorderBS 4.6561e-3 -> 1.9429e-3 (1.26), cpdi
// 2.0487e-3 -> 5.1755e-4 (1.98). The bounds bracket the observed order, so
// that a change either way is seen.
// Observed order 8^3 -> 16^3 (t = 0.005 s) with `ppc` particles per cell direction.
double order_8_16(const std::string& interpolator, int ppc = 1, double* e8 = nullptr) {
  ThreadCountScope one(1);
  double e[2];
  for (int k = 0; k < 2; ++k) {
    MmsRunOptions o;
    o.interpolator = interpolator;
    o.cells = 8 << k;
    o.end_time = 0.005;
    o.particles_per_cell_dir = ppc;
    e[k] = run_axis_aligned(o).error;
    std::printf("AA %-10s %2d^3, %d ppc: L2 error %.10e\n", interpolator.c_str(), o.cells, ppc, e[k]);
  }
  if (e8) *e8 = e[0];
  return std::log2(e[0] / e[1]);
}

// The deck as Vaango runs it (res [2,2,2], gimp): Vaango's initAxisAligned sets
// p.size = size F(X,0) and GIMP keeps it (mpm/mms/MmsInitialSize.h), so the
// particle domains are the deformed ones of t = 0 for the whole run. Measured
// (t = 0.005 s, multiplier 0.2, start v(-dt/2); docs/mpm-convergence.md
// "Session 18"): 1.9032e-3, 4.9176e-4, 1.4747e-4 at 8/16/32 cells, orders
// 1.95, 1.74 (with the seeded size instead: 1.9093e-3, 5.2281e-4, 1.9170e-4,
// orders 1.87, 1.45); at Vaango's harness time t = 0.02 s: 6.9788e-3, 1.7614e-3,
// 5.6061e-4, orders 1.99, 1.65 (seeded size 2.00, 1.75). The 32^3 runs (4 and
// 16 min) are not in the test: the 16 -> 32
// order stays below 1.8 at t = 0.005 s (the fixed-domain quadrature error, which
// the deformed start size reduces but does not remove: the domains match the
// body at t = 0 only). The 8^3 error is pinned to tell the two sizes apart
// (they differ by 0.3 %).
TEST(MpmMmsConvergence, GimpTwoPpcSymmetryFold) {
  double e8 = 0.0;
  EXPECT_GE(order_8_16("gimp", 2, &e8), 1.9);
  // One thread, the same arithmetic on any x86-64 (no FMA): 1e-8 relative; the seeded size's 1.9093e-3 is 3.2e-3 away.
  EXPECT_NEAR(e8, kGimpTwoPpcVaangoSize8, 1e-8 * kGimpTwoPpcVaangoSize8);
}

TEST(MpmMmsConvergence, QuadraticBsplineTwoPpcSymmetryFold) { EXPECT_GE(order_8_16("3rdorderBS", 2), 1.8); }

TEST(MpmMmsConvergence, CptiFirstOrderOnCubeSeededParticles) {
  const double p = order_8_16("cpti");
  EXPECT_GE(p, 0.67);
  EXPECT_LE(p, 0.87);
}

TEST(MpmMmsConvergence, CubicBsplineFirstOrder) {
  const double p = order_8_16("4thorderBS");
  EXPECT_GE(p, 1.10);
  EXPECT_LE(p, 1.30);
}

// Linear shape functions, for the record (no bound): the error grows from 8^3
// to 16^3 (cell-crossing noise) and at 32^3 a particle inverts before t =
// 0.005 (NumericalFailure).
TEST(MpmMmsConvergence, LinearForTheRecord) {
  ThreadCountScope one(1);
  double e[2];
  for (int k = 0; k < 2; ++k) {
    MmsRunOptions o;
    o.interpolator = "linear";
    o.cells = 8 << k;
    o.end_time = 0.005;
    o.particles_per_cell_dir = 1;
    e[k] = run_axis_aligned(o).error;
    std::printf("AA linear     %2d^3: L2 error %.4e\n", o.cells, e[k]);
  }
  EXPECT_GT(e[1], e[0]);  // the known failure of linear MPM to converge here
}

}  // namespace
}  // namespace tephra::test
