// Pressure-dependent yield (VT ch. 8) and its two-invariant return
// (models/plasticity/PorousReturn.h) in elastic_plastic_hp: the Gurson and
// Rousselier functions against their closed forms, the yield function zero on
// the returned stress, the reduction to von Mises at zero porosity (the
// uniaxial-strain closed form), and the Gurson hydrostatic yield stress.
#include <cmath>

#include <gtest/gtest.h>

#include "models/plasticity/PorousReturn.h"
#include "models/plasticity/YieldCondition.h"
#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

// Inventory ch. 8 tags: q1 1.5, q2 1.0, q3 2.25, k 4.0, f_c 0.05.
MapModelParameters gurson_tags() { return MapModelParameters({{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}}); }

Eigen::Matrix3d stress(double q, double I1) {  // (I1/3) I + sqrt(2/3) q n, n = diag(2,-1,-1)/sqrt(6)
  Eigen::Matrix3d n = Eigen::Matrix3d::Zero();
  n(0, 0) = 2 / std::sqrt(6.0), n(1, 1) = n(2, 2) = -1 / std::sqrt(6.0);
  return (I1 / 3.0) * Eigen::Matrix3d::Identity() + std::sqrt(2.0 / 3.0) * q * n;
}

// f = (q/σy)² + 2 q1 φ* cosh(q2 I1/(2σy)) - (1 + q3 φ*²) (8.9); φ* (8.10); φ = 0: (q/σy)² - 1.
TEST(PorousYield, GursonAndRousselierAgainstTheirClosedForms) {
  const auto g = create_yield_condition("gurson", gurson_tags());
  const double sy = 3e8;
  for (const double q : {0.0, 1e8, 3e8})
    for (const double I1 : {-6e8, 0.0, 4e8}) {
      EXPECT_NEAR(g->value(stress(q, I1), sy, 0.0), q * q / (sy * sy) - 1.0, 1e-14);
      const double phi = 0.03;
      EXPECT_NEAR(g->value(stress(q, I1), sy, phi),
                  q * q / (sy * sy) + 2 * 1.5 * phi * std::cosh(I1 / (2 * sy)) - (1 + 2.25 * phi * phi), 1e-14);
      const double ps = 0.05 + 4.0 * (0.08 - 0.05);  // φ = 0.08 > f_c
      EXPECT_NEAR(g->value(stress(q, I1), sy, 0.08),
                  q * q / (sy * sy) + 2 * 1.5 * ps * std::cosh(I1 / (2 * sy)) - (1 + 2.25 * ps * ps), 1e-13);
    }
  // Gradient against central differences of f along a perturbation E: ∂f/∂σ : E.
  const Eigen::Matrix3d s0 = stress(2e8, 3e8);
  Eigen::Matrix3d E;
  E << 1, 0.3, -0.2, 0.3, -0.5, 0.1, -0.2, 0.1, 0.7;
  const auto r = create_yield_condition("rousselier", MapModelParameters({{"D", 2.0}, {"sigma_1", 5e8}}));
  for (const YieldCondition* y : {g.get(), r.get()}) {
    const double h = 1e3;
    const double fd = (y->value(s0 + h * E, sy, 0.02) - y->value(s0 - h * E, sy, 0.02)) / (2 * h);
    EXPECT_NEAR(y->gradient(s0, sy, 0.02).cwiseProduct(E).sum() / fd, 1.0, 1e-7) << y->type();
  }
  // Rousselier (8.19): q/(1-φ) + D σ1 φ exp(I1/(3(1-φ)σ1)) - σy; φ = 0: q - σy.
  EXPECT_NEAR(r->value(stress(2e8, 3e8), sy, 0.0), 2e8 - sy, 1e-6);
  EXPECT_NEAR(r->value(stress(2e8, 3e8), sy, 0.02),
              2e8 / 0.98 + 2.0 * 5e8 * 0.02 * std::exp(3e8 / (3 * 0.98 * 5e8)) - sy, 1e-6);
}

// A return from a trial state outside the surface lands on f = 0, with
// q = q_tr - 3μΔλ f_q, I1 = I1_tr - 9KΔλ f_I1 and the work equivalence.
TEST(PorousYield, ReturnedStressIsOnTheYieldSurface) {
  const auto lin = create_flow_stress_model("linear", MapModelParameters({{"sigma_0", 3e8}, {"K", 1e9}}));
  const auto g = create_yield_condition("gurson", gurson_tags());
  const auto r = create_yield_condition("rousselier", MapModelParameters({{"D", 2.0}, {"sigma_1", 5e8}}));
  for (const YieldCondition* y : {g.get(), r.get()})
    for (const double I1 : {-2e9, 0.0, 1.5e9}) {
      PorousReturnInput in;
      in.q_trial = 6e8;
      in.I1_trial = I1;
      in.n_hat = unit_deviator(stress(1.0, 0.0));
      in.K = 160e9, in.mu = 80e9, in.dt = 1e-6;
      in.state.porosity = 0.03;
      const PorousReturnResult res = porous_return(*y, *lin, in);
      ASSERT_TRUE(res.converged) << y->type() << " I1 " << I1;
      const double sy = 3e8 + 1e9 * res.delta_eps_p;
      EXPECT_NEAR(res.sigma_y, sy, 1e-6);
      // f in stress units: f/|∂f/∂σ| (the solver's measure, <= 1e-10 max(q_tr, |I1_tr|)).
      const double fscale = y->gradient(res.stress, sy, 0.03).norm();
      EXPECT_LT(std::abs(y->value(res.stress, sy, 0.03) / fscale), 1e-9 * 2e9) << y->type() << " I1 " << I1;
      EXPECT_GT(res.delta_eps_p, 0.0);
      EXPECT_LT(res.q, 6e8);
      // Plastic work equivalence (1 - φ) σy Δε_p = σ : Δε^p: the solver stops at |R4| <= 1e-10 σy,
      // with Δε_p ~ 1e-3 a relative error <= 1e-7.
      EXPECT_NEAR(res.stress.cwiseProduct(res.plastic_strain).sum() / (0.97 * sy * res.delta_eps_p), 1.0, 1e-6);
      // Elastic predictor-corrector: σ = σ_tr - C:Δε^p (isotropic C = K I⊗I + 2μ I_dev).
      const Eigen::Matrix3d dp = res.plastic_strain;
      const Eigen::Matrix3d sig_tr = stress(6e8, I1);
      const Eigen::Matrix3d Cdp = 160e9 * dp.trace() * Eigen::Matrix3d::Identity() +
                                  2 * 80e9 * (dp - dp.trace() / 3 * Eigen::Matrix3d::Identity());
      EXPECT_LT((res.stress - (sig_tr - Cdp)).norm(), 1e-6 * 6e8) << y->type();
    }
}

