// Contracts every registered solid constitutive model satisfies (DESIGN.md §4):
//   zero stress and energy at F = I from the stress-free state (prestressed
//     models: the isotropic reference stress sigma_0, kept; limits below on sigma - sigma_0);
//   objectivity: a superposed rigid rotation Q(t) along the whole path gives
//     sigma' = Q sigma Q^T (and the same energy);
//   symmetric stress;
//   c^2 > 0 and c^2 = (K + 4G/3)/rho0 at F = I (the small-strain P-wave speed);
//   the small-strain limit sigma -> K tr(e) I + 2G dev(e) with the model's
//     declared moduli;
//   hyperelastic models: sigma = (1/J) dW/dF F^T (VT eq. 4.3) by central differences;
//   MPMICE pressure hooks, where provided: dp/drho by central differences,
//     rho(p(rho)) = rho and dp/drho(rho0) = K/rho0.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::drive_path;
using test::make_sample_model;
using test::PointState;
using test::step_point;
using M3 = Eigen::Matrix3d;

const double kRho0 = 7800.0;

M3 rotation(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

M3 random_F(std::mt19937& rng, double amp) {
  std::uniform_real_distribution<double> u(-amp, amp);
  M3 F = M3::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F(i, j) += u(rng);
  return F;
}

TEST(SolidContractTable, EveryRegisteredModelHasSampleParameters) {
  for (const std::string& t : constitutive_model_types()) {
    EXPECT_TRUE(test::sample_solid_parameters().count(t)) << t << " has no sample parameters";
    EXPECT_TRUE(make_sample_model(t)) << t;
    EXPECT_EQ(make_sample_model(t)->type(), t);
  }
  EXPECT_GE(constitutive_model_types().size(), 4u);
}

class SolidContract : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { model = make_sample_model(GetParam()); }
  ConstitutiveModelP model;
  double scale() const { return model->rigid() ? 1.0 : model->bulk_modulus() + model->shear_modulus(); }
};

// The stress of the reference state: 0, or the isotropic sigma_0 of a prestressed model.
M3 reference_stress(const ConstitutiveModel& m, const std::string& type) {
  if (!test::sample_is_prestressed(type)) return M3::Zero();
  PointState s(m);
  EXPECT_EQ(step_point(m, kRho0, s, M3::Identity(), 0.0), -1);
  return s.stress;
}

TEST_P(SolidContract, ZeroStressAtIdentity) {
  PointState s(*model);
  ASSERT_EQ(step_point(*model, kRho0, s, M3::Identity(), 0.0), -1);
  const M3 s0 = reference_stress(*model, GetParam());
  EXPECT_LE((s0 - s0.trace() / 3 * M3::Identity()).norm(), 1e-14 * scale());  // isotropic
  EXPECT_LE((s.stress - s0).norm(), 1e-14 * scale());
  EXPECT_LE(std::abs(s.energy_density), 1e-14 * scale());
  EXPECT_EQ(s.plastic_work, 0.0);
  // A step of zero deformation keeps the stress-free (reference) state.
  ASSERT_EQ(step_point(*model, kRho0, s, M3::Identity(), 1e-3), -1);
  EXPECT_LE((s.stress - s0).norm(), 1e-14 * scale());
}

TEST_P(SolidContract, WaveSpeedIsTheSmallStrainPWaveSpeed) {
  PointState s(*model);
  ASSERT_EQ(step_point(*model, kRho0, s, M3::Identity(), 0.0), -1);
  if (model->rigid()) {
    EXPECT_EQ(s.wave_speed, 0.0);  // no stress ever, no limit on dt
    return;
  }
  const double K = model->bulk_modulus(), G = model->shear_modulus();
  EXPECT_NEAR(s.wave_speed * s.wave_speed, (K + 4 * G / 3) / kRho0, 1e-12 * (K + 4 * G / 3) / kRho0);
  // c^2 > 0 and finite at finite strains (compression, tension, shear).
  std::mt19937 rng(5);
  for (int t = 0; t < 10; ++t) {
    const M3 F = random_F(rng, 0.2);
    const PointState r = drive_path(*model, kRho0, [&](double a) { return M3(M3::Identity() + a * (F - M3::Identity())); }, 4);
    EXPECT_GT(r.wave_speed, 0.0);
    EXPECT_TRUE(std::isfinite(r.wave_speed));
  }
}

TEST_P(SolidContract, ObjectivityUnderSuperposedRotation) {
  // Path F(a) = I + a (F1 - I); rotated path Q(a) F(a) with Q(a) a rotation
  // by a*theta about a fixed axis (a rotating observer). The rotation is exact
  // for path-independent models and for incremental models whose increments
  // depend on the stretch only.
  std::mt19937 rng(17);
  std::normal_distribution<double> n(0, 1);
  for (int t = 0; t < 8; ++t) {
    const M3 F1 = random_F(rng, 0.25);
    if (F1.determinant() < 0.5) continue;
    const Eigen::Vector3d axis(n(rng), n(rng), n(rng));
    const double theta = 2.5;
    auto path = [&](double a) { return M3(M3::Identity() + a * (F1 - M3::Identity())); };
    auto rotated = [&](double a) { return M3(rotation(axis, a * theta) * path(a)); };
    const PointState s = drive_path(*model, kRho0, path, 20);
    const PointState r = drive_path(*model, kRho0, rotated, 20);
    const M3 Q = rotation(axis, theta);
    EXPECT_LE((r.stress - Q * s.stress * Q.transpose()).norm(), 1e-11 * (scale() + s.stress.norm()));
    EXPECT_NEAR(r.energy_density, s.energy_density, 1e-11 * (scale() + std::abs(s.energy_density)));
    EXPECT_LE((r.stress - r.stress.transpose()).norm(), 1e-12 * (scale() + r.stress.norm()));
    EXPECT_NEAR(r.wave_speed, s.wave_speed, 1e-12 * (1 + s.wave_speed));
  }
}

