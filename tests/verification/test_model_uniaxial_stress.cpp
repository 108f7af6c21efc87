// Verification: homogeneous uniaxial stress of one material point, driven
// through the model's span interface (the stress update the MPM step calls).
//
// The scene: a bar stretched along z, h(t)/h0 = lambda(t) = 1 + (lambda_end - 1) t,
// free lateral faces. F_{n+1} = diag(a, a, lambda_{n+1}); the lateral stretch a
// is found each step by Newton's method so that sigma_xx = sigma_yy = 0 (a
// mixed stress/strain material-point driver); l = (F_{n+1} F_n^{-1} - I)/dt.
//
// Exact expectations:
//  * hypo_elastic (VT eq. 4.2, Green-Naghdi rate; no rotation here so tau = sigma):
//    sigma_xx = 0 requires d_xx = -nu d_zz, then sigma_zz_dot = E d_zz, so
//      sigma_zz = E ln(h/h0),  ln(a) = -nu ln(h/h0),
//    E = 9KG/(3K + G), nu = (3K - 2G)/(2(3K + G)). The midpoint increment
//    2(l1-l0)/(l1+l0) = ln(l1/l0) + O(dt^3) per step: observed order 2.
//  * comp_mooney_rivlin (VT eq. 4.12), path independent: with F = diag(a, a, l),
//    B = diag(a^2, a^2, l^2), I1 = 2a^2 + l^2, J = a^2 l, I3 = J^2,
//      sigma_xx(a) = (2/J)[(C1 + C2 I1) a^2 - C2 a^4] + 2 J W3 = 0  (a by bisection),
//      sigma_zz    = (2/J)[(C1 + C2 I1) l^2 - C2 l^4] + 2 J W3,
//    W3 = -2 C3/I3^3 + 2 C4 (I3 - 1): the driver must agree at any step count,
//    and the initial slope d sigma_zz / d ln l = E = 2G(1 + nu), G = 2(C1 + C2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "models/solid/CompMooneyRivlin.h"
#include "models/solid/HypoElastic.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;

M3 diag(double a, double b, double c) { return Eigen::Vector3d(a, b, c).asDiagonal(); }

// One uniaxial-stress step: Newton (secant derivative) on the lateral stretch a
// for sigma_xx = 0, every trial from the same state n. Returns the new state.
test::PointState uniaxial_step(const ConstitutiveModel& m, double rho0, const test::PointState& s, double lz,
                               double dt, double stress_scale) {
  auto trial = [&](double a) {
    test::PointState t = s;
    if (test::step_point(m, rho0, t, diag(a, a, lz), dt) != -1) throw std::runtime_error("rejected state");
    return t;
  };
  double a = s.F(0, 0) * std::pow(lz / s.F(2, 2), -0.4);  // guess: nu = 0.4
  test::PointState t = trial(a);
  for (int it = 0; it < 50 && std::abs(t.stress(0, 0)) > 1e-13 * stress_scale; ++it) {
    const double h = 1e-7 * a;
    const double slope = (trial(a + h).stress(0, 0) - t.stress(0, 0)) / h;
    a -= t.stress(0, 0) / slope;
    t = trial(a);
  }
  EXPECT_LE(std::abs(t.stress(0, 0)), 1e-12 * stress_scale);
  return t;
}

test::PointState uniaxial_run(const ConstitutiveModel& m, double rho0, double l_end, int n, double stress_scale) {
  test::PointState s(m);
  if (test::step_point(m, rho0, s, M3::Identity(), 0.0) != -1) throw std::runtime_error("init");
  for (int k = 1; k <= n; ++k) s = uniaxial_step(m, rho0, s, 1 + (l_end - 1) * double(k) / n, 1.0 / n, stress_scale);
  return s;
}

