// cnhp_damage (models/solid/CnhpDamage.h): the comp_neo_hook_plastic J2 return
// (Simo & Hughes 1998 Box 9.1, linear hardening) with cnh_damage's brittle
// failure and erosion. Closed forms: the one-step return from the reference
// state in simple shear; the Green-Lagrange threshold in uniaxial strain.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "models/solid/CnhDamage.h"
#include "models/solid/CnhpDamage.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kK = 8.0e9, kG = 3.0e9, kSy = 3.0e7, kH = 1.0e8, kRho0 = 8930.0;

ConstitutiveModelP make(double threshold, bool by_stress) {
  test::MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"yield_stress", kSy},
                              {"hardening_modulus", kH}, {"failure_variable_mean", threshold}});
  if (by_stress) p.values["failure_by_stress"] = 1;
  ConstitutiveModelP m = create_constitutive_model("cnhp_damage", p);
  if (!m) throw std::runtime_error("cnhp_damage not registered");
  return m;
}

M3 shear(double g) {
  M3 F = M3::Identity();
  F(0, 1) = g;
  return F;
}
M3 uniaxial(double l) {
  M3 F = M3::Identity();
  F(0, 0) = l;
  return F;
}

// One step from the reference state to simple shear F = I + g e1 (x) e2 (J = 1):
//   bbar_trial = B = [[1+g^2, g, 0], [g, 1, 0], [0, 0, 1]], I_e = (3 + g^2)/3,
//   s_trial = G dev B, |s_trial| = G g sqrt(2 g^2/3 + 2),
//   f = |s_trial| - sqrt(2/3) sigma_y, dgamma = f / (2 G I_e (1 + H/(3 G I_e)))   (Box 9.1)
//   s = c s_trial, c = 1 - 2 G I_e dgamma / |s_trial|, sigma = s (J = 1), alpha = sqrt(2/3) dgamma.
// Max principal stress of c G dev B (1-2 plane): c G [g^2/6 + sqrt(g^4/4 + g^2)].
struct ShearReturn {
  double c, alpha, smax;
};
ShearReturn shear_return(double g) {
  const double Ie = (3 + g * g) / 3, norm = kG * g * std::sqrt(2 * g * g / 3 + 2);
  const double f = norm - std::sqrt(2.0 / 3.0) * kSy;
  const double dgamma = f / (2 * kG * Ie * (1 + kH / (3 * kG * Ie)));
  const double c = 1 - 2 * kG * Ie * dgamma / norm;
  return {c, std::sqrt(2.0 / 3.0) * dgamma, c * kG * (g * g / 6 + std::sqrt(g * g * g * g / 4 + g * g))};
}

TEST(ModelCnhpDamage, OneStepShearReturnClosedFormAndStressFailureAtThePlasticStress) {
  const double g = 0.05;  // |s_trial| ~ 0.15 G = 450 MPa >> sqrt(2/3) sigma_y: plastic
  const ShearReturn r = shear_return(g);
  ASSERT_LT(r.c, 0.2);
  for (double side : {+1.0, -1.0}) {
    // Threshold just above (intact) / just below (failed) the plastic max principal stress.
    const ConstitutiveModelP m = make(r.smax * (1 + side * 1e-9), true);
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    ASSERT_EQ(test::step_point(*m, kRho0, s, shear(g), 1e-6), -1);
    EXPECT_NEAR(s.history[1][0], r.alpha, 1e-12 * r.alpha);  // alpha = sqrt(2/3) dgamma either way
    if (side > 0) {
      EXPECT_EQ(s.history[2][0], 0.0);
      EXPECT_NEAR(s.stress(0, 0), r.c * 2 * kG * g * g / 3, 1e-9 * kSy);
      EXPECT_NEAR(s.stress(1, 1), -r.c * kG * g * g / 3, 1e-9 * kSy);
      EXPECT_NEAR(s.stress(2, 2), -r.c * kG * g * g / 3, 1e-9 * kSy);
      EXPECT_NEAR(s.stress(0, 1), r.c * kG * g, 1e-9 * kSy);
      EXPECT_GT(s.plastic_work, 0.0);
    } else {
      EXPECT_EQ(s.history[2][0], 1.0);
      EXPECT_EQ(s.stress, M3::Zero());
      EXPECT_EQ(s.energy_density, 0.0);
    }
  }
  // The elastic cnh_damage with the same threshold does not fail: its shear stress
  // G g (1/c times larger) fails much earlier -- the threshold is met by the plastic stress only.
  test::MapModelParameters pe({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"failure_variable_mean", r.smax},
                               {"failure_by_stress", 1}});
  const ConstitutiveModelP e = create_constitutive_model("cnh_damage", pe);
  test::PointState se(*e);
  ASSERT_EQ(test::step_point(*e, kRho0, se, shear(g), 1e-6), -1);
  EXPECT_EQ(se.history[0][0], 1.0);
}

