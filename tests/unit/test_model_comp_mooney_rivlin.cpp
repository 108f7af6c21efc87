// comp_mooney_rivlin (models/solid/CompMooneyRivlin.h), VT eq. 4.10-4.12.
#include <gtest/gtest.h>

#include <cmath>

#include "models/solid/CompMooneyRivlin.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
// C1, C2, nu of Vaango's const_test_cmr.ups deck.
const CompMooneyRivlinParams kP{1.0e5, 2.0e4, 0.49};
const double kRho0 = 1100.0;

TEST(ModelCompMooneyRivlin, UniaxialStretchClosedForm) {
  // F = diag(l, 1, 1): B = diag(l^2, 1, 1), I1 = l^2 + 2, J = l, I3 = l^2,
  // W3 = -2 C3 / l^6 + 2 C4 (l^2 - 1):
  //   sigma_11 = 2 l (C1 + 2 C2) + 2 l W3
  //   sigma_22 = sigma_33 = (2/l) (C1 + C2 (l^2 + 1)) + 2 l W3
  //   W = C1 (l^2 - 1) + C2 (2 l^2 + 1 - 3) + C3 (l^-4 - 1) + C4 (l^2 - 1)^2
  const double C1 = kP.C1, C2 = kP.C2, C3 = kP.C3(), C4 = kP.C4();
  for (double l : {0.7, 0.95, 1.05, 1.5}) {
    M3 F = M3::Identity();
    F(0, 0) = l;
    const SolidPointResult r = comp_mooney_rivlin_point(F, kRho0, kP);
    const double W3 = -2 * C3 / std::pow(l, 6) + 2 * C4 * (l * l - 1);
    const double tol = 1e-14 * (C1 + C2 + std::abs(C4));
    EXPECT_NEAR(r.stress(0, 0), 2 * l * (C1 + 2 * C2) + 2 * l * W3, tol);
    EXPECT_NEAR(r.stress(1, 1), 2 / l * (C1 + C2 * (l * l + 1)) + 2 * l * W3, tol);
    EXPECT_NEAR(r.stress(2, 2), r.stress(1, 1), tol);
    EXPECT_NEAR(r.energy_density,
                C1 * (l * l - 1) + C2 * (2 * l * l - 2) + C3 * (std::pow(l, -4) - 1) + C4 * std::pow(l * l - 1, 2), tol);
    // VT eq. 4.7 along x (the stretched axis, lambda_1 = l) and y (lambda = 1):
    //   d2W/dl1^2 = 2 C1 + 4 C2 + [20 C3 / l^4 + 4 C4 l^2 (3 l^2 - 1)] / l^2
    //   d2W/dl2^2 = 2 C1 + 2 C2 (l^2 + 1) + 20 C3 / l^4 + 4 C4 l^2 (3 l^2 - 1)
    const double m1 = 2 * C1 + 4 * C2 + (20 * C3 / std::pow(l, 4) + 4 * C4 * l * l * (3 * l * l - 1)) / (l * l);
    const double m2 = 2 * C1 + 2 * C2 * (l * l + 1) + 20 * C3 / std::pow(l, 4) + 4 * C4 * l * l * (3 * l * l - 1);
    ASSERT_GT(std::max(m1, m2), 0.0);
    EXPECT_NEAR(r.wave_speed, std::sqrt(std::max(m1, m2) / kRho0), 1e-12 * r.wave_speed);
  }
}

TEST(ModelCompMooneyRivlin, SimpleShearStressIsLinearInGamma) {
  // F = I + g e1 (x) e2: J = I3 = 1, B12 = g, (B^2)12 = g (2 + g^2), I1 = 3 + g^2, so
  //   sigma_12 = 2 [(C1 + C2 I1) g - C2 g (2 + g^2)] = 2 (C1 + C2) g = G g exactly,
  //   sigma_11 - sigma_22 = 2 [(C1 + C2 I1) g^2 - C2 ((B^2)11 - (B^2)22)] with
  //   (B^2)11 - (B^2)22 = (1+g^2)^2 - 1 = 2 g^2 + g^4  ->  2 (C1 + C2) g^2 = G g^2.
  for (double g : {0.1, 0.5, 1.0}) {
    M3 F = M3::Identity();
    F(0, 1) = g;
    const SolidPointResult r = comp_mooney_rivlin_point(F, kRho0, kP);
    EXPECT_NEAR(r.stress(0, 1), kP.shear_modulus() * g, 1e-14 * kP.shear_modulus());
    EXPECT_NEAR(r.stress(0, 0) - r.stress(1, 1), kP.shear_modulus() * g * g, 1e-14 * kP.shear_modulus());
  }
}

