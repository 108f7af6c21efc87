// The continuum elasto-plastic tangents against finite differences of the returns.
//
// J2 (VT 18.29-18.39 for von Mises, StabilityCheck.h): C^ep = K 1⊗1 + 2μ (I_dev - 3μ/(3μ + H) n̂⊗n̂),
// n̂ = ξ/|ξ| (ξ = s - β), H = dσ_y/dε_p + H_kin with the kinematic modulus
// H_kin = H_1 - 3/2 H_2 β:n̂ (KinematicHardeningModel::j2_modulus; Prager H_2 = 0).
// J2-I1 (VT §18.6.2, ContinuumTangent.h): C^ep = C^e - (C^e:N)⊗(N:C^e)/(N:C^e:N + H_p) for
// Gurson and Rousselier (N = ∂f/∂σ, H_p from the equivalent plastic work, φ fixed).
//
// The check: from a plastic state σ_0 (reached along a mixed tension-shear path), a step with a
// small strain increment h E (E a unit symmetric direction with E : N > 0, i.e. plastic loading)
// gives Δσ; the continuum tangent is the h -> 0 limit of the backward-Euler return's response,
//   |Δσ - C^ep : Δε| / |C^ep : Δε| = O(h)      (Δε: the model's own unrotated increment),
// because the algorithmic tangent differs from the continuum one by terms of order Δγ (the
// rotation of the flow direction, the change of N). Asserted: the error falls about tenfold
// from h = 1e-6 to 1e-7 (first order) and is below 5e-4 at h = 1e-7 (the elastic tangent,
// the wrong answer, is off by O(1)). Deformation gradients are symmetric, so R = I.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/LU>

#include "models/plasticity/ContinuumTangent.h"
#include "models/plasticity/PorousReturn.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/ElasticPlastic.h"
#include "models/solid/ElasticPlasticHP.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kK = 129e9, kMu = 46e9, kS0 = 100e6, kH = 2e9, kRho = 8930.0;

MapModelParameters parameters() {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kMu}, {"isothermal", 1.0},
                        {"coeff_thermal_expansion", 0.0}, {"tolerance", 1e-13}, {"evolve_porosity", 0.0},
                        {"evolve_damage", 0.0}, {"check_TEPLA_failure_criterion", 0.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", kH}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}, {"density", kRho}};
  return p;
}

// The unrotated strain increment of the models for symmetric F (U = F): sym((U1 - U0) ((U0 + U1)/2)^{-1}).
Eigen::Matrix3d increment(const Eigen::Matrix3d& U0, const Eigen::Matrix3d& U1) {
  const Eigen::Matrix3d G = (U1 - U0) * (0.5 * (U0 + U1)).inverse();
  return 0.5 * (G + G.transpose());
}

// Loads the point plastically along F(t) = I + t A (A symmetric: tension plus shear) in 60 steps.
test::PointState preload(const ConstitutiveModel& m, double strain) {
  test::PointState s(m);
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  A(0, 0) = 1.0;
  A(1, 1) = -0.3;
  A(2, 2) = -0.2;
  A(0, 1) = A(1, 0) = 0.6;
  A(1, 2) = A(2, 1) = -0.25;
  for (int k = 1; k <= 60; ++k)
    EXPECT_EQ(test::step_point(m, kRho, s, Eigen::Matrix3d::Identity() + strain * k / 60.0 * A, 1e-6), -1);
  return s;
}

struct FdResult {
  double err_coarse = 0, err_fine = 0;
};

// Worst relative error over random plastic-loading directions at h = 1e-6 and 1e-7.
template <class TangentAt>
FdResult finite_difference_check(const ConstitutiveModel& m, const test::PointState& s0, const Eigen::Matrix3d& N,
                                 TangentAt&& tangent) {
  const Tangent4 C = tangent();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  FdResult r;
  int used = 0;
  const double ep0 = s0.history[0][0];
  while (used < 6) {
    Eigen::Matrix3d E;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) E(i, j) = u(rng);
    E = (0.5 * (E + E.transpose())).eval();
    E /= E.norm();
    if (E.cwiseProduct(N).sum() < 0.3 * N.norm()) continue;  // plastic loading only
    ++used;
    for (const double h : {1e-6, 1e-7}) {
      test::PointState s = s0;
      const Eigen::Matrix3d F1 = s0.F + h * E;
      EXPECT_EQ(test::step_point(m, kRho, s, F1, 1e-6), -1);
      EXPECT_GT(s.history[0][0], ep0);  // the step is plastic
      const Eigen::Matrix3d ds = s.stress - s0.stress;
      const Eigen::Matrix3d pred = C.contract(increment(s0.F, F1));
      const double err = (ds - pred).norm() / pred.norm();
      (h > 5e-7 ? r.err_coarse : r.err_fine) = std::max(h > 5e-7 ? r.err_coarse : r.err_fine, err);
    }
  }
  return r;
}

void expect_first_order(const FdResult& r, const std::string& what) {
  std::printf("%-44s |dsigma - C:deps|/|C:deps|: h = 1e-6: %.3e, h = 1e-7: %.3e (ratio %.2f)\n", what.c_str(),
              r.err_coarse, r.err_fine, r.err_coarse / r.err_fine);
  EXPECT_LT(r.err_fine, 5e-4) << what;  // the elastic tangent (the wrong answer) is off by O(1)
  EXPECT_GT(r.err_coarse / r.err_fine, 7.0) << what;  // O(h)
  EXPECT_LT(r.err_coarse / r.err_fine, 13.0) << what;
}

