// mw_visco_elastic (models/solid/MwViscoElastic.h): a standard linear solid
// (elastic spring in parallel with a Maxwell element), backward Euler in the
// unrotated frame. Checks:
//  - no relaxation (eta -> inf, here eta_d = eta_v = 0 springs removed instead):
//    with G_ve = K_ve = 0 or with zero time the model is hypo_elastic with
//    K = K_e + K_ve, G = G_e + G_ve (identity with models/solid/HypoElastic.h);
//  - relaxation at fixed F after a step strain: the Maxwell part decays by
//    beta = eta / (eta + 2 G_ve dt) per step (the scheme exactly), and
//    beta^N -> exp(-t/tau), tau = eta_d / (2 G_ve), at first order in dt;
//  - the dissipation of a step is J |s_ve|^2 / eta_d dt >= 0;
//  - the MPMICE hooks p = K (1 - rho0/rho) and their inverse.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "models/solid/HypoElastic.h"
#include "models/solid/MwViscoElastic.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kRho0 = 1200.0;
const double kGe = 1.0e8, kKe = 3.0e8, kGve = 2.0e8, kKve = 4.0e8;
const double kTau = 1e-3;  // eta_d = 2 G_ve tau, eta_v = 3 K_ve tau: one relaxation time for both

ConstitutiveModelP make(double tau = kTau, double Gve = kGve, double Kve = kKve) {
  test::MapModelParameters p({{"e_shear_modulus", kGe}, {"e_bulk_modulus", kKe}, {"ve_shear_modulus", Gve},
                              {"ve_bulk_modulus", Kve}, {"ve_volumetric_viscosity", 3 * Kve * tau},
                              {"ve_deviatoric_viscosity", 2 * Gve * tau}});
  return create_constitutive_model("mw_visco_elastic", p);
}

M3 shear(double g) {
  M3 F = M3::Identity();
  F(0, 1) = g;
  F(2, 2) = 0.98;
  return F;
}

TEST(ModelMwViscoElastic, WithoutTimeItIsHypoElasticWithTheSummedModuli) {
  const auto m = make();
  HypoElastic h(HypoElasticParams{kGe + kGve, kKe + kKve});
  test::PointState s(*m), r(h);
  for (int k = 1; k <= 10; ++k) {
    const M3 F = shear(0.03 * k);
    ASSERT_EQ(test::step_point(*m, kRho0, s, F, 0.0), -1);  // dt = 0: beta = 1, no relaxation
    ASSERT_EQ(test::step_point(h, kRho0, r, F, 0.0), -1);
  }
  EXPECT_LE((s.stress - r.stress).norm(), 1e-12 * r.stress.norm());
  EXPECT_NEAR(s.wave_speed, r.wave_speed, 1e-12 * r.wave_speed);
}

TEST(ModelMwViscoElastic, StressRelaxesToTheSpringAtTheMaxwellRate) {
  const M3 F = shear(0.02);
  const auto m = make();
  const auto spring = make(kTau, 0.0, 0.0);  // the elastic branch alone: the relaxed limit
  test::PointState s_inf(*spring);
  ASSERT_EQ(test::step_point(*spring, kRho0, s_inf, F, 0.0), -1);
  const double T = 2 * kTau;
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const int n = 40 << k;
    const double dt = T / n;
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, F, 0.0), -1);  // the step strain
    const M3 s0 = s.stress;
    double dissipated = 0;
    for (int j = 0; j < n; ++j) {
      ASSERT_EQ(test::step_point(*m, kRho0, s, F, dt), -1);
      EXPECT_GE(s.plastic_work, 0.0);
      dissipated += s.plastic_work;
    }
    const double beta = 2 * kGve * kTau / (2 * kGve * kTau + 2 * kGve * dt);
    // The scheme exactly: sigma_N - sigma_inf = beta^N (sigma_0 - sigma_inf).
    EXPECT_LE((s.stress - s_inf.stress - std::pow(beta, n) * (s0 - s_inf.stress)).norm(), 1e-10 * s0.norm());
    // Against the continuous solution exp(-T/tau).
    err[k] = (s.stress - s_inf.stress - std::exp(-T / kTau) * (s0 - s_inf.stress)).norm() / (s0 - s_inf.stress).norm();
    EXPECT_GT(dissipated, 0.0);
  }
  std::printf("mw_visco_elastic relaxation over 2 tau: relative errors %.3e %.3e %.3e (40/80/160 steps)\n", err[0],
              err[1], err[2]);
  EXPECT_NEAR(err[0] / err[1], 2.0, 0.1);  // backward Euler: first order
  EXPECT_NEAR(err[1] / err[2], 2.0, 0.1);
}

TEST(ModelMwViscoElastic, DissipationOfAStepIsTheDashpotPower) {
  const auto m = make();
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, shear(0.01), 0.0), -1);
  const double dt = 1e-5;
  ASSERT_EQ(test::step_point(*m, kRho0, s, shear(0.01), dt), -1);
  const std::vector<double>& sd = s.history[1];
  double sd2 = 0;
  for (double v : sd) sd2 += v * v;
  const double pv = s.history[2][0];
  const double J = shear(0.01).determinant();
  const double expected = J * (sd2 / (2 * kGve * kTau) + 3 * pv * pv / (3 * kKve * kTau)) * dt;
  EXPECT_NEAR(s.plastic_work, expected, 1e-12 * expected);
}

TEST(ModelMwViscoElastic, MpmIceHooks) {
  const auto m = make();
  const double K = kKe + kKve;
  for (double x : {0.95, 1.0, 1.1}) {
    const double rho = x * kRho0;
    const SolidEosPoint e = *m->pressure_at_density(rho, kRho0, 300);
    EXPECT_NEAR(e.pressure, K * (1 - 1 / x), 1e-9 * K);
    EXPECT_NEAR(e.dp_drho, K / (kRho0 * x * x), 1e-12 * K / kRho0);
    EXPECT_NEAR(*m->density_at_pressure(e.pressure, kRho0, 300), rho, 1e-10 * rho);
  }
}

TEST(ModelMwViscoElastic, BadParametersAreErrors) {
  test::MapModelParameters p({{"e_shear_modulus", kGe}, {"e_bulk_modulus", kKe}, {"ve_shear_modulus", kGve},
                              {"ve_bulk_modulus", kKve}, {"ve_volumetric_viscosity", 1.0}});
  EXPECT_THROW(create_constitutive_model("mw_visco_elastic", p), std::invalid_argument);
  p.values["ve_deviatoric_viscosity"] = -1.0;
  EXPECT_THROW(create_constitutive_model("mw_visco_elastic", p), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
