// cnh_damage (models/solid/CnhDamage.h): comp_neo_hook stress, brittle failure
// by max principal Green-Lagrange strain or max principal Cauchy stress, erosion
// to zero stress. Closed forms of sigma = K/2 (J - 1/J) I + G J^{-5/3} dev(B).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "models/solid/CnhDamage.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kK = 8.0e9, kG = 3.0e9, kRho0 = 7800.0;

ConstitutiveModelP make(double threshold, bool by_stress) {
  test::MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"failure_variable_mean", threshold}});
  if (by_stress) p.values["failure_by_stress"] = 1;
  ConstitutiveModelP m = create_constitutive_model("cnh_damage", p);
  if (!m) throw std::runtime_error("cnh_damage not registered");
  return m;
}

M3 uniaxial(double l) {
  M3 F = M3::Identity();
  F(0, 0) = l;
  return F;
}
M3 shear(double g) {
  M3 F = M3::Identity();
  F(0, 1) = g;
  return F;
}

TEST(ModelCnhDamage, UniaxialStrainClosedFormAndStrainFailureExactlyAtThreshold) {
  // F = diag(l,1,1): J = l, dev(B) = (l^2 - 1)/3 diag(2, -1, -1), so
  //   sigma_11 = K/2 (l - 1/l) + 2G l^{-5/3} (l^2 - 1)/3
  //   sigma_22 = sigma_33 = K/2 (l - 1/l) - G l^{-5/3} (l^2 - 1)/3.
  // Green-Lagrange E_11 = (l^2 - 1)/2 is the max principal strain (l > 1):
  // with e_f = 0.1 failure happens at l_c = sqrt(1 + 2 e_f), not before.
  const double ef = 0.1, lc = std::sqrt(1 + 2 * ef);
  const ConstitutiveModelP m = make(ef, false);
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= 10; ++k) {
    const double l = 1 + k * (lc * (1 - 1e-9) - 1) / 10;
    ASSERT_EQ(test::step_point(*m, kRho0, s, uniaxial(l), 1e-6), -1);
    EXPECT_EQ(s.history[0][0], 0.0) << "l = " << l;
    const double vol = 0.5 * kK * (l - 1 / l), dev = kG * std::pow(l, -5.0 / 3) * (l * l - 1) / 3;
    EXPECT_NEAR(s.stress(0, 0), vol + 2 * dev, 1e-12 * kK);
    EXPECT_NEAR(s.stress(1, 1), vol - dev, 1e-12 * kK);
    EXPECT_NEAR(s.stress(2, 2), vol - dev, 1e-12 * kK);
    EXPECT_EQ(s.plastic_work, 0.0);
  }
  const double W_before = s.energy_density;
  EXPECT_GT(W_before, 0.0);
  // Cross the threshold: flag set, stress eroded, stored energy released as dissipation.
  ASSERT_EQ(test::step_point(*m, kRho0, s, uniaxial(lc * (1 + 1e-9)), 1e-6), -1);
  EXPECT_EQ(s.history[0][0], 1.0);
  EXPECT_EQ(s.stress, M3::Zero());
  EXPECT_EQ(s.energy_density, 0.0);
  EXPECT_NEAR(s.plastic_work, W_before, 1e-6 * W_before);  // W(l_c(1+1e-9)) ~ W(l_c(1-1e-9))
  // Failure is permanent: unloading to F = I and compressing keep zero stress, no more dissipation.
  for (double l : {1.0, 0.9}) {
    ASSERT_EQ(test::step_point(*m, kRho0, s, uniaxial(l), 1e-6), -1);
    EXPECT_EQ(s.history[0][0], 1.0);
    EXPECT_EQ(s.stress, M3::Zero());
    EXPECT_EQ(s.plastic_work, 0.0);
  }
}

TEST(ModelCnhDamage, CompressionNeverFailsByStrain) {
  // F = diag(l,1,1), l < 1: principal Green-Lagrange strains (l^2 - 1)/2 < 0, 0, 0:
  // the max is 0, never above e_f > 0, however large the compression.
  const ConstitutiveModelP m = make(1e-3, false);
  const test::PointState s = test::drive_path(*m, kRho0, [](double a) { return uniaxial(1 - 0.5 * a); }, 20);
  EXPECT_EQ(s.history[0][0], 0.0);
  EXPECT_LT(s.stress(0, 0), 0.0);
}