TEST(ModelCompMooneyRivlin, ModuliAndParameters) {
  // G = 2 (C1 + C2), K = 2G(1 + nu)/(3(1 - 2 nu)) (header; checked against the
  // response by the contract SmallStrainLimitIsLinearElasticity).
  EXPECT_DOUBLE_EQ(kP.shear_modulus(), 2.4e5);
  EXPECT_NEAR(kP.bulk_modulus(), 2 * 2.4e5 * 1.49 / (3 * 0.02), 1e-9 * kP.bulk_modulus());
  test::MapModelParameters p({{"he_constant_1", 1e5}, {"he_constant_2", 2e4}, {"he_PR", 0.49}});
  ConstitutiveModelP m = create_constitutive_model("comp_mooney_rivlin", p);
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->hyperelastic());
  ASSERT_TRUE(m->pressure_at_density(kRho0, kRho0, 300).has_value());  // Tephra's hydrostatic hooks
  p.values["he_PR"] = 0.5;
  EXPECT_THROW(create_constitutive_model("comp_mooney_rivlin", p), std::invalid_argument);
  p.values["he_PR"] = 0.49;
  p.values.erase("he_constant_2");
  EXPECT_THROW(create_constitutive_model("comp_mooney_rivlin", p), std::invalid_argument);
}

TEST(ModelCompMooneyRivlin, LossOfStabilityIsReported) {
  // nu = 0.3 makes C4 < 0 (eq. 4.11): the volumetric stiffness 20 C3/J^6 + C4 (12 J^2 - 4)
  // turns negative in moderate tension and no real wave speed exists (eq. 4.7);
  // the update rejects that state instead of returning c = NaN or 0.
  const CompMooneyRivlinParams p{1.0e5, 2.0e4, 0.3};
  ASSERT_LT(p.C4(), 0.0);
  CompMooneyRivlin m(p);
  test::PointState s(m);
  EXPECT_EQ(test::step_point(m, kRho0, s, 1.01 * M3::Identity(), 1e-3), -1);
  EXPECT_EQ(test::step_point(m, kRho0, s, 1.3 * M3::Identity(), 1e-3), 0);
}

TEST(ModelRigid, ZeroStressForAnyDeformationAndHeldReferenceConfiguration) {
  // VT eq. 3.1: sigma = 0 and F = I (the driver holds F because rigid() is true).
  test::MapModelParameters p;
  ConstitutiveModelP m = create_constitutive_model("rigid", p);
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->rigid());
  EXPECT_EQ(m->bulk_modulus(), 1e200);  // Vaango default
  test::PointState s(*m);
  M3 F = M3::Identity();
  F(0, 1) = 0.3;
  F(2, 2) = 0.5;
  s.stress.setConstant(7.0);  // whatever came before
  ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-3), -1);
  EXPECT_EQ(s.stress, M3::Zero());
  EXPECT_EQ(s.wave_speed, 0.0);
  EXPECT_EQ(s.energy_density, 0.0);
  p.values["bulk_modulus"] = -1;
  EXPECT_THROW(create_constitutive_model("rigid", p), std::invalid_argument);
}

TEST(ModelCompMooneyRivlin, PressureHooksAreTheHydrostaticStress) {
  // The hook p(rho) is the pressure of the point function at F = J^{1/3} I, J = rho0/rho:
  // sigma = -p I (eq. 4.12 reduced to a hydrostatic state); round trip 1e-10.
  test::MapModelParameters p({{"he_constant_1", 1e5}, {"he_constant_2", 2e4}, {"he_PR", 0.49}});
  ConstitutiveModelP m = create_constitutive_model("comp_mooney_rivlin", p);
  for (double J : {0.8, 0.95, 1.0, 1.05, 1.3}) {
    const SolidPointResult r = comp_mooney_rivlin_point(std::cbrt(J) * Eigen::Matrix3d::Identity(), kRho0, kP);
    const SolidEosPoint e = *m->pressure_at_density(kRho0 / J, kRho0, 300);
    EXPECT_NEAR(e.pressure, -r.stress(0, 0), 1e-9 * kP.bulk_modulus()) << J;
    EXPECT_NEAR(r.stress(0, 1), 0.0, 1e-9 * kP.bulk_modulus());
    const double rho = kRho0 / J, h = 1e-6 * rho;
    const double fd = (m->pressure_at_density(rho + h, kRho0, 300)->pressure -
                       m->pressure_at_density(rho - h, kRho0, 300)->pressure) / (2 * h);
    EXPECT_NEAR(e.dp_drho, fd, 1e-6 * e.dp_drho);
    EXPECT_NEAR(*m->density_at_pressure(e.pressure, kRho0, 300), rho, 1e-10 * rho);
  }
}

}  // namespace
}  // namespace tephra
