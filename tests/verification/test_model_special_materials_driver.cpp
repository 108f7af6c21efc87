// The chapter-3 special materials (VT §3.2-3.5) through the real MPM step: one
// cell of particles taken along uniaxial strain F*(t) = diag(lambda(t), 1, 1),
// lambda: 1 -> 0.8 over 1 ms (tests/support/PrescribedDriver.h). Expected:
//   sigma = -p(J) I with J = lambda and the model's closed-form p(J):
//     ideal_gas     p = p_ref (J^{-gamma} - 1)                (VT eq. 3.4)
//     water         p = kappa (J^{-gamma} - 1)                (VT eq. 3.8)
//     murnaghanMPM  p = (K/K') (J^{-K'} - 1)                  (VT eq. 3.11)
//     jwlpp_mpm     p = (J^{-n} - 1)/(n kappa)  below ignition (VT eqs. 3.15-3.16, f = 0)
//   and, with a viscosity mu, the Newtonian part 2 mu dev(d): sigma11 - sigma22 = 2 mu d11,
//   d11 = (lambda_{n+1}/lambda_n - 1)/dt (the MPM step's l of the homogeneous motion).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"
#include "tests/support/PrescribedDriver.h"

namespace tephra {
namespace {

const double kT1 = 1e-3, kLambda = 0.8;

std::vector<PrescribedRow> uniaxial() {
  return {PrescribedRow{0.0, Mat3::Identity(), 0.0, Vec3::UnitZ()},
          PrescribedRow{kT1, Vec3(kLambda, 1, 1).asDiagonal(), 0.0, Vec3::UnitZ()}};
}

void expect_pressure(const std::string& xml, double p_exact, double scale, test::PrescribedDriverOptions o = {}) {
  o.steps = 50;
  const test::PrescribedHistory h = test::drive_prescribed(xml, uniaxial(), o);
  const Mat3& s = h.stress.back();
  std::printf("%s\n  sigma = diag(%.8e, %.8e, %.8e), -p exact %.8e\n", xml.substr(0, 48).c_str(), s(0, 0), s(1, 1),
              s(2, 2), -p_exact);
  EXPECT_LE((s + p_exact * Mat3::Identity()).norm(), 1e-10 * scale);
}

TEST(SpecialMaterialsDriver, UniaxialStrainPressureIsTheClosedForm) {
  set_thread_count(1);
  const double J = kLambda;
  expect_pressure("<constitutive_model type=\"ideal_gas\"><gamma>1.4</gamma><specific_heat>716</specific_heat>"
                  "<reference_pressure>101325</reference_pressure></constitutive_model>",
                  101325.0 * (std::pow(J, -1.4) - 1), 101325.0, {.density = 1.2});
  expect_pressure("<constitutive_model type=\"water\"><bulk_modulus>3e8</bulk_modulus><gamma>7.15</gamma>"
                  "<viscosity>0</viscosity></constitutive_model>",
                  3e8 * (std::pow(J, -7.15) - 1), 3e8);
  expect_pressure("<constitutive_model type=\"murnaghanMPM\"><K>2.56e9</K><Kprime>7.4</Kprime>"
                  "<pressure>101325</pressure><rho0>1160</rho0><viscosity>0</viscosity></constitutive_model>",
                  2.56e9 / 7.4 * (std::pow(J, -7.4) - 1), 2.56e9, {.density = 1160.0});
  // Ignition far above the pressures reached: the unreacted Murnaghan branch.
  expect_pressure("<constitutive_model type=\"jwlpp_mpm\"><ignition_pressure>1e12</ignition_pressure>"
                  "<viscosity>0</viscosity><murnaghan_K>3.9e-10</murnaghan_K><murnaghan_n>7.4</murnaghan_n>"
                  "<jwl_A>2.9867e11</jwl_A><jwl_B>4.11706e9</jwl_B><jwl_C>7.206147e8</jwl_C><jwl_R1>4.95</jwl_R1>"
                  "<jwl_R2>1.15</jwl_R2><jwl_om>0.35</jwl_om><reaction_G>3.5083e-7</reaction_G>"
                  "<reaction_b>1.3</reaction_b></constitutive_model>",
                  (std::pow(J, -7.4) - 1) / (7.4 * 3.9e-10), 1 / 3.9e-10, {.density = 1160.0});
}

TEST(SpecialMaterialsDriver, WaterViscousStressIsNewtonian) {
  set_thread_count(1);
  const double mu = 1.0e3;  // a syrup, so the viscous part is well above round-off
  const test::PrescribedHistory h = test::drive_prescribed(
      "<constitutive_model type=\"water\"><bulk_modulus>3e8</bulk_modulus><gamma>7.15</gamma>"
      "<viscosity>1e3</viscosity></constitutive_model>",
      uniaxial(), {.steps = 200});  // n below
  const Mat3& s = h.stress.back();
  // The last step's l is (F_{n+1} F_n^{-1} - I)/dt of the homogeneous motion:
  // d11 = (lambda_N / lambda_{N-1} - 1)/dt (-> lambda_dot/lambda as dt -> 0).
  const int n = 200;
  const double dt = kT1 / n, lam_prev = 1 - (1 - kLambda) * (n - 1) / n;
  const double d11 = (kLambda / lam_prev - 1) / dt;
  std::printf("water mu = 1e3: sigma11 - sigma22 = %.8e, 2 mu d11 = %.8e (continuum 2 mu lambda_dot/lambda = %.8e)\n",
              s(0, 0) - s(1, 1), 2 * mu * d11, 2 * mu * (-(1 - kLambda) / kT1) / kLambda);
  EXPECT_NEAR((s(0, 0) - s(1, 1)) / (2 * mu * d11), 1.0, 1e-8);
  EXPECT_NEAR(s(1, 1), s(2, 2), 1e-9 * std::abs(s(1, 1)));
  // mean stress still -p(J): the viscous part is trace-free.
  EXPECT_NEAR(s.trace() / 3, -3e8 * (std::pow(kLambda, -7.15) - 1), 1e-9 * 3e8);
}

TEST(SpecialMaterialsDriver, DeckErrorsNameTheElement) {
  set_thread_count(1);
  // The old Uintah name <gamma> (inputs/MPM/MaterialData/MurnaghanEOSANFO.xml) instead of <Kprime>:
  // the required <Kprime> is missing -> DeckError at the <constitutive_model> element.
  const std::string old_names =
      "<constitutive_model type=\"murnaghanMPM\"><K>2.56e9</K><gamma>7.4</gamma>"
      "<pressure>101325</pressure><rho0>1000</rho0><viscosity>0</viscosity></constitutive_model>";
  try {
    test::drive_prescribed(old_names, uniaxial());
    ADD_FAILURE() << "no DeckError";
  } catch (const DeckError& e) {
    std::printf("DeckError: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("Kprime"), std::string::npos);
    EXPECT_GT(e.where().line, 0);
  }
  // rho0 different from the material <density>.
  EXPECT_THROW(test::drive_prescribed("<constitutive_model type=\"murnaghanMPM\"><K>2.56e9</K><Kprime>7.4</Kprime>"
                                      "<pressure>101325</pressure><rho0>1160</rho0><viscosity>0</viscosity>"
                                      "</constitutive_model>",
                                      uniaxial(), {.density = 1000.0}),
               DeckError);
  // A valid deck asking for an unimplemented option: MissingFeature (exit 3).
  EXPECT_THROW(test::drive_prescribed("<constitutive_model type=\"jwlpp_mpm\"><ignition_pressure>1e12</ignition_pressure>"
                                      "<viscosity>0</viscosity><murnaghan_K>3.9e-10</murnaghan_K><murnaghan_n>7.4</murnaghan_n>"
                                      "<jwl_A>2.9867e11</jwl_A><jwl_B>4.11706e9</jwl_B><jwl_C>7.206147e8</jwl_C>"
                                      "<jwl_R1>4.95</jwl_R1><jwl_R2>1.15</jwl_R2><jwl_om>0.35</jwl_om>"
                                      "<reaction_G>3.5083e-7</reaction_G><reaction_b>1.3</reaction_b>"
                                      "<useInitialStress>true</useInitialStress></constitutive_model>",
                                      uniaxial()),
               MissingFeature);
}

}  // namespace
}  // namespace tephra
