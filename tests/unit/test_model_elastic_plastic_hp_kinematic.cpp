// elastic_plastic_hp with kinematic hardening (VT ch. 11: Prager eq. 11.2,
// Armstrong-Frederick eq. 11.3; von Mises yield on xi = s - beta): the closed-form
// uniaxial-strain tests run for both metal models in test_model_elastic_plastic_kinematic
// (KinematicClosedForm/elastic_plastic_hp); here what only elastic_plastic_hp checks.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kK = 117e9, kG = 43.8e9, kS0 = 70e6;  // copper-tube values of the inventory (ch. 17)

MapModelParameters base() {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"isothermal", 1.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", 0.0}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}};
  return p;
}

TEST(ElasticPlasticHPKinematic, MissingFeatureCombinations) {
  auto is_missing = [](const MapModelParameters& p) {
    try {  // MapModelParameters: fail() throws invalid_argument, missing_feature() logic_error
      create_constitutive_model("elastic_plastic_hp", p);
    } catch (const std::invalid_argument&) {
      return false;
    } catch (const std::logic_error&) {
      return true;
    }
    return false;
  };
  auto ok = base();
  ok.add_block("kinematic_hardening_model", "prager", {{"hardening_modulus", 1e9}});
  EXPECT_FALSE(is_missing(ok));
  auto st = ok;
  st.add_block("stability_check", "acoustic");
  EXPECT_FALSE(is_missing(st));  // the stability tangent on xi = s - beta with the kinematic modulus
  auto g = ok;
  g.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
  EXPECT_FALSE(is_missing(g));  // the shifted two-invariant return (test_plasticity_porous_kinematic)
  auto none = base();
  none.add_block("kinematic_hardening_model", "none");
  EXPECT_EQ(create_constitutive_model("elastic_plastic_hp", none)->history().size(), 6u);  // + strainRate
}

}  // namespace
}  // namespace tephra
