// elastic_plastic with kinematic hardening (VT ch. 18, eq. 18.47-18.52, with the ch. 11
// laws: Prager eq. 11.2, Armstrong-Frederick eq. 11.3; von Mises on xi = s - beta) against
// the closed forms of the uniaxial-strain path F = diag(lambda, 1, 1), eps = ln lambda (the
// hypoelastic log strain), perfect plasticity sigma_y = s0 (linear flow, K = 0), isothermal,
// no thermal expansion. The closed-form tests run for both metal models that compose kinematic
// hardening, elastic_plastic (ch. 18) and elastic_plastic_hp (ch. 17) (KinematicClosedForm below).
//
// Along this path every deviator is proportional to diag(1, -1/2, -1/2), so with
// e the (signed) axial plastic strain, eps^p = e diag(1, -1/2, -1/2), ||d eps^p|| = sqrt(3/2)|de|:
//   Sigma := sigma_11 - sigma_22 = 3/2 s_11 = 2G eps - 3G e       (s = 2G dev(eps - eps^p))
//   beta = beta_11 diag(1, -1/2, -1/2),  A := 3/2 beta_11 (the backstress in Sigma units)
//   yield: |Sigma - A| = s0.
// Prager (beta_dot = 2/3 H eps_dot^p): beta_11 = 2/3 H e, A = H e. Forward: Sigma = s0 + H e,
//   e = (2G eps - s0)/(3G + H). Reverse yield at Sigma_rev = A_f - s0 = Sigma_f - 2 s0 (Bauschinger),
//   then Sigma = -s0 + H e, e = (2G eps + s0)/(3G + H).
// Armstrong-Frederick (beta_dot = 2/3 H1 eps_dot^p - H2 beta ||eps_dot^p||), monotonic e:
//   d beta_11/de = 2/3 H1 - gamma beta_11, gamma = sqrt(3/2) H2  =>  beta_11 = (2 H1/(3 gamma)) (1 - exp(-gamma e)),
//   A -> A_sat = H1/gamma; Sigma = s0 + A.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kK = 117e9, kG = 43.8e9, kS0 = 70e6;  // copper-tube values of the inventory (ch. 17)
// A metal model with kinematic hardening: where its backStress history column sits.
struct Variant {
  const char* model;
  int beta_column;           // backStress after the model's scalar history columns
  std::size_t history_size;
};
constexpr Variant kElasticPlastic{"elastic_plastic", 6, 7};
constexpr Variant kElasticPlasticHP{"elastic_plastic_hp", 6, 7};  // + strainRate
constexpr int kBeta = kElasticPlastic.beta_column;  // for the elastic_plastic-only tests

MapModelParameters base(const Variant& v = kElasticPlastic) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"isothermal", 1.0}});
  if (std::string(v.model) == "elastic_plastic") p.values["coeff_thermal_expansion"] = 0.0;
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", 0.0}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}};
  return p;
}

ConstitutiveModelP prager(double H, const Variant& v = kElasticPlastic) {
  auto p = base(v);
  p.add_block("kinematic_hardening_model", "prager", {{"beta", 1.0}, {"hardening_modulus", H}});
  return create_constitutive_model(v.model, p);
}

ConstitutiveModelP armstrong_frederick(double H1, double H2, const Variant& v) {
  auto p = base(v);
  p.add_block("kinematic_hardening_model", "armstrong_frederick",
              {{"beta", 1.0}, {"hardening_modulus_1", H1}, {"hardening_modulus_2", H2}});
  return create_constitutive_model(v.model, p);
}

class KinematicClosedForm : public ::testing::TestWithParam<Variant> {};

Eigen::Matrix3d stretch(double eps) {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = std::exp(eps);
  return F;
}

double sigma_diff(const test::PointState& s) { return s.stress(0, 0) - s.stress(1, 1); }

