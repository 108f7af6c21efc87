// comp_neo_hook_plastic / UCNH (models/solid/CompNeoHookPlastic.h): the
// multiplicative J2 return of Simo & Hughes (1998) Box 9.1 on the neo-Hookean
// Kirchhoff deviator s = G dev(bbar_e), linear isotropic hardening.
//   - elastic branch: the comp_neo_hook stress K/2 (J - 1/J) I + (G/J) dev(J^{-2/3} F F^T);
//   - yield consistency after a plastic step: |s| = sqrt(2/3) (sigma_y + H alpha);
//   - plastic incompressibility: det bbar_e = 1, i.e. det F_p = (det bbar_e)^{-1/2} = 1;
//   - one-step closed form of the return from the reference state (below), its
//     dissipation Psi(bbar_trial) - Psi(bbar_1);
//   - Vaango's modified EOS (UCNH::computePressEOSCM) and its inverse.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include <Eigen/LU>

#include "core/base/Types.h"
#include "models/solid/CompNeoHookPlastic.h"
#include "models/solid/CompNeoHookean.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

const double kK = 8.0e9, kG = 3.0e9, kSy = 3.0e7, kH = 1.0e8, kRho0 = 8930.0;

ConstitutiveModelP make(std::map<std::string, double> extra = {}, const std::string& type = "comp_neo_hook_plastic") {
  std::map<std::string, double> v = {{"bulk_modulus", kK}, {"shear_modulus", kG}, {"yield_stress", kSy},
                                     {"hardening_modulus", kH}};
  for (const auto& [k, x] : extra) v[k] = x;
  test::MapModelParameters p(v);
  return create_constitutive_model(type, p);
}

Mat3 random_F(std::mt19937& rng, double amp) {
  std::uniform_real_distribution<double> u(-amp, amp);
  Mat3 F = Mat3::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F(i, j) += u(rng);
  return F;
}

Mat3 bbar_of(const test::PointState& s) {
  Mat3 b;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b(i, j) = s.history[0][3 * i + j];
  return b;
}

// The Kirchhoff deviator J dev(sigma).
Mat3 dev_tau(const test::PointState& s) {
  const Mat3 tau = s.F.determinant() * s.stress;
  return tau - tau.trace() / 3.0 * Mat3::Identity();
}

TEST(ModelCompNeoHookPlastic, ElasticBranchIsCompNeoHook) {
  // sigma_y large: every step elastic. The incremental bbar_e = fbar bbar_n fbar^T
  // telescopes to J^{-2/3} F F^T, so the stress is comp_neo_hook's (to round-off).
  const auto m = make({{"yield_stress", 1e12}});
  const CompNeoHookeanParams cnh{kK, kG};
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat3 F = random_F(rng, 0.3);
    const test::PointState s = test::drive_path(*m, kRho0, [&](double t) { return Mat3(Mat3::Identity() + t * (F - Mat3::Identity())); }, 10);
    const SolidPointResult r = comp_neo_hookean_point(F, kRho0, cnh);
    EXPECT_LE((s.stress - r.stress).norm(), 1e-12 * r.stress.norm()) << F;
    EXPECT_NEAR(s.energy_density, r.energy_density, 1e-12 * std::abs(r.energy_density));
    EXPECT_NEAR(s.wave_speed, r.wave_speed, 1e-14 * r.wave_speed);
    EXPECT_EQ(s.history[1][0], 0.0);
    EXPECT_EQ(s.plastic_work, 0.0);
  }
  // UCNH without usePlasticity: bbar = J^{-2/3} F F^T directly, the same stress.
  const auto u = make({}, "UCNH");
  EXPECT_TRUE(u->hyperelastic());
  const Mat3 F = random_F(rng, 0.3);
  test::PointState s(*u);
  ASSERT_EQ(test::step_point(*u, kRho0, s, F, 1e-3), -1);
  EXPECT_LE((s.stress - comp_neo_hookean_point(F, kRho0, cnh).stress).norm(), 1e-12 * s.stress.norm());
}