Eigen::Matrix3d deviator(const Eigen::Matrix3d& a) { return a - a.trace() / 3.0 * Eigen::Matrix3d::Identity(); }

Eigen::Matrix3d backstress_of(const test::PointState& s, int column) {
  Eigen::Matrix3d b = Eigen::Matrix3d::Zero();
  if (column < 0) return b;
  for (int i = 0; i < 9; ++i) b(i / 3, i % 3) = s.history[column][i];
  return b;
}

int column(const ConstitutiveModel& m, const std::string& name) {
  const auto h = m.history();
  for (std::size_t k = 0; k < h.size(); ++k)
    if (h[k].name == name) return static_cast<int>(k);
  return -1;
}

// J2 with linear isotropic hardening, Prager and Armstrong-Frederick backstress, both models.
TEST(ContinuumTangent, J2TangentIsTheLimitOfTheReturnInBothModels) {
  struct Case {
    std::string kin;
    double H1, H2;
  };
  for (const std::string type : {"elastic_plastic", "elastic_plastic_hp"}) {
    for (const Case& c : {Case{"none", 0, 0}, Case{"prager", 1e10, 0}, Case{"armstrong_frederick", 1e10, 50.0}}) {
      auto p = parameters();
      if (c.kin == "prager") p.add_block("kinematic_hardening_model", "prager", {{"hardening_modulus", c.H1}});
      if (c.kin == "armstrong_frederick")
        p.add_block("kinematic_hardening_model", "armstrong_frederick",
                    {{"hardening_modulus_1", c.H1}, {"hardening_modulus_2", c.H2}});
      const auto m = create_constitutive_model(type, p);
      ASSERT_TRUE(m);
      const test::PointState s0 = preload(*m, 0.004);
      const Eigen::Matrix3d beta = backstress_of(s0, column(*m, "backStress"));
      const Eigen::Matrix3d xi = deviator(s0.stress) - beta;
      ASSERT_NEAR(std::sqrt(1.5) * xi.norm() / (kS0 + kH * s0.history[0][0]), 1.0, 1e-10);  // on the surface
      if (c.kin == "armstrong_frederick") ASSERT_GT(std::abs(beta.cwiseProduct(xi).sum()), 0.0);
      double Hk = 0;
      if (c.kin == "prager") Hk = c.H1;
      if (c.kin == "armstrong_frederick") Hk = c.H1 - 1.5 * c.H2 * beta.cwiseProduct(xi / xi.norm()).sum();
      const FdResult r = finite_difference_check(*m, s0, xi, [&] {
        return j2_elastoplastic_tangent(kK, kMu, kH + Hk, xi / xi.norm());
      });
      expect_first_order(r, type + " J2 + " + c.kin);
    }
  }
}

// The J2-I1 tangent with the von Mises yield is the J2 tangent (an identity of the formulas).
TEST(ContinuumTangent, J2I1TangentOfVonMisesIsTheJ2Tangent) {
  MapModelParameters none;
  const auto vm = create_yield_condition("von_mises", none);
  Eigen::Matrix3d s;
  s << 3e7, 2e7, -1e7, 2e7, -5e7, 4e7, -1e7, 4e7, 1e7;
  const double sy = std::sqrt(1.5) * deviator(s).norm();  // on the surface
  const Tangent4 a = yield_continuum_tangent(*vm, s, sy, kH, 0.0, kK, kMu);
  const Tangent4 b = j2_elastoplastic_tangent(kK, kMu, kH, deviator(s) / deviator(s).norm());
  double worst = 0;
  for (int i = 0; i < 81; ++i) worst = std::max(worst, std::abs(a.c[i] - b.c[i]));
  EXPECT_LT(worst, 1e-6 * kK);  // ∂f/∂σ_y by central difference: ~1e-12 relative here (f linear in σ_y)
}

// Gurson and Rousselier (VT 8.9-8.23) through the two-invariant return (PorousReturn.h) of
// elastic_plastic_hp and elastic_plastic, porosity 0.05 held (evolve_porosity false).
TEST(ContinuumTangent, J2I1TangentIsTheLimitOfThePorousReturn) {
  for (const std::string type : {"elastic_plastic_hp", "elastic_plastic"}) {
    for (const std::string yield : {"gurson", "rousselier"}) {
      auto p = parameters();
      if (yield == "gurson")
        p.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
      else
        p.add_block("yield_condition", "rousselier", {{"D", 2.0}, {"sigma_1", 300e6}});
      p.values["initial_mean_porosity"] = 0.05;
      const auto m = create_constitutive_model(type, p);
      ASSERT_TRUE(m);
      const test::PointState s0 = preload(*m, 0.004);
      const double phi = s0.history[column(*m, "porosity")][0];
      ASSERT_NEAR(phi, 0.05, 1e-15);
      const std::shared_ptr<const YieldCondition>& y =
          type == "elastic_plastic" ? static_cast<const ElasticPlastic&>(*m).yield_
                                    : static_cast<const ElasticPlasticHP&>(*m).yield_;
      ASSERT_TRUE(y);
      const double sy = kS0 + kH * s0.history[0][0];
      const Eigen::Matrix3d N = y->gradient(s0.stress, sy, phi);
      ASSERT_LT(std::abs(y->value(s0.stress, sy, phi)) / N.norm(), 1e-8 * sy);  // on the surface (stress distance)
      const FdResult r =
          finite_difference_check(*m, s0, N, [&] { return yield_continuum_tangent(*y, s0.stress, sy, kH, phi, kK, kMu); });
      expect_first_order(r, type + " " + yield);
    }
  }
}

}  // namespace
}  // namespace tephra