// Linear Prager, load to ε = 0.01 and back to ε = -0.01 (400 + 800 steps): the
// piecewise closed form above at every step, the backstress 2/3 H e, and the
// reverse yield point Σ_rev = Σ_f - 2 s0. Exact up to round-off and the O(h^3)
// midpoint kinematics (the return is exact for linear hardening on a proportional path).
TEST_P(KinematicClosedForm, PragerUniaxialBauschinger) {
  const Variant& v = GetParam();
  const int kBeta = v.beta_column;
  const double H = 2.0e10;
  const auto m = prager(H, v);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->history().size(), v.history_size);
  EXPECT_EQ(m->history()[kBeta].name, "backStress");
  test::PointState s(*m);
  const int n = 400;
  const double eps_max = 0.01, tol = 1e-9 * 1.2e9;
  const double e_f = (2 * kG * eps_max - kS0) / (3 * kG + H);  // axial plastic strain at the turn
  const double sigma_f = kS0 + H * e_f;                          // Σ at the turn
  const double sigma_rev = sigma_f - 2 * kS0;                    // Bauschinger: reverse yield
  const double eps_rev = (sigma_rev + 3 * kG * e_f) / (2 * kG);  // elastic unloading Σ = 2Gε - 3G e_f
  bool saw_reverse_elastic = false, saw_reverse_plastic = false;
  for (int k = 1; k <= 3 * n; ++k) {
    const double eps = k <= n ? eps_max * k / n : eps_max * (2.0 * n - k) / n;
    ASSERT_EQ(test::step_point(*m, 8930.0, s, stretch(eps), 1e-6), -1);
    double e, ep;  // signed axial plastic strain, accumulated equivalent plastic strain
    if (k <= n) {
      e = std::max(0.0, (2 * kG * eps - kS0) / (3 * kG + H));
      ep = e;
    } else if (eps >= eps_rev) {
      e = e_f;
      ep = e_f;
      saw_reverse_elastic = saw_reverse_elastic || k > n;
    } else {
      e = (2 * kG * eps + kS0) / (3 * kG + H);
      ep = e_f + (e_f - e);
      saw_reverse_plastic = true;
      EXPECT_LE(sigma_diff(s), sigma_rev + tol) << "eps " << eps;  // beyond the reverse yield point
    }
    const double Sigma = 2 * kG * eps - 3 * kG * e;
    EXPECT_NEAR(sigma_diff(s), Sigma, tol) << "eps " << eps;
    EXPECT_NEAR(s.stress(0, 0) + 2 * s.stress(1, 1), 3 * kK * eps, 3 * tol) << "eps " << eps;  // pressure K ε
    EXPECT_NEAR(s.history[0][0], ep, 1e-12) << "eps " << eps;
    const auto& b = s.history[kBeta];
    EXPECT_NEAR(b[0], 2.0 / 3.0 * H * e, tol) << "eps " << eps;  // β_11 = 2/3 H e
    EXPECT_NEAR(b[4], -1.0 / 3.0 * H * e, tol) << "eps " << eps;
    EXPECT_NEAR(b[8], -1.0 / 3.0 * H * e, tol) << "eps " << eps;
    EXPECT_NEAR(b[1], 0.0, tol);
  }
  EXPECT_TRUE(saw_reverse_elastic);
  EXPECT_TRUE(saw_reverse_plastic);
  // The reverse yield stress differs from the forward one by 2 s0, not 2 Σ_f (isotropic).
  EXPECT_NEAR(sigma_f - sigma_rev, 2 * kS0, 1e-6);
  EXPECT_LT(std::abs(sigma_rev), sigma_f - 1e8);  // the shift is visible: |Σ_rev| << Σ_f
}

// Armstrong-Frederick under monotonic uniaxial strain: β_11(e) against the exponential
// closed form (backward Euler in the model: first order, so the error halves when the
// steps are halved), Σ = s0 + 3/2 β_11 on the yield surface, and saturation A → H1/γ
// (the backward-Euler fixed point is the exact saturation value).
TEST_P(KinematicClosedForm, ArmstrongFrederickSaturation) {
  const Variant& v = GetParam();
  const int kBeta = v.beta_column;
  const double H1 = 2.0e10, H2 = 1000.0 / std::sqrt(1.5);  // γ = sqrt(3/2) H2 = 1000
  const double gamma = std::sqrt(1.5) * H2, A_sat = H1 / gamma;
  const auto m = armstrong_frederick(H1, H2, v);
  ASSERT_TRUE(m);
  auto max_error_at = [&](int n, double eps_end, double* sat_error) {
    test::PointState s(*m);
    double err = 0.0;
    for (int k = 1; k <= n; ++k) {
      const double eps = eps_end * k / n;
      EXPECT_EQ(test::step_point(*m, 8930.0, s, stretch(eps), 1e-6), -1);
      const double e = s.history[0][0];
      const double beta11 = s.history[kBeta][0];
      err = std::max(err, std::abs(beta11 - 2.0 * H1 / (3.0 * gamma) * (1.0 - std::exp(-gamma * e))));
      EXPECT_NEAR(s.history[kBeta][4], -0.5 * beta11, 1e-9 * A_sat);
      if (e > 0.0) EXPECT_NEAR(sigma_diff(s), kS0 + 1.5 * beta11, 1e-9 * 1.2e9) << "eps " << eps;
    }
    if (sat_error) *sat_error = 1.5 * s.history[kBeta][0] - A_sat;
    return err;
  };
  // Transient: ε up to 0.004 (γ e up to ~2.3).
  const double e1 = max_error_at(200, 0.004, nullptr), e2 = max_error_at(400, 0.004, nullptr);
  EXPECT_LT(e1, 0.02 * A_sat);
  EXPECT_NEAR(e1 / e2, 2.0, 0.2);  // first-order backward Euler
  // Saturation: ε = 0.06, γ e ≈ 40, exp(-40) ~ 4e-18.
  double sat = 1.0;
  max_error_at(2000, 0.06, &sat);
  EXPECT_NEAR(sat, 0.0, 1e-9 * A_sat);
  std::printf("AF: max |beta11 error| %.4e (200 steps) %.4e (400 steps) ratio %.3f; A_sat %.6e, A - A_sat %.3e\n", e1,
              e2, e1 / e2, A_sat, sat);
}

