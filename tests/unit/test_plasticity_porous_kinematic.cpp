// Kinematic hardening with a porous yield (Gurson) in the two-invariant return
// (models/plasticity/PorousReturn.h, VT §18.7.1 eqs. 18.64-18.70: the yield on xi = sigma - beta,
// Delta eps^p = Delta lambda df/dxi, beta by the backward Euler of VT 11.2/11.3).
//
// Oracles:
//  1. the return itself: f(xi) = 0, sigma = sigma_trial - C^e : Delta eps^p, beta =
//     KinematicHardeningModel::backstress_after(beta_n, Delta eps^p), dev xi parallel to
//     dev Delta eps^p, and xi : Delta eps^p = (1 - phi) sigma_y Delta eps_p;
//  2. phi = 0: Gurson is von Mises (f_I1 = 0), so elastic_plastic and elastic_plastic_hp with
//     gurson + prager / armstrong_frederick give the von Mises kinematic model's stress and
//     backstress on a uniaxial-strain cycle (to the Newton tolerance), and the Bauschinger
//     closed form of test_model_elastic_plastic_kinematic: reverse yield at
//     Sigma_rev = Sigma_f - 2 s0, i.e. the yield range is shifted by A_f = 3/2 beta_11 = H e_f;
//  3. hydrostatic tension F = lambda I with Prager (q = 0, phi held): Delta eps^p is isotropic,
//     so beta = (2/3) H eps^p gains a mean part (2/9) H eps_v^p and the mean stress keeps rising
//     past Gurson's hydrostatic yield point I1* = (2 s0/q2) acosh((1 + q3 phi^2)/(2 q1 phi)):
//       sigma_m = I1*/3 + (2H/9) eps_v^p,  sigma_m = K (eps_v - eps_v^p)   (default_hypo)
//       =>  sigma_m = I1*/3 + (2H/9)(K eps_v - I1*/3)/(K + 2H/9),
//     eps_v = sum of tr(de), de the models' midpoint increment of U (= 3 ln lambda + O(dt^2)).
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "models/plasticity/FlowStressModel.h"
#include "models/plasticity/PorousReturn.h"
#include "models/plasticity/YieldCondition.h"
#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;
using M3 = Eigen::Matrix3d;

constexpr double kK = 117e9, kG = 43.8e9, kS0 = 70e6;  // the inventory's copper tube (ch. 17)

MapModelParameters gurson_tags() { return MapModelParameters({{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}}); }

M3 deviator(const M3& a) { return a - a.trace() / 3 * M3::Identity(); }

// ---------------------------------------------------------------- 1. the return
TEST(PorousKinematicReturn, ShiftedReturnSatisfiesItsEquations) {
  const auto flow = create_flow_stress_model("linear", MapModelParameters({{"sigma_0", 3e8}, {"K", 1e9}}));
  const auto gurson = create_yield_condition("gurson", gurson_tags());
  const auto af = create_kinematic_hardening_model(
      "armstrong_frederick", MapModelParameters({{"hardening_modulus_1", 5e9}, {"hardening_modulus_2", 20.0}}));
  const auto prager = create_kinematic_hardening_model("prager", MapModelParameters({{"hardening_modulus", 5e9}}));
  const double K = 160e9, mu = 80e9, phi = 0.03;
  M3 beta_n;
  beta_n << 4e7, 1e7, 0, 1e7, -1e7, 2e7, 0, 2e7, -2e7;  // with a small mean part (a porous history)
  M3 s_dir;
  s_dir << 1.0, 0.3, 0.0, 0.3, -0.2, 0.1, 0.0, 0.1, -0.8;
  for (const KinematicHardeningModel* kin : {prager.get(), af.get()})
    for (const double I1 : {-2e9, 0.0, 1.5e9}) {
      PorousReturnInput in;
      in.n_hat = unit_deviator(s_dir);
      in.q_trial = 7e8;
      in.I1_trial = I1;
      in.K = K, in.mu = mu, in.dt = 1e-6;
      in.state.porosity = phi;
      in.beta_n = beta_n;
      in.H_lin = kin->linear_modulus();
      in.H_rec = kin->recovery_modulus();
      const ShiftedTrial xt = shifted_trial(in);
      ASSERT_GT(yield_at(*gurson, xt.q, xt.I1, xt.n_hat, 3e8, phi), 0.0);
      const PorousReturnResult r = porous_return(*gurson, *flow, in);
      ASSERT_TRUE(r.converged) << kin->type() << " I1 " << I1;
      const double sy = 3e8 + 1e9 * r.delta_eps_p;
      const M3 dp = r.plastic_strain;
      // f(xi) = 0 in stress units (the solver's measure f/|df/dsigma| <= 1e-10 of the scale 2e9).
      EXPECT_LT(std::abs(gurson->value(r.xi, sy, phi)) / gurson->gradient(r.xi, sy, phi).norm(), 1e-9 * 2e9);
      // sigma = sigma_trial - C^e : Delta eps^p.
      const M3 sig_tr = I1 / 3 * M3::Identity() + std::sqrt(2.0 / 3.0) * in.q_trial * in.n_hat;
      const M3 Cdp = K * dp.trace() * M3::Identity() + 2 * mu * deviator(dp);
      EXPECT_LT((r.stress - (sig_tr - Cdp)).norm(), 1e-7 * 7e8) << kin->type();
      // beta: the kinematic model's backward Euler; xi = sigma - beta.
      EXPECT_LT((r.backstress - kin->backstress_after(beta_n, dp)).norm(), 1e-9 * 7e8) << kin->type();
      EXPECT_LT((r.xi - (r.stress - r.backstress)).norm(), 1e-9 * 7e8);
      // dev xi parallel to dev Delta eps^p (associated flow along n-hat).
      const M3 a = deviator(r.xi), b = deviator(dp);
      EXPECT_NEAR(a.cwiseProduct(b).sum() / (a.norm() * b.norm()), 1.0, 1e-12);
      // Gurson's matrix work: xi : Delta eps^p = (1 - phi) sigma_y Delta eps_p.
      EXPECT_NEAR(r.xi.cwiseProduct(dp).sum() / ((1 - phi) * sy * r.delta_eps_p), 1.0, 1e-6);
      EXPECT_GT(r.delta_eps_p, 0.0);
    }
}

