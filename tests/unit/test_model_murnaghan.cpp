// murnaghanMPM (models/solid/MurnaghanMPM.h): VT §3.4 eqs. 3.9-3.11 and the
// MPMICE hooks (the same EOS in density form; header: deviation from Vaango's hooks).
#include <gtest/gtest.h>

#include <cmath>

#include "models/solid/MurnaghanMPM.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kRho0 = 1160.0, kK = 2.56e9, kKp = 7.4, kP0 = 101325.0, kMu = 0.0;

test::MapModelParameters params() {
  return test::MapModelParameters({{"K", kK}, {"Kprime", kKp}, {"pressure", kP0}, {"rho0", kRho0}, {"viscosity", kMu}});
}
ConstitutiveModelP make() { return create_constitutive_model("murnaghanMPM", params()); }

TEST(ModelMurnaghan, UniaxialStrainPressureIsEq311) {
  // ANFO (K = 1/3.9e-10 Pa, n = 7.4): inventory oracle p(v = 0.9) = 4.091295e8 Pa (the JWL++
  // reactant); with K = 2.56 GPa (~1/3.9e-10) the closed form (K/K')(J^{-K'} - 1) is checked directly.
  const auto m = make();
  for (double J : {0.8, 0.9, 0.95, 1.1}) {
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, Eigen::Vector3d(1, J, 1).asDiagonal().toDenseMatrix(), 0.0), -1);
    const double p = kK / kKp * (std::pow(J, -kKp) - 1);
    EXPECT_LE((s.stress + p * M3::Identity()).norm(), 1e-12 * kK) << J;
    // c^2 = dp/drho = (dp/dJ)(dJ/drho) = (K J^{-K'-1}) (J^2/rho0) = K J^{1-K'}/rho0: the tangent
    // bulk modulus K + K' p = K J^{-K'} over the current density rho0/J (and the MPMICE hook's c^2).
    EXPECT_NEAR(s.wave_speed * s.wave_speed, kK * std::pow(J, 1 - kKp) / kRho0, 1e-9 * kK / kRho0);
  }
  const MurnaghanParams anfo{1.0 / 3.9e-10, 7.4, kP0, kRho0, 0.0};
  EXPECT_NEAR(murnaghan_pressure(0.9, anfo), 4.091295e8, 1e-6 * 4.091295e8);
  EXPECT_NEAR(murnaghan_pressure(0.95, anfo), 1.599641e8, 1e-6 * 1.599641e8);
}

TEST(ModelMurnaghan, MpmIceHooksAreEq311InDensityFormAndRoundTrip) {
  const auto m = make();
  const MurnaghanParams mp{kK, kKp, kP0, kRho0, 0};
  for (double x : {0.7, 0.95, 1.0, 1.05, 1.3}) {
    const double rho = x * kRho0;
    const SolidEosPoint e = *m->pressure_at_density(rho, kRho0, 300);
    EXPECT_NEAR(e.pressure, kK / kKp * (std::pow(x, kKp) - 1), 1e-10 * kK) << x;
    EXPECT_NEAR(e.pressure, murnaghan_pressure(1 / x, mp), 1e-10 * kK) << x;  // = the MPM pressure at J = rho0/rho
    EXPECT_NEAR(e.dp_drho, kK / kRho0 * std::pow(x, kKp - 1), 1e-12 * e.dp_drho) << x;
    const double h = 1e-6 * rho;
    const double fd = (m->pressure_at_density(rho + h, kRho0, 300)->pressure -
                       m->pressure_at_density(rho - h, kRho0, 300)->pressure) / (2 * h);
    EXPECT_NEAR(e.dp_drho, fd, 1e-6 * e.dp_drho) << x;
    EXPECT_NEAR(*m->density_at_pressure(e.pressure, kRho0, 300), rho, 1e-10 * rho) << x;
  }
  EXPECT_TRUE(std::isnan(*m->density_at_pressure(-1.01 * kK / kKp, kRho0, 300)));
}

TEST(ModelMurnaghan, BadParametersAreErrors) {
  auto p = params();
  p.values.erase("Kprime");
  EXPECT_THROW(create_constitutive_model("murnaghanMPM", p), std::invalid_argument);
  p = params();
  p.enclosing = {{"density", 2.0 * kRho0}};  // rho0 differs from the material density
  EXPECT_THROW(create_constitutive_model("murnaghanMPM", p), std::invalid_argument);
  p = params();
  p.values["pressure"] = 0.0;
  EXPECT_THROW(create_constitutive_model("murnaghanMPM", p), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
