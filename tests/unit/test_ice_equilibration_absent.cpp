// Equilibration pressure with absent materials: a trace (theta ~ 1e-10, as
// tiny_rho leaves a material where it is absent) and a material with no mass
// at all in a cell (ice/Equilibration.cpp iterates every material in every
// cell, as Uintah; session 16 tried leaving the traces out of the Newton:
// correct, not faster, reverted; docs/algorithms/ice.md "Absent materials").
//
// Oracle (Dalton, every material an ideal gas): theta_m = rho_CC_m (g_m - 1)
// cv_m T_m / p, so sum theta = 1 gives exactly
//     p = sum_m (g_m - 1) rho_CC_m cv_m T_m,
// including the absent material's share. Its share here is 5e-10 of p (theta
// 5e-10 at the answer), 30x the 1.5e-11 the test allows: a Newton that
// ignored the trace (or kept its starting theta, which cell 1 makes 10x
// smaller) fails the pressure check.
// Also: Sum theta = 1 to 1.5 tol, rho_micro = rho(p, T) and c^2 = g p / rho of
// the absent material at the converged p, and a material with rho_CC = 0
// (theta 0: no share) still gets rho(p, T).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ice/Equilibration.h"
#include "models/eos/IdealGas.h"

namespace tephra {
namespace {

struct Gas {
  double g, cv;
  double R() const { return (g - 1.0) * cv; }
};

TEST(IceEquilibration, TracesAndEmptyMaterialsKeepTheirShare) {
  const Gas ga{1.4, 717.5}, gb{1.289, 652.9}, gc{1.25, 2000.0};
  const IdealGas a(ga.g, ga.cv), b(gb.g, gb.cv), c(gc.g, gc.cv);
  // Four cells. Material c is absent in cells 0-2 and present in cell 3.
  //  0: c at theta 5e-10 of the answer, p guess = the answer
  //  1: the same with the guess 10x too high (c's starting theta is 1/10 of
  //     its final one)
  //  2: c with rho_CC = 0 (theta 0, no share), guess 3x too high
  //  3: all three present (the ordinary Newton), guess 2x too low
  const std::vector<double> Ta = {300, 300, 300, 350}, Tb = {400, 400, 400, 380}, Tc = {2500, 2500, 2500, 600};
  std::vector<double> ra = {0.6, 0.6, 0.6, 0.5}, rb = {0.9, 0.9, 0.9, 0.4}, rc(4);
  double exact[4];
  for (int i = 0; i < 4; ++i) exact[i] = ra[i] * ga.R() * Ta[i] + rb[i] * gb.R() * Tb[i];
  // theta_c = rc R_c Tc / p = 5e-10 at the answer p = p_ab / (1 - 5e-10).
  for (int i = 0; i < 2; ++i) {
    exact[i] /= 1.0 - 5e-10;
    rc[i] = 5e-10 * exact[i] / (gc.R() * Tc[i]);
  }
  rc[2] = 0.0;
  rc[3] = 0.3;
  exact[3] += rc[3] * gc.R() * Tc[3];
  const double guess[4] = {exact[0], 10.0 * exact[1], 3.0 * exact[2], 0.5 * exact[3]};
  std::vector<double> p(guess, guess + 4);
  // Starting micro densities (1/sp_vol of the previous step): each gas at the guess.
  std::vector<double> ma(4), mb(4), mc(4), tha(4), thb(4), thc(4), ca(4), cb(4), cc(4);
  for (int i = 0; i < 4; ++i) {
    ma[i] = guess[i] / (ga.R() * Ta[i]);
    mb[i] = guess[i] / (gb.R() * Tb[i]);
    mc[i] = guess[i] / (gc.R() * Tc[i]);
  }
  const double tol = 1e-11;
  EXPECT_NEAR(rc[1] / mc[1], 5e-11, 1e-22) << "cell 1 starts at 1/10 of its final theta";
  std::vector<EquilibrationMaterial> mats = {
      {&a, ra, Ta, ma, tha, ca}, {&b, rb, Tb, mb, thb, cb}, {&c, rc, Tc, mc, thc, cc}};
  const EquilibrationResult r = equilibrate_pressure(mats, p, 100, tol);
  ASSERT_TRUE(r.converged) << "iterations " << r.iterations;
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(p[i], exact[i], 1.5e-11 * exact[i]);
    EXPECT_NEAR(tha[i] + thb[i] + thc[i], 1.0, 1.5 * tol);
    // Every material, absent or not, at rho(p, T) of the converged p.
    EXPECT_NEAR(mc[i], p[i] / (gc.R() * Tc[i]), 1e-14 * mc[i]);
    EXPECT_NEAR(cc[i], gc.g * p[i] / mc[i], 1e-13 * cc[i]);
    EXPECT_NEAR(ma[i], p[i] / (ga.R() * Ta[i]), 1e-14 * ma[i]);
  }
  EXPECT_NEAR(thc[0], 5e-10, 1e-20);
  EXPECT_NEAR(thc[1], 5e-10, 1e-20);
  EXPECT_EQ(thc[2], 0.0);
}

}  // namespace
}  // namespace tephra