TEST(ModelCnhDamage, SimpleShearClosedFormAndStressFailureExactlyAtThreshold) {
  // F = I + g e1 (x) e2: J = 1, sigma = G dev(B), B = [[1+g^2, g, 0], [g, 1, 0], [0, 0, 1]]:
  //   sigma_11 = 2 G g^2/3, sigma_22 = sigma_33 = -G g^2/3, sigma_12 = G g.
  // Max principal stress (the 1-2 plane; sigma_33 is smaller):
  //   s_max = (s11 + s22)/2 + sqrt(((s11 - s22)/2)^2 + s12^2) = G [g^2/6 + sqrt(g^4/4 + g^2)].
  // Threshold = s_max(g_c), g_c = 0.2: intact up to g_c (1 - 1e-9), failed just above.
  const double gc = 0.2;
  const auto smax = [](double g) { return kG * (g * g / 6 + std::sqrt(g * g * g * g / 4 + g * g)); };
  const ConstitutiveModelP m = make(smax(gc), true);
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= 8; ++k) {
    const double g = k * gc * (1 - 1e-9) / 8;
    ASSERT_EQ(test::step_point(*m, kRho0, s, shear(g), 1e-6), -1);
    EXPECT_EQ(s.history[0][0], 0.0) << "g = " << g;
    EXPECT_NEAR(s.stress(0, 0), 2 * kG * g * g / 3, 1e-12 * kK);
    EXPECT_NEAR(s.stress(1, 1), -kG * g * g / 3, 1e-12 * kK);
    EXPECT_NEAR(s.stress(2, 2), -kG * g * g / 3, 1e-12 * kK);
    EXPECT_NEAR(s.stress(0, 1), kG * g, 1e-12 * kK);
    // The model's criterion value is the closed form s_max.
    const CnhDamageParams p{{kK, kG}, smax(gc), true};
    EXPECT_NEAR(cnh_damage_criterion(shear(g), s.stress, p), smax(g), 1e-12 * kK);
  }
  ASSERT_EQ(test::step_point(*m, kRho0, s, shear(gc * (1 + 1e-9)), 1e-6), -1);
  EXPECT_EQ(s.history[0][0], 1.0);
  EXPECT_EQ(s.stress, M3::Zero());
}

TEST(ModelCnhDamage, ShearStrainCriterionClosedForm) {
  // Green-Lagrange strain of simple shear: E = 1/2 [[0, g, 0], [g, g^2, 0], [0, 0, 0]],
  // max eigenvalue e_max = (g^2 + g sqrt(g^2 + 4))/4.
  const CnhDamageParams p{{kK, kG}, 1.0, false};
  for (double g : {0.01, 0.3, 2.0}) {
    EXPECT_NEAR(cnh_damage_criterion(shear(g), M3::Zero(), p), (g * g + g * std::sqrt(g * g + 4)) / 4, 1e-14);
  }
}

TEST(ModelCnhDamage, Parameters) {
  test::MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}});
  EXPECT_THROW(create_constitutive_model("cnh_damage", p), std::invalid_argument);  // threshold required
  p.values["failure_variable_mean"] = 0.1;
  ConstitutiveModelP m = create_constitutive_model("cnh_damage", p);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->bulk_modulus(), kK);
  EXPECT_EQ(m->shear_modulus(), kG);
  ASSERT_EQ(m->history().size(), 1u);
  EXPECT_EQ(m->history()[0].name, "localized");
  p.values["failure_variable_std"] = 0.01;
  EXPECT_THROW(create_constitutive_model("cnh_damage", p), std::logic_error);  // MissingFeature
  p.values.erase("failure_variable_std");
  // <failure_variable_distrib> with std 0: every point's threshold is the mean (accepted, the
  // same model); with std > 0 the random thresholds are the MissingFeature above.
  p.strings["failure_variable_distrib"] = "gauss";
  EXPECT_TRUE(create_constitutive_model("cnh_damage", p));
  p.values["failure_variable_std"] = 0.01;
  EXPECT_THROW(create_constitutive_model("cnh_damage", p), std::logic_error);
  p.values.erase("failure_variable_std");
  p.strings.erase("failure_variable_distrib");
  p.values["failure_variable_mean"] = -1;
  EXPECT_THROW(create_constitutive_model("cnh_damage", p), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