TEST_P(SolidContract, SmallStrainLimitIsLinearElasticity) {
  if (model->rigid()) GTEST_SKIP() << "rigid: sigma = 0 for all F (VT eq. 3.1)";
  // F = I + eps H in one step: sigma = K tr(e) I + 2G dev(e) + O(eps^2), e = sym(eps H);
  // the relative error must fall like eps.
  std::mt19937 rng(3);
  M3 H = random_F(rng, 0.5) - M3::Identity();
  if (test::sample_is_tensionless(GetParam())) H -= (H.trace() / 3 + 1) * M3::Identity();  // tr H = -3: J < 1
  const double K = model->bulk_modulus(), G = model->shear_modulus();
  double err[2];
  const double eps[2] = {1e-4, 1e-5};
  for (int k = 0; k < 2; ++k) {
    const M3 e = 0.5 * eps[k] * (H + H.transpose());
    const M3 lin = K * e.trace() * M3::Identity() + 2 * G * (e - e.trace() / 3 * M3::Identity());
    PointState s(*model);
    ASSERT_EQ(step_point(*model, kRho0, s, M3::Identity(), 0.0), -1);
    ASSERT_EQ(step_point(*model, kRho0, s, M3(M3::Identity() + eps[k] * H), 1e-3), -1);
    err[k] = (s.stress - reference_stress(*model, GetParam()) - lin).norm() / lin.norm();
  }
  EXPECT_LT(err[0], 10 * eps[0]);
  EXPECT_NEAR(err[0] / err[1], 10.0, 1.5);  // first order in eps
}

TEST_P(SolidContract, HyperelasticStressIsDerivativeOfEnergy) {
  if (!model->hyperelastic()) GTEST_SKIP() << "not hyperelastic";
  // P = dW/dF by central differences (error O(h^2 W''') ~ 1e-10 relative),
  // sigma = P F^T / J (VT eq. 4.3).
  std::mt19937 rng(23);
  auto W = [&](const M3& F) {
    PointState s(*model);
    EXPECT_EQ(step_point(*model, kRho0, s, F, 0.0), -1);
    return s;
  };
  for (int t = 0; t < 10; ++t) {
    const M3 F = random_F(rng, 0.25);
    if (F.determinant() < 0.5) continue;
    M3 P;
    const double h = 1e-6;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        M3 Fp = F, Fm = F;
        Fp(i, j) += h;
        Fm(i, j) -= h;
        P(i, j) = (W(Fp).energy_density - W(Fm).energy_density) / (2 * h);
      }
    const M3 sigma = W(F).stress;
    EXPECT_LE((sigma - P * F.transpose() / F.determinant()).norm(), 1e-7 * (scale() + sigma.norm()));
  }
}

TEST_P(SolidContract, PressureHooksWhereProvided) {
  const auto e0 = model->pressure_at_density(kRho0, kRho0, 300.0);
  if (!e0) GTEST_SKIP() << "no pressure hooks (MPMICE reports MissingFeature)";
  if (!test::sample_has_thermal_hooks(GetParam())) {
    EXPECT_NEAR(e0->pressure, 0.0, 1e-12 * model->bulk_modulus());
    EXPECT_NEAR(e0->dp_drho, model->bulk_modulus() / kRho0, 1e-12 * model->bulk_modulus() / kRho0);
  }
  if (model->rigid()) {
    // Rigid (Vaango RigidMaterial): p = p_ref and rho = rho0 whatever the
    // load; dp/drho = K/rho0 is the stiffness of the incompressible limit.
    EXPECT_EQ(model->pressure_at_density(1.1 * kRho0, kRho0, 300.0)->pressure, 0.0);
    EXPECT_EQ(*model->density_at_pressure(1e6, kRho0, 300.0), kRho0);
    return;
  }
  for (double x : {0.9, 1.0, 1.1}) {
    const double rho = x * kRho0;
    const auto e = *model->pressure_at_density(rho, kRho0, 300.0);
    EXPECT_GT(e.c2, 0.0);
    const double h = 1e-4 * rho;
    const double fd = (model->pressure_at_density(rho + h, kRho0, 300.0)->pressure -
                       model->pressure_at_density(rho - h, kRho0, 300.0)->pressure) / (2 * h);
    EXPECT_NEAR(e.dp_drho, fd, 1e-6 * e.dp_drho);
    EXPECT_NEAR(*model->density_at_pressure(e.pressure, kRho0, 300.0), rho, 1e-12 * rho);
  }
}

TEST_P(SolidContract, SpanUpdateReportsInvertedPoint) {
  if (model->rigid()) GTEST_SKIP() << "rigid: F is held at I by the driver";
  PointState s(*model);
  M3 F = M3::Identity();
  F(2, 2) = -0.5;  // det F < 0
  EXPECT_EQ(step_point(*model, kRho0, s, F, 1e-3), 0);
}

INSTANTIATE_TEST_SUITE_P(Registered, SolidContract, ::testing::ValuesIn(constitutive_model_types()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tephra