TEST(ModelCompNeoHookPlastic, YieldConsistencyAndPlasticIncompressibility) {
  const auto m = make();
  std::mt19937 rng(11);
  int plastic_steps = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const Mat3 F1 = random_F(rng, 0.2), F2 = random_F(rng, 0.2);
    if (F1.determinant() <= 0.3 || (F1 * F2).determinant() <= 0.3) continue;
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, Mat3::Identity(), 0.0), -1);
    const int n = 40;
    for (int k = 1; k <= n; ++k) {
      // Out along F1, then on to F1 F2 (a non-proportional path).
      const double t = 2.0 * k / n;
      const Mat3 F = t <= 1 ? Mat3(Mat3::Identity() + t * (F1 - Mat3::Identity()))
                            : Mat3((Mat3::Identity() + (t - 1) * (F2 - Mat3::Identity())) * F1);
      const double alpha_old = s.history[1][0];
      // The elastic trial state at the new F: fbar bbar_n fbar^T, fbar = det(f)^{-1/3} f.
      const Mat3 f = F * s.F.inverse();
      const Mat3 fbar = std::cbrt(1.0 / f.determinant()) * f;
      const Mat3 bbar_trial = fbar * bbar_of(s) * fbar.transpose();
      ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-4), -1);
      const double alpha = s.history[1][0];
      EXPECT_NEAR(bbar_of(s).determinant(), 1.0, 1e-12);  // det F_p = 1
      if (alpha > alpha_old) {
        ++plastic_steps;
        const double yield = std::sqrt(2.0 / 3.0) * (kSy + kH * alpha);
        EXPECT_NEAR(dev_tau(s).norm(), yield, 1e-10 * yield);
        // Dissipation of the step: the energy the return releases at fixed F,
        // G/2 (tr bbar_trial - tr bbar_{n+1}) > 0; it exceeds (sigma_y + H alpha) dalpha
        // (by ~ G dgamma^2, the backward-Euler return's share; the sum converges, see
        // the driver's energy-balance test).
        EXPECT_NEAR(s.plastic_work, 0.5 * kG * (bbar_trial.trace() - bbar_of(s).trace()), 1e-6 * s.plastic_work);
        EXPECT_GT(s.plastic_work, (kSy + kH * alpha) * (alpha - alpha_old) * (1 - 1e-2));
        // s = G dev(bbar_e): the stored elastic state carries the returned stress.
        const Mat3 b = bbar_of(s);
        EXPECT_LE((kG * (b - b.trace() / 3.0 * Mat3::Identity()) - dev_tau(s)).norm(), 1e-10 * yield);
      } else {
        EXPECT_LE(dev_tau(s).norm(), std::sqrt(2.0 / 3.0) * (kSy + kH * alpha) * (1 + 1e-12));
      }
      EXPECT_EQ(s.heating, 0.0);  // Vaango UCNH: pdTdt = 0
    }
  }
  EXPECT_GT(plastic_steps, 100);
}

TEST(ModelCompNeoHookPlastic, OneStepReturnClosedForm) {
  // From the reference state, one step to the isochoric F = diag(l, 1/sqrt(l), 1/sqrt(l)):
  // bbar_trial = diag(l^2, 1/l, 1/l), I_e = (l^2 + 2/l)/3, s_trial = G (l^2 - 1/l) diag(2,-1,-1)/3,
  // |s_trial| = sqrt(2/3) G (l^2 - 1/l); f = |s_trial| - sqrt(2/3) sigma_y,
  // dgamma = f / (2 G I_e + 2H/3), alpha = sqrt(2/3) dgamma (Box 9.1 with mubar = G I_e).
  const auto m = make();
  const double l = 1.05;
  const Mat3 F = Vec3(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal();
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-3), -1);
  const double Ie = (l * l + 2 / l) / 3, nt = std::sqrt(2.0 / 3.0) * kG * (l * l - 1 / l);
  const double dgamma = (nt - std::sqrt(2.0 / 3.0) * kSy) / (2 * kG * Ie + 2 * kH / 3);
  EXPECT_NEAR(s.history[1][0], std::sqrt(2.0 / 3.0) * dgamma, 1e-13);
  const double s11 = (nt - 2 * kG * Ie * dgamma) * std::sqrt(2.0 / 3.0);  // |s| sqrt(2/3) = s11 for diag(2,-1,-1)/3 shape
  EXPECT_NEAR(s.stress(0, 0), s11, 1e-10 * kSy);  // J = 1: sigma = s
  EXPECT_NEAR(s.stress(1, 1), -s11 / 2, 1e-10 * kSy);
  EXPECT_NEAR(s.stress(0, 1), 0.0, 1e-10 * kSy);
  // Dissipation = Psi(bbar_trial) - Psi(bbar_1) = G/2 (tr bbar_trial - tr bbar_1).
  EXPECT_NEAR(s.plastic_work, 0.5 * kG * (l * l + 2 / l - bbar_of(s).trace()), 1e-6);
  EXPECT_GT(s.plastic_work, 0.0);
}

