// program_burn (models/solid/ProgramBurn.h): the burned fraction from the front
// that leaves starting_location at T0 with speed D, through the point context
// (x_p, t, V0), and the JWL++ mixture pressure of VT eqs. 3.15-3.17.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "models/solid/ProgramBurn.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
using V3 = Eigen::Vector3d;
// ANFO-like JWL++ constants (K a compressibility [1/Pa]).
const double kK = 3.9e-10, kN = 7.4, kA = 2.9867e11, kB = 4.11706e9, kC = 7.206147e8, kR1 = 4.95, kR2 = 1.15,
             kOm = 0.35, kRho0 = 1160.0, kD = 5000.0;

test::MapModelParameters params(const std::string& start, const std::string& dir = "", double T0 = 0) {
  test::MapModelParameters p({{"K", kK}, {"n", kN}, {"A", kA}, {"B", kB}, {"C", kC}, {"R1", kR1}, {"R2", kR2},
                              {"om", kOm}, {"rho0", kRho0}, {"D", kD}, {"T0", T0}});
  p.strings["starting_location"] = start;
  if (!dir.empty()) p.strings["direction_if_plane"] = dir;
  return p;
}

// One step ending in F = J^{1/3} I, starting at time t (the model's burn time), at x.
test::PointState at(const ConstitutiveModel& m, const V3& x, double t, double J, double V0 = 8e-9) {
  test::PointState s(m);
  s.x = x;
  s.volume0 = V0;
  EXPECT_EQ(test::step_point(m, kRho0, s, M3::Identity(), 0.0), -1);
  s.time = t;
  EXPECT_EQ(test::step_point(m, kRho0, s, std::cbrt(J) * M3::Identity(), 1e-9), -1);
  return s;
}

double p_murnaghan(double J) { return (std::pow(J, -kN) - 1) / (kN * kK); }                        // eq. 3.16
double p_jwl(double J) { return kA * std::exp(-kR1 * J) + kB * std::exp(-kR2 * J) + kC * std::pow(J, -(1 + kOm)); }  // 3.17

TEST(ModelProgramBurn, PointIgnitionFractionFromTheFrontAtDt) {
  // x_0 = (0.1, 0, 0), the point at distance d = 0.05 m: t_b = d/D = 1e-5 s. The particle
  // (V0 = 8e-9 m^3, mass rho0 V0) burns through in dL = 1.5 V0^{1/3}/D = 1.5 * 2e-3 / 5000 = 6e-7 s:
  //   F = (t - t_b)/dL on [t_b, t_b + 0.96 dL], 1 after; p = (1 - F) p_M + F p_JWL.
  const ConstitutiveModelP m = create_constitutive_model("program_burn", params("[0.1, 0, 0]"));
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->needs_position());
  const V3 x(0.1, 0.03, 0.04);  // |x - x_0| = 0.05
  const double tb = 0.05 / kD, dL = 1.5 * 2e-3 / kD, J = 0.9;
  struct Case {
    double t, F;
  };
  for (const Case c : {Case{0.0, 0.0}, Case{tb * (1 - 1e-9), 0.0}, Case{tb + 0.25 * dL, 0.25}, Case{tb + 0.5 * dL, 0.5},
                       Case{tb + 0.95 * dL, 0.95}, Case{tb + 0.97 * dL, 1.0}, Case{tb + 10 * dL, 1.0}}) {
    const test::PointState s = at(*m, x, c.t, J);
    EXPECT_NEAR(s.history[0][0], c.F, 1e-6) << "t = " << c.t;
    const double p = (1 - c.F) * p_murnaghan(J) + c.F * p_jwl(J);
    EXPECT_NEAR(-s.stress(0, 0), p, 1e-6 * std::abs(p) + 1e-6 * p_jwl(J)) << "t = " << c.t;
    EXPECT_EQ(s.stress(0, 1), 0.0);
  }
  // Unreacted sound speed: c^2 = (1/(K rho0)) (rho/rho0)^{n-1}, rho/rho0 = 1/J.
  const test::PointState s0 = at(*m, x, 0.0, J);
  EXPECT_NEAR(s0.wave_speed * s0.wave_speed, std::pow(1 / J, kN - 1) / (kK * kRho0), 1e-12 * std::pow(1 / J, kN - 1) / (kK * kRho0));
  // The front is spherical: a point twice as far burns at twice the time.
  const V3 far(0.1, 0.06, 0.08);
  EXPECT_EQ(at(*m, far, 2 * tb * (1 - 1e-9), J).history[0][0], 0.0);
  EXPECT_NEAR(at(*m, far, 2 * tb + 0.5 * dL, J).history[0][0], 0.5, 1e-6);
}

TEST(ModelProgramBurn, PlaneIgnitionAndIgnitionTimeT0) {
  // Plane through x_0 = (0, 0, 0) with normal (0, 0, 2): t_b = |z|/D whatever x, y; T0 shifts the clock.
  const double T0 = 3e-6;
  const ConstitutiveModelP m = create_constitutive_model("program_burn", params("[0, 0, 0]", "[0, 0, 2]", T0));
  const double dL = 1.5 * 2e-3 / kD, tb = 0.02 / kD;
  for (const V3& x : {V3(0, 0, 0.02), V3(5, -3, 0.02), V3(1, 1, -0.02)}) {
    EXPECT_EQ(at(*m, x, T0 + tb * (1 - 1e-9), 1.0).history[0][0], 0.0);
    EXPECT_NEAR(at(*m, x, T0 + tb + 0.4 * dL, 1.0).history[0][0], 0.4, 1e-6);
  }
  // Burn-through time scales with the particle size: V0 8x larger -> dL 2x larger.
  EXPECT_NEAR(at(*m, V3(0, 0, 0.02), T0 + tb + 0.4 * dL, 1.0, 64e-9).history[0][0], 0.2, 1e-6);
  // Fully burned at J = 1: p = p_JWL(1) = A e^{-R1} + B e^{-R2} + C.
  const test::PointState s = at(*m, V3(0, 0, 0), T0 + dL, 1.0);
  EXPECT_NEAR(-s.stress(1, 1), kA * std::exp(-kR1) + kB * std::exp(-kR2) + kC, 1e-9 * kA);
}

TEST(ModelProgramBurn, Parameters) {
  test::MapModelParameters p = params("[0, 0]");
  EXPECT_THROW(create_constitutive_model("program_burn", p), std::invalid_argument);
  test::MapModelParameters q = params("[0, 0, 0]");
  q.values["D"] = 0;
  EXPECT_THROW(create_constitutive_model("program_burn", q), std::invalid_argument);
  test::MapModelParameters r = params("[0, 0, 0]");
  r.values.erase("om");
  EXPECT_THROW(create_constitutive_model("program_burn", r), std::invalid_argument);
  ASSERT_EQ(create_constitutive_model("program_burn", params("[0, 0, 0]"))->history()[0].name, "progressF");
}

}  // namespace
}  // namespace tephra