// ---------------------------------------------------------------- 2. phi = 0 = von Mises
struct Variant {
  const char* model;
};

MapModelParameters metal(const std::string& model, const std::string& yield, const std::string& kin, double H1,
                         double H2) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"isothermal", 1.0},
                        {"initial_mean_porosity", 0.0}, {"evolve_porosity", 0.0}, {"evolve_damage", 0.0},
                        {"check_max_stress_failure", 0.0}, {"check_TEPLA_failure_criterion", 0.0}});
  if (model == "elastic_plastic") p.values["coeff_thermal_expansion"] = 0.0;
  if (yield == "gurson") {
    p.blocks["yield_condition"] = std::make_shared<MapModelParameters>(gurson_tags());
    p.blocks["yield_condition"]->type = "gurson";
  } else {
    p.add_block("yield_condition", "von_mises");
  }
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", 0.0}});
  if (kin == "prager") p.add_block("kinematic_hardening_model", "prager", {{"hardening_modulus", H1}});
  else p.add_block("kinematic_hardening_model", "armstrong_frederick",
                   {{"hardening_modulus_1", H1}, {"hardening_modulus_2", H2}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}, {"density", 8930.0}};
  return p;
}

int column(const ConstitutiveModel& m, const std::string& name) {
  for (int k = 0; k < int(m.history().size()); ++k)
    if (m.history()[k].name == name) return k;
  return -1;
}

M3 stretch(double eps) {
  M3 F = M3::Identity();
  F(0, 0) = std::exp(eps);
  return F;
}

class PorousKinematicZeroPorosity : public ::testing::TestWithParam<const char*> {};

TEST_P(PorousKinematicZeroPorosity, GursonIsTheVonMisesKinematicModelOnACycle) {
  const std::string model = GetParam();
  for (const char* kin : {"prager", "armstrong_frederick"}) {
    const double H1 = 2.0e10, H2 = kin == std::string("prager") ? 0.0 : 100.0;
    const auto g = create_constitutive_model(model, metal(model, "gurson", kin, H1, H2));
    const auto v = create_constitutive_model(model, metal(model, "von_mises", kin, H1, H2));
    ASSERT_TRUE(g && v);
    const int bg = column(*g, "backStress"), bv = column(*v, "backStress");
    ASSERT_GE(bg, 0);
    ASSERT_GE(bv, 0);
    test::PointState sg(*g), sv(*v);
    const int n = 400;
    const double eps_max = 0.01;
    double max_ds = 0, max_db = 0;
    for (int k = 1; k <= 3 * n; ++k) {
      const double eps = k <= n ? eps_max * k / n : eps_max * (2.0 * n - k) / n;
      ASSERT_EQ(test::step_point(*g, 8930.0, sg, stretch(eps), 1e-6), -1) << kin << " step " << k;
      ASSERT_EQ(test::step_point(*v, 8930.0, sv, stretch(eps), 1e-6), -1) << kin << " step " << k;
      max_ds = std::max(max_ds, (sg.stress - sv.stress).norm());
      for (int c = 0; c < 9; ++c) max_db = std::max(max_db, std::abs(sg.history[bg][c] - sv.history[bv][c]));
    }
    std::printf("%s %s, gurson phi = 0 vs von_mises: max |dsigma| = %.3e Pa, max |dbeta| = %.3e Pa\n",
                model.c_str(), kin, max_ds, max_db);
    // The porous return stops at residuals <= 1e-11 of max(q_tr, |I1_tr|) ~ 3e9 per step.
    EXPECT_LT(max_ds, 1e-8 * kS0 * 100);
    EXPECT_LT(max_db, 1e-8 * kS0 * 100);
    EXPECT_NEAR(sg.history[0][0], sv.history[0][0], 1e-9);  // equivalent plastic strain
  }
}

