// Contract tests of the ICE specific-heat models (models/thermo/IceSpecificHeat.h).
#include <gtest/gtest.h>

#include <cmath>

#include "models/thermo/IceSpecificHeat.h"

namespace tephra {
namespace {

// HMX product coefficients (decks/inputs/ICE/EOSData/HMXProductCv.xml).
const std::vector<double> kHmx = {-8.330700e14, 1.811170e14, -1.426913e13, 5.305770e11,
                                  -9.958630e9,  9.237480e7,  -3.85805e5,   1476.8};

TEST(IceSpecificHeat, PolynomialClosedFormAndClamp) {
  // c_v = sum a_i T^(i-m): a = (2, 3, 5), m = 2 -> c_v(10) = 2/100 + 3/10 + 5 = 5.32.
  auto p = make_polynomial_cv(2, {2, 3, 5}, 1.0, 100.0);
  EXPECT_NEAR(p->cv(10.0), 5.32, 1e-14);
  EXPECT_DOUBLE_EQ(p->cv(0.5), p->cv(1.0));      // clamped at Tmin
  EXPECT_DOUBLE_EQ(p->cv(1e4), p->cv(100.0));    // clamped at Tmax
  EXPECT_FALSE(p->gamma().has_value());
  // HMX products: positive over [Tmin, 6000 K] and tending to a_7 = 1476.8 J/(kg K).
  auto h = make_polynomial_cv(7, kHmx, 250, 1e6);
  for (double T = 250; T <= 6000; T += 50) EXPECT_GT(h->cv(T), 0) << T;
  EXPECT_NEAR(h->cv(1e6), 1476.8, 1.0);
}

TEST(IceSpecificHeat, DebyeLimits) {
  // T >> T_D: Dulong-Petit 3 N k_B (1 - (T_D/T)^2/20 + ...); T << T_D: (12 pi^4/5) N k_B (T/T_D)^3.
  const double kB = 1.3806503e-23;
  auto d = make_debye_cv(4, 300.0);
  const double r = 300.0 / 3.0e4;
  EXPECT_NEAR(d->cv(3.0e4) / (3 * 4 * kB), 1.0 - r * r / 20.0, 1e-9);
  const double t = 3.0 / 300.0;
  EXPECT_NEAR(d->cv(3.0) / (12.0 * std::pow(M_PI, 4) / 5.0 * 4 * kB * t * t * t), 1.0, 1e-9);
  for (double T = 1; T < 3000; T *= 1.5) EXPECT_GT(d->cv(T), 0);
}

TEST(IceSpecificHeat, ComponentPureGasesAndGamma) {
  // Pure N2 at 300 K: c_p/R from the low-range fit, c_v = 1000 R (c_p/R)/1.4/28.0134.
  std::vector<double> X(10, 0.0);
  X[5] = 1.0;
  auto n2 = make_component_cv(X);
  const double T = 300, R = 8.3144621;
  const double cpR = 3.6748 - 1.2082e-3 * T + 2.3240e-6 * T * T - 6.3218e-10 * T * T * T - 2.2577e-13 * T * T * T * T;
  EXPECT_NEAR(n2->cv(T), 1000 * R * cpR / 1.4 / 28.0134, 1e-10);
  EXPECT_NEAR(n2->cv(T), 742.0, 10.0);  // tabulated c_v of N2 at 300 K: 743 J/(kg K)
  EXPECT_DOUBLE_EQ(*n2->gamma(), 1.4);
  // 50/50 CO2/H2O: gamma_mix = 1.3; monatomic H: c_p/R = 5/2, gamma 1.6.
  std::vector<double> Y(10, 0.0);
  Y[0] = Y[1] = 0.5;
  EXPECT_DOUBLE_EQ(*make_component_cv(Y)->gamma(), 1.3);
  std::vector<double> H(10, 0.0);
  H[9] = 1.0;
  EXPECT_NEAR(make_component_cv(H)->cv(2000), 1000 * R * 2.5 / 1.6 / 1.00794, 1e-9);
  for (double TT = 100; TT < 6000; TT += 100) EXPECT_GT(n2->cv(TT), 0);
}

}  // namespace
}  // namespace tephra