TEST(VerifyUniaxialStress, HypoElasticReachesELogStretchAtSecondOrder) {
  const HypoElasticParams p{3.0e9, 8.0e9};  // G, K
  const HypoElastic m(p);
  const double E = 9 * p.K * p.G / (3 * p.K + p.G), nu = (3 * p.K - 2 * p.G) / (2 * (3 * p.K + p.G));
  for (double l_end : {1.3, 0.75}) {  // tension and compression
    double err[4];
    for (int k = 0; k < 4; ++k) {
      const int n = 8 << k;
      const test::PointState s = uniaxial_run(m, 7800.0, l_end, n, E);
      const double h = s.F(2, 2);
      err[k] = std::abs(s.stress(2, 2) - E * std::log(h)) / (E * std::abs(std::log(h)));
      EXPECT_NEAR(std::log(s.F(0, 0)), -nu * std::log(h), 1e-3 * std::abs(std::log(h)) / (1 << (2 * k)));
      EXPECT_LE(std::abs(s.stress(1, 1)), 1e-12 * E);
      std::printf("hypo_elastic uniaxial stress, h/h0 = %.2f, N = %3d: |sigma_zz - E ln(h/h0)| / |E ln(h/h0)| = %.3e\n",
                  l_end, n, err[k]);
    }
    for (int k = 0; k < 3; ++k) {
      const double order = std::log2(err[k] / err[k + 1]);
      std::printf("  observed order %d->%d steps: %.3f\n", 8 << k, 16 << k, order);
      EXPECT_NEAR(order, 2.0, 0.05);
    }
    EXPECT_LT(err[3], 2e-5);
  }
}

double cmr_sigma(const CompMooneyRivlinParams& p, double a, double l, int comp) {
  const double I1 = 2 * a * a + l * l, J = a * a * l, I3 = J * J;
  const double W3 = -2 * p.C3() / (I3 * I3 * I3) + 2 * p.C4() * (I3 - 1);
  const double b = comp == 0 ? a * a : l * l;
  return 2 / J * ((p.C1 + p.C2 * I1) * b - p.C2 * b * b) + 2 * J * W3;
}

TEST(VerifyUniaxialStress, CompMooneyRivlinMatchesClosedForm) {
  const CompMooneyRivlinParams p{1.0e5, 2.0e4, 0.49};  // Vaango const_test_cmr.ups
  const CompMooneyRivlin m(p);
  for (double l_end : {1.5, 0.7}) {
    // Closed form: bisection for sigma_xx(a) = 0 (sigma_xx increases with a).
    double lo = 0.3, hi = 2.0;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (cmr_sigma(p, mid, l_end, 0) > 0 ? hi : lo) = mid;
    }
    const double a = 0.5 * (lo + hi), szz = cmr_sigma(p, a, l_end, 2);
    for (int n : {4, 16}) {  // path independent: any step count
      const test::PointState s = uniaxial_run(m, 1100.0, l_end, n, p.shear_modulus());
      std::printf("comp_mooney_rivlin uniaxial stress, h/h0 = %.2f, N = %2d: sigma_zz = %.9e (closed form %.9e), a = %.9f (%.9f)\n",
                  l_end, n, s.stress(2, 2), szz, s.F(0, 0), a);
      EXPECT_NEAR(s.stress(2, 2), szz, 1e-9 * std::abs(szz));
      EXPECT_NEAR(s.F(0, 0), a, 1e-9);
    }
  }
  // Small-strain slope: d sigma_zz / d ln l -> E = 2G(1 + nu) as l -> 1 (first order in ln l).
  const double E = 2 * p.shear_modulus() * (1 + p.nu);
  double rel[2];
  const double eps[2] = {1e-3, 1e-4};
  for (int k = 0; k < 2; ++k) {
    const test::PointState s = uniaxial_run(m, 1100.0, 1 + eps[k], 1, p.shear_modulus());
    rel[k] = std::abs(s.stress(2, 2) / std::log(s.F(2, 2)) - E) / E;
  }
  EXPECT_LT(rel[0], 20 * eps[0]);
  EXPECT_NEAR(rel[0] / rel[1], 10.0, 1.0);
}

}  // namespace
}  // namespace tephra