INSTANTIATE_TEST_SUITE_P(MetalModels, KinematicClosedForm, ::testing::Values(kElasticPlastic, kElasticPlasticHP),
                         [](const ::testing::TestParamInfo<Variant>& i) { return std::string(i.param.model); });

// With adiabatic heating and a temperature-dependent flow stress, the backstress return keeps
// its closed-form identities at every plastic step (VT 18.52-18.55 at convergence):
//   sqrt(3/2)|xi| = sigma_y(eps_p, eps_p_dot, T_{n+1})  (JC, T_{n+1} = T_n + heating dt),
//   beta_{n+1} = beta_n + 2/3 H Delta eps^p with Delta eps^p = sqrt(3/2) Delta eps_p xi/|xi| (Prager).
TEST(ElasticPlasticKinematic, PragerWithAdiabaticJohnsonCookStaysOnTheSurface) {
  // JC's T_r = 298 K and T_m = 1793 K are Vaango's defaults (the block leaves them out).
  const double H = 5e9, A = 90e6, B = 292e6, C = 0.025, n = 0.31, m = 1.09, Tr = 298, Tm = 1793;
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"coeff_thermal_expansion", 0.0},
                        {"tolerance", 1e-12}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "johnson_cook", {{"A", A}, {"B", B}, {"C", C}, {"n", n}, {"m", m}});
  p.add_block("kinematic_hardening_model", "prager", {{"beta", 1.0}, {"hardening_modulus", H}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}};
  const auto model = create_constitutive_model("elastic_plastic", p);
  auto jc = [&](double ep, double rate, double T) {
    return (A + B * std::pow(ep, n)) * (1 + C * std::log(std::max(rate, 1.0))) * (1 - std::pow((T - Tr) / (Tm - Tr), m));
  };
  test::PointState s(*model);
  s.temperature = 696.0;
  const double rate = 4000.0, dt = 0.3 / rate / 300;
  double worst_f = 0, worst_beta = 0, ep_prev = 0;
  Eigen::Matrix3d beta_prev = Eigen::Matrix3d::Zero();
  int plastic = 0;
  for (int k = 1; k <= 300; ++k) {
    // Tension to 0.15 then shear on top: the flow direction turns, so beta and s are not parallel.
    const double t = k * dt;
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    const double l = std::exp(rate * std::min(t, 0.15 / rate));
    F(0, 0) = l;
    F(1, 1) = F(2, 2) = 1 / std::sqrt(l);
    F(0, 1) = F(1, 0) = 0.5 * rate * std::max(0.0, t - 0.15 / rate);  // symmetric: R = I
    const double T_n = s.temperature;
    ASSERT_EQ(test::step_point(*model, 8930.0, s, F, dt), -1) << k;
    const double T1 = T_n + s.heating * dt;
    s.temperature = T1;
    const double ep = s.history[0][0], dg = ep - ep_prev;
    Eigen::Matrix3d beta;
    for (int i = 0; i < 9; ++i) beta(i / 3, i % 3) = s.history[kBeta][i];
    if (dg > 0) {
      ++plastic;
      const Eigen::Matrix3d dev = s.stress - s.stress.trace() / 3 * Eigen::Matrix3d::Identity();
      const Eigen::Matrix3d xi = dev - beta;
      const double q = std::sqrt(1.5 * xi.squaredNorm());
      worst_f = std::max(worst_f, std::abs(q / jc(ep, dg / dt, T1) - 1.0));
      const Eigen::Matrix3d dep = std::sqrt(1.5) * dg * xi / xi.norm();
      worst_beta = std::max(worst_beta, (beta - beta_prev - 2.0 / 3.0 * H * dep).norm() / (H * dg));
    }
    ep_prev = ep;
    beta_prev = beta;
  }
  std::printf("Prager + adiabatic JC: %d plastic steps, max |q_xi/sigma_y - 1| %.2e, max backstress-law error %.2e "
              "(of H Delta eps_p), T %.2f K, eps_p %.4f\n", plastic, worst_f, worst_beta, s.temperature, ep_prev);
  EXPECT_GT(plastic, 250);
  EXPECT_LT(worst_f, 1e-9);
  EXPECT_LT(worst_beta, 1e-6);
  EXPECT_GT(s.temperature, 696.0 + 10.0);  // adiabatic heating happened
}

}  // namespace
}  // namespace tephra
