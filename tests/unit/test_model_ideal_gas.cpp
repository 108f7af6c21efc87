// ideal_gas (models/solid/IdealGasMaterial.h): VT §3.2 eqs. 3.3-3.5 and the MPMICE
// hooks of Vaango's IdealGasMP (P = (gamma - 1) rho c_v T).
#include <gtest/gtest.h>

#include <cmath>

#include "models/solid/IdealGasMaterial.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kRho0 = 1.2, kGamma = 1.4, kCv = 716.0, kPref = 101325.0;

ConstitutiveModelP make(std::map<std::string, double> extra = {}) {
  test::MapModelParameters p({{"gamma", kGamma}, {"specific_heat", kCv}, {"reference_pressure", kPref}});
  for (auto& [k, v] : extra) p.values[k] = v;
  return create_constitutive_model("ideal_gas", p);
}

M3 diag(double a, double b, double c) { return Eigen::Vector3d(a, b, c).asDiagonal(); }

TEST(ModelIdealGas, PressureIsTheIsentropeOfEq34) {
  // Inventory oracle: p/p_ref = J^{-gamma} - 1 = 1.63902 at J = 0.5, 0.158939 at J = 0.9 (gamma = 1.4).
  const IdealGasParams p{kGamma, kCv, kPref, 298.0};
  EXPECT_NEAR(ideal_gas_pressure(0.5, p) / kPref, 1.63902, 1e-5);
  EXPECT_NEAR(ideal_gas_pressure(0.9, p) / kPref, 0.158939, 1e-6);
  EXPECT_EQ(ideal_gas_pressure(1.0, p), 0.0);
  EXPECT_EQ(ideal_gas_pressure(1.3, p), 0.0);  // no tension (eq. 3.4: eps_v = 0 for J >= 1)
  // Through the span interface: uniaxial strain F = diag(J, 1, 1): sigma = -p I (eq. 3.3).
  const auto m = make();
  for (double J : {0.5, 0.8, 0.99, 1.2}) {
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, diag(J, 1, 1), 0.0), -1);
    const double pe = J < 1 ? kPref * (std::pow(J, -kGamma) - 1) : 0.0;
    EXPECT_LE((s.stress + pe * M3::Identity()).norm(), 1e-12 * kPref) << J;
    // c^2 = gamma (p + p_ref) / rho, rho = rho0 / J.
    EXPECT_NEAR(s.wave_speed * s.wave_speed, kGamma * (pe + kPref) * J / kRho0, 1e-10 * kGamma * kPref / kRho0);
    // W = p_ref [(J^{1-gamma} - 1)/(gamma - 1) + J - 1] for J < 1.
    const double W = J < 1 ? kPref * ((std::pow(J, 1 - kGamma) - 1) / (kGamma - 1) + J - 1) : 0.0;
    EXPECT_NEAR(s.energy_density, W, 1e-12 * kPref);
  }
}

TEST(ModelIdealGas, HeatingRateIsEq35) {
  // One step J: 1 -> 0.9 in dt: dT/dt = (1/dt)(1 - J_new/J_old) p / (rho c_v), rho = rho0 / J_new.
  const auto m = make();
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double dt = 1e-4, J = 0.9;
  ASSERT_EQ(test::step_point(*m, kRho0, s, diag(J, 1, 1), dt), -1);
  const double p = kPref * (std::pow(J, -kGamma) - 1);
  const double expected = (1 - J) * p / ((kRho0 / J) * kCv) / dt;
  EXPECT_NEAR(s.heating, expected, 1e-12 * expected);
  EXPECT_GT(s.heating, 0.0);  // compression heats
  EXPECT_EQ(s.plastic_work, 0.0);
}

TEST(ModelIdealGas, MpmIceHooksAreTheThermalIdealGas) {
  const auto m = make();
  const double T = 300.0;
  for (double rho : {0.5, 1.2, 3.0}) {
    const SolidEosPoint e = *m->pressure_at_density(rho, kRho0, T);
    const double P = (kGamma - 1) * rho * kCv * T;  // absolute pressure (Vaango IdealGasMP)
    EXPECT_NEAR(e.pressure, P - kPref, 1e-10 * P);  // gauge to the model's reference pressure
    EXPECT_NEAR(e.dp_drho, (kGamma - 1) * kCv * T, 1e-12 * kCv * T);
    EXPECT_NEAR(e.c2, kGamma * P / rho, 1e-12 * kGamma * P / rho);  // dp/drho + dp/de P/rho^2
    const double h = 1e-5 * rho;
    const double fd = (m->pressure_at_density(rho + h, kRho0, T)->pressure -
                       m->pressure_at_density(rho - h, kRho0, T)->pressure) / (2 * h);
    EXPECT_NEAR(e.dp_drho, fd, 1e-8 * e.dp_drho);
    EXPECT_NEAR(*m->density_at_pressure(e.pressure, kRho0, T), rho, 1e-10 * rho);  // round trip
  }
}

TEST(ModelIdealGas, BadParametersAreErrors) {
  test::MapModelParameters missing({{"specific_heat", kCv}});
  EXPECT_THROW(create_constitutive_model("ideal_gas", missing), std::invalid_argument);  // gamma required
  EXPECT_THROW(make({{"gamma", 1.0}}), std::invalid_argument);
  EXPECT_THROW(make({{"specific_heat", -1.0}}), std::invalid_argument);
  EXPECT_THROW(make({{"reference_pressure", 0.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