TEST(ModelCnhpDamage, IntactPathIsCompNeoHookPlasticAndStrainFailureAtGreenLagrangeThreshold) {
  // Uniaxial strain F = diag(l,1,1): max principal Green-Lagrange strain (l^2 - 1)/2,
  // threshold e_f = 0.05 -> l_c = sqrt(1 + 2 e_f). Before l_c every step equals
  // comp_neo_hook_plastic's (same return, bit for bit) and plastic; after, zero stress.
  const double ef = 0.05, lc = std::sqrt(1 + 2 * ef);
  const ConstitutiveModelP m = make(ef, false);
  test::MapModelParameters pp({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"yield_stress", kSy},
                               {"hardening_modulus", kH}});
  const ConstitutiveModelP ref = create_constitutive_model("comp_neo_hook_plastic", pp);
  test::PointState s(*m), t(*ref);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  ASSERT_EQ(test::step_point(*ref, kRho0, t, M3::Identity(), 0.0), -1);
  double W_last = 0, dissipated = 0;
  for (int k = 1; k <= 20; ++k) {
    const double l = 1 + k * (lc * (1 - 1e-9) - 1) / 20;
    ASSERT_EQ(test::step_point(*m, kRho0, s, uniaxial(l), 1e-6), -1);
    ASSERT_EQ(test::step_point(*ref, kRho0, t, uniaxial(l), 1e-6), -1);
    EXPECT_EQ(s.history[2][0], 0.0) << "l = " << l;
    EXPECT_EQ(s.stress, t.stress);
    EXPECT_EQ(s.plastic_work, t.plastic_work);
    EXPECT_EQ(s.history[1][0], t.history[1][0]);
    W_last = s.energy_density;
    dissipated += s.plastic_work;
  }
  EXPECT_GT(s.history[1][0], 0.0);  // yielded on the way
  // Consistency at the last plastic step: |J dev sigma| = sqrt(2/3)(sigma_y + H alpha).
  const M3 tau = s.F.determinant() * s.stress;
  EXPECT_NEAR((tau - tau.trace() / 3 * M3::Identity()).norm(), std::sqrt(2.0 / 3.0) * (kSy + kH * s.history[1][0]),
              1e-9 * kSy);
  ASSERT_EQ(test::step_point(*m, kRho0, s, uniaxial(lc * (1 + 1e-9)), 1e-6), -1);
  EXPECT_EQ(s.history[2][0], 1.0);
  EXPECT_EQ(s.stress, M3::Zero());
  EXPECT_EQ(s.energy_density, 0.0);
  // Released: the stored energy just before (to 1e-6: F moved by 2e-9) plus the step's dissipation.
  EXPECT_NEAR(s.plastic_work, W_last, 1e-3 * W_last);
  EXPECT_GT(dissipated, 0.0);
  const double alpha_failed = s.history[1][0];
  for (double l : {1.0, 0.9, 1.3}) {
    ASSERT_EQ(test::step_point(*m, kRho0, s, uniaxial(l), 1e-6), -1);
    EXPECT_EQ(s.history[2][0], 1.0);
    EXPECT_EQ(s.stress, M3::Zero());
    EXPECT_EQ(s.plastic_work, 0.0);
    EXPECT_EQ(s.history[1][0], alpha_failed);  // frozen
    EXPECT_GT(s.wave_speed, 0.0);
  }
}

TEST(ModelCnhpDamage, Parameters) {
  test::MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"yield_stress", kSy},
                              {"hardening_modulus", kH}});
  EXPECT_THROW(create_constitutive_model("cnhp_damage", p), std::invalid_argument);  // threshold required
  p.values["failure_variable_mean"] = 0.1;
  ConstitutiveModelP m = create_constitutive_model("cnhp_damage", p);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->history().size(), 3u);
  EXPECT_EQ(m->history()[0].name, "bElBar");
  EXPECT_EQ(m->history()[1].name, "plasticStrain");
  EXPECT_EQ(m->history()[2].name, "localized");
  p.values.erase("yield_stress");
  EXPECT_THROW(create_constitutive_model("cnhp_damage", p), std::invalid_argument);
  p.values["yield_stress"] = kSy;
  p.values["failure_variable_std"] = 0.01;
  EXPECT_THROW(create_constitutive_model("cnhp_damage", p), std::logic_error);  // MissingFeature
}

}  // namespace
}  // namespace tephra
