// `tephra --list FAMILY` for the sub-model families of elastic_plastic(_hp): every key
// issue 4 (item 1) names is registered under its family, and the deck aliases it names
// too (von_mises/vonMises, linear/isotropic_hardening, mts_model, steinberg_cochran_guinan).
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "models/plasticity/SubModelFamilies.h"
#include "mpmice/ComponentFactory.h"

namespace tephra {
namespace {

// Issue 4, "What to build", item 1 (the keys of Vaango's schema, constitutive_models.xml).
const std::map<std::string, std::vector<std::string>> kIssueKeys = {
    {"equation_of_state", {"default_hypo", "default_hyper", "mie_gruneisen", "mie_gruneisen_energy", "air", "water", "granite"}},
    {"shear_modulus_model", {"constant_shear", "mts_shear", "scg_shear", "np_shear", "ptw_shear"}},
    {"yield_condition", {"von_mises", "gurson", "rousselier", "vonMises"}},
    {"flow_model",
     {"linear", "johnson_cook", "mechanical_threshold_stress", "preston_tonks_wallace", "steinberg_cochran_guinan",
      "zerilli_armstrong", "zerilli_armstrong_polymer", "isotropic_hardening", "mts_model"}},
    {"internal_variable_model", {"metal_internal_var"}},
    {"kinematic_hardening_model", {"prager", "armstrong_frederick"}},
    {"damage_model", {"johnson_cook", "hancock_mackenzie"}},
    {"melting_temp_model", {"constant_Tm", "linear_Tm", "scg_Tm", "bps_Tm"}},
    {"specific_heat_model", {"constant_Cp", "cubic_Cp", "copper_Cp", "steel_Cp"}},
    {"stability_check", {"none", "drucker", "acoustic", "becker", "drucker_becker"}},
    {"viscoplastic_flow_model", {"suvic_i"}},  // visco_plastic's
};

TEST(SubModelFamilies, EveryIssueKeyIsListed) {
  ASSERT_EQ(plasticity_sub_model_families().size(), kIssueKeys.size());
  for (const auto& family : plasticity_sub_model_families()) {
    ASSERT_TRUE(kIssueKeys.count(family)) << family;
    const std::vector<std::string> listed = registered_keys(family);  // what `tephra --list` prints
    for (const auto& key : kIssueKeys.at(family))
      EXPECT_NE(std::find(listed.begin(), listed.end(), key), listed.end()) << family << ": " << key;
    // No key twice within a family (an alias that shadows another row would be ambiguous).
    std::vector<std::string> sorted = listed;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << family;
  }
}

TEST(SubModelFamilies, UnknownFamilyNamesTheSubModelFamilies) {
  EXPECT_FALSE(plasticity_sub_model_keys("no_such_family"));
  try {
    registered_keys("no_such_family");
    FAIL() << "expected a usage error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("stability_check"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("constitutive_model"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tephra
