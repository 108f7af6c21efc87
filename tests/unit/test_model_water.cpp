// water (models/solid/Water.h): VT §3.3 eqs. 3.6-3.8, and its MPMICE hooks
// (the same EOS in density form).
#include <gtest/gtest.h>

#include <cmath>

#include "models/solid/Water.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kRho0 = 1000.0, kKappa = 3.0e8, kGamma = 7.15, kMu = 1.0e-3;

ConstitutiveModelP make(double mu = kMu) {
  test::MapModelParameters p({{"bulk_modulus", kKappa}, {"gamma", kGamma}, {"viscosity", mu}});
  return create_constitutive_model("water", p);
}

TEST(ModelWater, UniaxialStrainPressureIsEq38) {
  const auto m = make(0.0);
  for (double J : {0.8, 0.95, 1.0, 1.05}) {
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, Eigen::Vector3d(J, 1, 1).asDiagonal().toDenseMatrix(), 0.0), -1);
    const double p = kKappa * (std::pow(J, -kGamma) - 1);  // eq. 3.8
    EXPECT_LE((s.stress + p * M3::Identity()).norm(), 1e-12 * kKappa * kGamma) << J;
    EXPECT_NEAR(s.wave_speed * s.wave_speed, kGamma * kKappa * std::pow(J, -kGamma) * J / kRho0,
                1e-12 * kGamma * kKappa / kRho0);
    const double W = kKappa * ((std::pow(J, 1 - kGamma) - 1) / (kGamma - 1) + J - 1);  // -int_1^J p
    EXPECT_NEAR(s.energy_density, W, 1e-12 * kKappa);
  }
}

TEST(ModelWater, ShearRateGivesNewtonianStressAndDissipation) {
  // l = gdot e1 (x) e2 (isochoric): d = gdot/2 (e1e2 + e2e1), eta = d, sigma12 = mu gdot (eq. 3.6);
  // dissipated power tau : d = mu gdot^2 per unit volume (J = 1).
  const auto m = make();
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double gdot = 250.0, dt = 1e-5;
  M3 F = M3::Identity();
  F(0, 1) = gdot * dt;
  ASSERT_EQ(test::step_point(*m, kRho0, s, F, dt), -1);
  EXPECT_NEAR(s.stress(0, 1), kMu * gdot, 1e-12 * kMu * gdot);
  EXPECT_NEAR(s.stress(1, 0), kMu * gdot, 1e-12 * kMu * gdot);
  EXPECT_NEAR(s.stress(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(s.plastic_work, kMu * gdot * gdot * dt, 1e-12 * kMu * gdot * gdot * dt);
  EXPECT_FALSE(m->hyperelastic());
  EXPECT_TRUE(make(0.0)->hyperelastic());
}

TEST(ModelWater, MpmIceHooksMatchTheMpmPressure) {
  const auto m = make();
  for (double x : {0.9, 1.0, 1.05, 1.2}) {
    const double rho = x * kRho0;
    const SolidEosPoint e = *m->pressure_at_density(rho, kRho0, 300);
    EXPECT_NEAR(e.pressure, water_pressure(kRho0 / rho, WaterParams{kKappa, kGamma, kMu}), 1e-6);  // J = rho0/rho
    EXPECT_NEAR(e.dp_drho, kGamma * kKappa * std::pow(x, kGamma - 1) / kRho0, 1e-12 * e.dp_drho);
    const double h = 1e-6 * rho;
    const double fd = (m->pressure_at_density(rho + h, kRho0, 300)->pressure -
                       m->pressure_at_density(rho - h, kRho0, 300)->pressure) / (2 * h);
    EXPECT_NEAR(e.dp_drho, fd, 1e-7 * e.dp_drho);
    EXPECT_NEAR(*m->density_at_pressure(e.pressure, kRho0, 300), rho, 1e-10 * rho);
  }
  EXPECT_TRUE(std::isnan(*m->density_at_pressure(-1.5 * kKappa, kRho0, 300)));  // beyond cavitation
}

TEST(ModelWater, BadParametersAreErrors) {
  test::MapModelParameters p({{"bulk_modulus", kKappa}, {"gamma", kGamma}});
  EXPECT_THROW(create_constitutive_model("water", p), std::invalid_argument);  // viscosity required
  p.values["viscosity"] = -1;
  EXPECT_THROW(create_constitutive_model("water", p), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
