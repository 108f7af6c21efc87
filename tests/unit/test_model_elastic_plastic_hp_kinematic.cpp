// elastic_plastic_hp with kinematic hardening (VT ch. 11: Prager eq. 11.2,
// Armstrong-Frederick eq. 11.3; von Mises yield on ξ = s - β, VT ch. 8) against
// closed forms of the uniaxial-strain path F = diag(λ, 1, 1), ε = ln λ (the
// hypoelastic log strain), perfect plasticity σ_y = s0 (linear flow, K = 0).
//
// Along this path every deviator is proportional to diag(1, -1/2, -1/2), so with
// e the (signed) axial plastic strain, ε^p = e diag(1, -1/2, -1/2), ||dε^p|| = sqrt(3/2)|de|:
//   Σ := σ_11 - σ_22 = 3/2 s_11 = 2G ε - 3G e           (s = 2G dev(ε - ε^p))
//   β = β_11 diag(1, -1/2, -1/2),  A := 3/2 β_11 (the backstress in Σ units)
//   yield: |Σ - A| = s0.
// Prager (β̇ = 2/3 H ε̇^p): β_11 = 2/3 H e, A = H e. Forward: Σ = s0 + H e,
//   e = (2Gε - s0)/(3G + H). Reverse yield at Σ_rev = A_f - s0 = Σ_f - 2 s0 (Bauschinger),
//   then Σ = -s0 + H e, e = (2Gε + s0)/(3G + H).
// Armstrong-Frederick (β̇ = 2/3 H1 ε̇^p - H2 β ||ε̇^p||), monotonic e:
//   dβ_11/de = 2/3 H1 - γ β_11, γ = sqrt(3/2) H2  =>  β_11 = (2 H1/(3γ)) (1 - exp(-γ e)),
//   A → A_sat = H1/γ (= C/γ with C = H1); Σ = s0 + A.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kK = 117e9, kG = 43.8e9, kS0 = 70e6;  // copper-tube values of the inventory (ch. 17)
constexpr int kBeta = 5;                                // history column of backStress (after the 5 scalars)

MapModelParameters base() {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"isothermal", 1.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", 0.0}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}};
  return p;
}

ConstitutiveModelP prager(double H) {
  auto p = base();
  p.add_block("kinematic_hardening_model", "prager", {{"beta", 1.0}, {"hardening_modulus", H}});
  return create_constitutive_model("elastic_plastic_hp", p);
}

ConstitutiveModelP armstrong_frederick(double H1, double H2) {
  auto p = base();
  p.add_block("kinematic_hardening_model", "armstrong_frederick",
              {{"beta", 1.0}, {"hardening_modulus_1", H1}, {"hardening_modulus_2", H2}});
  return create_constitutive_model("elastic_plastic_hp", p);
}

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
TEST(ElasticPlasticHPKinematic, PragerUniaxialBauschingerClosedForm) {
  const double H = 2.0e10;
  const auto m = prager(H);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->history().size(), 6u);
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
TEST(ElasticPlasticHPKinematic, ArmstrongFrederickSaturationClosedForm) {
  const double H1 = 2.0e10, H2 = 1000.0 / std::sqrt(1.5);  // γ = sqrt(3/2) H2 = 1000
  const double gamma = std::sqrt(1.5) * H2, A_sat = H1 / gamma;
  const auto m = armstrong_frederick(H1, H2);
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

TEST(ElasticPlasticHPKinematic, MissingFeatureCombinations) {
  auto is_missing = [](const MapModelParameters& p) {
    try {  // MapModelParameters: fail() throws invalid_argument, missing_feature() logic_error
      create_constitutive_model("elastic_plastic_hp", p);
    } catch (const std::invalid_argument&) {
      return false;
    } catch (const std::logic_error&) {
      return true;
    }
    return false;
  };
  auto ok = base();
  ok.add_block("kinematic_hardening_model", "prager", {{"hardening_modulus", 1e9}});
  EXPECT_FALSE(is_missing(ok));
  auto st = ok;
  st.add_block("stability_check", "acoustic");
  EXPECT_FALSE(is_missing(st));  // the stability tangent on xi = s - beta with the kinematic modulus
  auto g = ok;
  g.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
  EXPECT_TRUE(is_missing(g));  // porous return has no backstress
  auto none = base();
  none.add_block("kinematic_hardening_model", "none");
  EXPECT_EQ(create_constitutive_model("elastic_plastic_hp", none)->history().size(), 5u);
}

}  // namespace
}  // namespace tephra
