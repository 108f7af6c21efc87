// JWLC rho(p) (models/eos/ExplosiveProductEos.cpp: Newton in x = ln(rho/rho0)
// on ln p, started where the C term alone gives p). ANFO constants of
// EOSData/JWLEOSANFO.xml. Checks:
//   p(rho(p)) = p to round-off over p = 1e2 .. 1e12 Pa (an absent product at
//     atmospheric pressure up to 10x the CJ pressure),
//   the same rho as the bracketed Newton on rho (DensitySolve.h, the solver
//     used before) to 1e-13,
//   the low-density limit: for rho << rho0 the exponentials vanish
//     (A e^{-R1 rho0/rho} < e^{-400} at rho = rho0/100), so
//     rho(p) = rho0 (p/C)^{1/(1+om)} in closed form.
#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "models/eos/DensitySolve.h"
#include "models/eos/EquationOfState.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

constexpr double kA = 2.9867e11, kB = 4.11706e9, kC = 7.206147e8, kR1 = 4.95, kR2 = 1.15, kOm = 0.35, kRho0 = 1160.0;

EquationOfStateP anfo() {
  test::MapModelParameters p({{"A", kA}, {"B", kB}, {"C", kC}, {"R1", kR1}, {"R2", kR2}, {"om", kOm}, {"rho0", kRho0}});
  return create_equation_of_state("JWLC", p, {});
}

// p = A e^{-R1 V} + B e^{-R2 V} + C (rho/rho0)^{1+om}, V = rho0/rho (Souers' JWL++).
std::pair<double, double> jwlc(double rho) {
  const double V = kRho0 / rho, P1 = kA * std::exp(-kR1 * V), P2 = kB * std::exp(-kR2 * V);
  const double P3 = kC * std::pow(rho / kRho0, 1.0 + kOm);
  return {P1 + P2 + P3, (kR1 * V * P1 + kR2 * V * P2 + (1.0 + kOm) * P3) / rho};
}

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

TEST(JwlcDensity, InvertsPressureOverTenDecades) {
  const EquationOfStateP eos = anfo();
  for (int k = 0; k <= 200; ++k) {
    const double p = std::pow(10.0, 2.0 + 10.0 * k / 200.0);
    const double rho = eos->density_at(p, 300.0);
    ASSERT_TRUE(std::isfinite(rho)) << "p=" << p;
    EXPECT_LT(rel(jwlc(rho).first, p), 1e-14) << "p=" << p << " rho=" << rho;
    // The bracketed Newton on rho from [0, rho0] (the previous solver).
    const double ref = solve_density_bracketed(
        [&](double r) {
          const auto [pr, dp] = jwlc(r);
          return std::pair{pr - p, dp};
        },
        0.0, kRho0);
    EXPECT_LT(rel(rho, ref), 1e-13) << "p=" << p;
  }
}

TEST(JwlcDensity, LowDensityLimitIsThePowerLaw) {
  const EquationOfStateP eos = anfo();
  for (double ratio : {1e-2, 1e-3, 1e-5}) {
    const double rho = ratio * kRho0;
    const double p = kC * std::pow(ratio, 1.0 + kOm);  // exponentials < e^{-400}: p is the C term alone
    EXPECT_LT(rel(eos->density_at(p, 300.0), kRho0 * std::pow(p / kC, 1.0 / (1.0 + kOm))), 1e-14);
    EXPECT_LT(rel(eos->density_at(p, 300.0), rho), 1e-14);
  }
}

// The JWLC point skips exp(-R V) when R V > 746 (an absent product at 1 atm
// has V = rho0/rho ~ 700, R1 V ~ 3500): in IEEE double exp(-x) rounds to 0
// for every x > 745.14 (the smallest subnormal is 4.94e-324 = e^{-744.44}),
// so the skip returns the same 0 as the library, only without its slow
// underflow path. Checked: the library fact at the threshold, and p, dp/drho
// of the EOS equal (bit for bit) the unguarded closed form jwlc() at
// relative volumes V = 1 .. 2000, where R1 V and R2 V each cross 746.
TEST(JwlcDensity, UnderflowSkipGivesTheClosedFormBitForBit) {
  EXPECT_EQ(std::exp(-746.0), 0.0);
  EXPECT_GT(std::exp(-745.0), 0.0);
  const EquationOfStateP eos = anfo();
  int crossed_r1 = 0, crossed_r2 = 0;
  for (int k = 0; k <= 4000; ++k) {
    const double V = std::pow(2000.0, k / 4000.0), rho = kRho0 / V;
    const EosState s = eos->at(rho, 300.0);
    const auto [p, dp] = jwlc(rho);
    ASSERT_EQ(s.p, p) << "V=" << V;
    ASSERT_EQ(s.dp_drho, dp) << "V=" << V;
    crossed_r1 += kR1 * V > 746.0;
    crossed_r2 += kR2 * V > 746.0;
  }
  EXPECT_GT(crossed_r1, 0);
  EXPECT_GT(crossed_r2, 0);
}

}  // namespace
}  // namespace tephra