TEST(ModelCompNeoHookPlastic, InitialAlphaRaisesTheYieldStress) {
  // <alpha> is the initial plastic strain: yield at sqrt(2/3)(sigma_y + H alpha_0).
  const double a0 = 0.5;
  const auto m = make({{"alpha", a0}});
  test::PointState s(*m);
  EXPECT_EQ(s.history[1][0], a0);
  const double l = 1.05;
  ASSERT_EQ(test::step_point(*m, kRho0, s, Mat3(Vec3(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal()), 1e-3), -1);
  EXPECT_NEAR(dev_tau(s).norm(), std::sqrt(2.0 / 3.0) * (kSy + kH * s.history[1][0]), 1e-10 * kSy);
  EXPECT_GT(s.history[1][0], a0);
}

TEST(ModelCompNeoHookPlastic, ModifiedEosClosedForms) {
  const double p_ref = 101325.0;
  const double n = kK / p_ref;  // ~8e4: the tension branch falls to vacuum within ~1e-4 of strain
  // Continuous at rho0: p = p_ref and dp/drho = K/rho0 from both sides.
  const SolidEosPoint b = modified_eos_pressure(kRho0, kRho0, kK, p_ref);
  EXPECT_EQ(b.pressure, 0.0);
  EXPECT_NEAR(b.dp_drho, kK / kRho0, 1e-15 * kK / kRho0);
  const double eps = 1e-12;
  const SolidEosPoint a = modified_eos_pressure(kRho0 * (1 - eps), kRho0, kK, p_ref);
  // p_ref ((1-eps)^n - 1) ~ -n p_ref eps; 1 - eps carries a relative round-off of ~1e-4 in eps
  EXPECT_NEAR(a.pressure, -kK * eps, 1e-3 * kK * eps);
  EXPECT_NEAR(a.dp_drho, kK / kRho0, 2 * n * eps * kK / kRho0);
  for (double x : {0.999, 0.99999, 0.999995, 1.0, 1.01, 1.2}) {
    const double rho = x * kRho0, h = 1e-9 * rho;
    const SolidEosPoint e = modified_eos_pressure(rho, kRho0, kK, p_ref);
    EXPECT_GE(e.pressure, -p_ref);  // never below vacuum
    if (x < 1) EXPECT_NEAR(e.pressure, p_ref * std::pow(x, n) - p_ref, 1e-9 * p_ref);
    if (x == 0.999) continue;  // p + p_ref ~ p_ref e^{-79}: the inverse is lost to round-off there
    const double fd = (modified_eos_pressure(rho + h, kRho0, kK, p_ref).pressure -
                       modified_eos_pressure(rho - h, kRho0, kK, p_ref).pressure) / (2 * h);
    if (x != 1.0) EXPECT_NEAR(e.dp_drho, fd, 1e-5 * e.dp_drho) << x;
    EXPECT_NEAR(modified_eos_density(e.pressure, kRho0, kK, p_ref), rho, 1e-9 * rho) << x;
  }
  // The generic hooks have no p_ref: absent with useModifiedEOS, the standard EOS without.
  EXPECT_TRUE(make({{"useModifiedEOS", 1}})->modified_eos());  // hooks: the compression branch (ModifiedEos.h)
  EXPECT_FALSE(make()->modified_eos());
  EXPECT_NEAR(make()->pressure_at_density(1.1 * kRho0, kRho0, 300)->pressure, 0.5 * kK * (1.1 - 1 / 1.1), 1e-6);
}

TEST(ModelCompNeoHookPlastic, DeckChecks) {
  EXPECT_THROW(make({{"useDamage", 1}}), std::logic_error);         // MissingFeature
  EXPECT_THROW(make({{"useInitialStress", 1}}), std::logic_error);  // MissingFeature
  EXPECT_THROW(make({{"yield_stress", -1}}), std::invalid_argument);
  test::MapModelParameters no_yield({{"bulk_modulus", kK}, {"shear_modulus", kG}});
  EXPECT_THROW(create_constitutive_model("comp_neo_hook_plastic", no_yield), std::invalid_argument);
  // UCNH: plasticity only with usePlasticity.
  EXPECT_TRUE(create_constitutive_model("UCNH", no_yield));
  EXPECT_FALSE(make({{"usePlasticity", 1}}, "UCNH")->hyperelastic());
  EXPECT_EQ(make({{"usePlasticity", 1}}, "UCNH")->type(), "UCNH");
  // <equation_of_state>: only Vaango's default (HyperElasticEOS, K from <bulk_modulus>).
  test::MapModelParameters with_eos({{"bulk_modulus", kK}, {"shear_modulus", kG}});
  with_eos.add_block("equation_of_state", "default_hyper", {{"bulk_modulus", 1.0}});
  EXPECT_EQ(create_constitutive_model("UCNH", with_eos)->bulk_modulus(), kK);
  with_eos.add_block("equation_of_state", "mie_gruneisen");
  EXPECT_THROW(create_constitutive_model("UCNH", with_eos), std::logic_error);  // MissingFeature
}

}  // namespace
}  // namespace tephra