TEST_P(PorousKinematicZeroPorosity, PragerBauschingerShiftIsTwiceTheYieldStress) {
  // Linear Prager along eps: 0 -> 0.01 -> -0.01 (closed form of test_model_elastic_plastic_kinematic):
  // forward Sigma = s0 + H e, e = (2G eps - s0)/(3G + H); reverse yield at Sigma_f - 2 s0,
  // then Sigma = -s0 + H e, e = (2G eps + s0)/(3G + H); beta_11 = 2/3 H e.
  const std::string model = GetParam();
  const double H = 2.0e10;
  const auto m = create_constitutive_model(model, metal(model, "gurson", "prager", H, 0.0));
  const int kb = column(*m, "backStress");
  test::PointState s(*m);
  const int n = 400;
  const double eps_max = 0.01, tol = 1e-8 * kS0 * 10;
  const double e_f = (2 * kG * eps_max - kS0) / (3 * kG + H), sigma_f = kS0 + H * e_f;
  const double sigma_rev = sigma_f - 2 * kS0, eps_rev = (sigma_rev + 3 * kG * e_f) / (2 * kG);
  for (int k = 1; k <= 3 * n; ++k) {
    const double eps = k <= n ? eps_max * k / n : eps_max * (2.0 * n - k) / n;
    ASSERT_EQ(test::step_point(*m, 8930.0, s, stretch(eps), 1e-6), -1);
    double e;
    if (k <= n) e = std::max(0.0, (2 * kG * eps - kS0) / (3 * kG + H));
    else if (eps >= eps_rev) e = e_f;
    else e = (2 * kG * eps + kS0) / (3 * kG + H);
    EXPECT_NEAR(s.stress(0, 0) - s.stress(1, 1), 2 * kG * eps - 3 * kG * e, tol) << "eps " << eps;
    EXPECT_NEAR(s.stress.trace(), 3 * kK * eps, 3 * tol) << "eps " << eps;
    EXPECT_NEAR(s.history[kb][0], 2.0 / 3.0 * H * e, tol) << "eps " << eps;
  }
  std::printf("%s gurson(phi = 0) + prager: Sigma_f = %.6e, reverse yield Sigma_rev = Sigma_f - 2 s0 = %.6e Pa\n",
              model.c_str(), sigma_f, sigma_rev);
}

// ---------------------------------------------------------------- 3. hydrostatic closed form
TEST_P(PorousKinematicZeroPorosity, GursonPragerHydrostaticHardeningClosedForm) {
  const std::string model = GetParam();
  const double phi = 0.04, H = 5e10;
  auto p = metal(model, "gurson", "prager", H, 0.0);
  p.values["initial_mean_porosity"] = phi;
  const auto m = create_constitutive_model(model, p);
  const int kb = column(*m, "backStress");
  test::PointState s(*m);
  const double I1s = 2 * kS0 / 1.0 * std::acosh((1 + 2.25 * phi * phi) / (2 * 1.5 * phi));
  int plastic_steps = 0;
  for (int k = 1; k <= 60; ++k) {
    const double l = std::exp(0.0005 * k);  // eps_v = 3 ln l; yields near eps_v = I1*/(3K) ~ 1.5e-3
    ASSERT_EQ(test::step_point(*m, 8930.0, s, l * M3::Identity(), 1e-6), -1);
    // The models' volumetric increment: the midpoint rule on U = l I gives 3 x 2 tanh(0.0005/2)
    // per step (not 3 x 0.0005: a relative 2e-8 per step, above this test's tolerance).
    const double ev = 6.0 * k * std::tanh(0.00025);
    if (kK * ev <= I1s / 3) {
      EXPECT_NEAR(s.stress.trace() / 3, kK * ev, 1e-9 * kK * ev);
      continue;
    }
    ++plastic_steps;
    const double evp = (kK * ev - I1s / 3) / (kK + 2 * H / 9);
    const double sm = I1s / 3 + 2 * H / 9 * evp;
    EXPECT_NEAR(s.stress.trace() / 3, sm, 1e-9 * sm) << "eps_v " << ev;
    EXPECT_NEAR(s.history[kb][0], 2 * H / 9 * evp, 1e-9 * sm) << "eps_v " << ev;  // beta = (2/9) H eps_v^p I
    EXPECT_LT((s.stress - s.stress.trace() / 3 * M3::Identity()).norm(), 1e-8 * sm);
  }
  EXPECT_GT(plastic_steps, 30);
  std::printf("%s gurson + prager hydrostatic: I1*/3 = %.6e Pa, final sigma_m = %.6e Pa (perfectly plastic: I1*/3)\n",
              model.c_str(), I1s / 3, s.stress.trace() / 3);
}

INSTANTIATE_TEST_SUITE_P(Models, PorousKinematicZeroPorosity, ::testing::Values("elastic_plastic", "elastic_plastic_hp"),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
}  // namespace tephra