// elastic_plastic(_hp) with a porous yield, isothermal, no porosity evolution.
MapModelParameters hp(const std::string& type, const std::string& yield, double phi0, double H) {
  MapModelParameters p({{"bulk_modulus", 117e9}, {"shear_modulus", 43.8e9}, {"isothermal", 1.0},
                        {"initial_mean_porosity", phi0}, {"evolve_porosity", 0.0}, {"evolve_damage", 0.0},
                        {"check_max_stress_failure", 0.0}, {"check_TEPLA_failure_criterion", 0.0}});
  if (type == "elastic_plastic") p.values["coeff_thermal_expansion"] = 0.0;
  if (yield == "gurson") p.blocks["yield_condition"] = std::make_shared<MapModelParameters>(gurson_tags());
  else p.add_block("yield_condition", "rousselier", {{"D", 2.0}, {"sigma_1", 5e8}});
  p.blocks["yield_condition"]->type = yield;
  p.add_block("flow_model", "linear", {{"sigma_0", 70e6}, {"K", H}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}, {"density", 8930.0}};
  return p;
}

// φ = 0: both reduce to von Mises. Uniaxial strain closed form (copper tube, inventory ch. 17):
//   ε_p = max(0, (2Gε - s0)/(3G + H)), y = 2Gε or s0 + H ε_p,
//   σ11 = Kε + 2/3 y, σ22 = Kε - 1/3 y (default_hypo: tr σ/3 = K ε).
TEST(PorousYield, ZeroPorosityReducesToVonMisesUniaxialStrain) {
  const double K = 117e9, G = 43.8e9, s0 = 70e6;
  for (const char* type : {"elastic_plastic", "elastic_plastic_hp"})
  for (const char* yield : {"gurson", "rousselier"})
    for (const double H : {0.0, 1e9}) {
      const auto m = create_constitutive_model(type, hp(type, yield, 0.0, H));
      ASSERT_TRUE(m);
      test::PointState s(*m);
      for (int k = 1; k <= 100; ++k) {
        const double eps = 0.005 * k / 100;
        Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
        F(0, 0) = std::exp(eps);
        ASSERT_EQ(test::step_point(*m, 8930.0, s, F, 1e-6), -1) << type << " " << yield;
        const double ep = std::max(0.0, (2 * G * eps - s0) / (3 * G + H));
        const double y = 2 * G * eps <= s0 ? 2 * G * eps : s0 + H * ep;
        EXPECT_NEAR(s.stress(0, 0), K * eps + 2.0 / 3.0 * y, 1e-8 * 6e8) << yield << " eps " << eps;
        EXPECT_NEAR(s.stress(1, 1), K * eps - 1.0 / 3.0 * y, 1e-8 * 6e8) << yield << " eps " << eps;
        EXPECT_NEAR(s.history[0][0], ep, 1e-9) << yield << " eps " << eps;  // |R4| <= 1e-11 σy per step
      }
    }
}

// Gurson's pressure dependence: under hydrostatic tension F = λ I (q = 0) the mean stress
// saturates at the closed form of f(0, I1) = 0:
//   I1 = (2 σy/q2) acosh((1 + q3 φ*²)/(2 q1 φ*)),   φ = 0.04 <= f_c so φ* = φ.
TEST(PorousYield, GursonHydrostaticYieldStressClosedForm) {
  const double phi = 0.04, sy = 70e6;
  for (const char* type : {"elastic_plastic", "elastic_plastic_hp"}) {
  const auto m = create_constitutive_model(type, hp(type, "gurson", phi, 0.0));
  test::PointState s(*m);
  for (int k = 1; k <= 50; ++k) {
    const double l = std::exp(0.002 * k);  // yields near ε_v = 3 x 0.0013
    ASSERT_EQ(test::step_point(*m, 8930.0, s, l * Eigen::Matrix3d::Identity(), 1e-6), -1);
  }
  const double I1 = 2 * sy / 1.0 * std::acosh((1 + 2.25 * phi * phi) / (2 * 1.5 * phi));
  EXPECT_NEAR(s.stress.trace() / I1, 1.0, 1e-9);
  EXPECT_LT(std::abs(s.stress(0, 1)) + std::abs(s.stress(0, 0) - s.stress(1, 1)), 1e-8 * sy);  // no deviator
  EXPECT_GT(s.history[0][0], 0.0);  // plastic
  // The plastic volume is history (ln J^p > 0 in dilatation).
  int kevp = -1;
  for (int k = 0; k < int(m->history().size()); ++k)
    if (m->history()[k].name == "plasticVolumetricStrain") kevp = k;
  ASSERT_GE(kevp, 0);
  EXPECT_GT(s.history[kevp][0], 0.05);
  }
}

}  // namespace
}  // namespace tephra
