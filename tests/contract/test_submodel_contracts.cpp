// Contracts of the metal-plasticity sub-model registries (models/plasticity):
// every key of Vaango's schema (ups_spec/constitutive_models.xml) for these
// families is accepted, aliases map to one model, and every file of
// decks/inputs/MPM/MaterialData that holds one of these sub-models creates it
// with every child read (no silently ignored parameter).
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <set>
#include <vector>

#include "core/deck/DeckLoader.h"
#include "models/plasticity/FlowStressModel.h"
#include "models/plasticity/PlasticityEos.h"
#include "models/plasticity/ThermalModels.h"
#include "models/plasticity/YieldCondition.h"
#include "mpm/DeckModelParameters.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

// Parameters that remember which names a creator read.
class RecordingParameters final : public ModelParameters {
 public:
  std::map<std::string, double> values;
  mutable std::set<std::string> used;
  bool has(const std::string& n) const override { used.insert(n); return values.count(n) > 0; }
  double get_double(const std::string& n) const override {
    used.insert(n);
    if (!values.count(n)) throw std::invalid_argument("missing " + n);
    return values.at(n);
  }
  double get_double(const std::string& n, double f) const override { used.insert(n); return values.count(n) ? values.at(n) : f; }
  bool get_bool(const std::string& n, bool f) const override { used.insert(n); return values.count(n) ? values.at(n) != 0 : f; }
  [[noreturn]] void fail(const std::string& n, const std::string& m) const override { throw std::invalid_argument(n + ": " + m); }
  [[noreturn]] void missing_feature(const std::string& n, const std::string& m) const override { throw std::logic_error(n + ": " + m); }
};

// Creates the sub-model of `family` named `key`; true if the family knows the key.
bool create(const std::string& family, const std::string& key, const ModelParameters& p) {
  const SubModelContext ctx{.bulk_modulus = 1.6e11, .shear_modulus = 8e10, .melt_temperature = 1700,
                            .specific_heat = 450, .room_temperature = 294, .density0 = 7800};
  if (family == "flow_model") return create_flow_stress_model(key, p, ctx) != nullptr;
  if (family == "shear_modulus_model") return create_shear_modulus_model(key, p, ctx) != nullptr;
  if (family == "equation_of_state") return create_plasticity_eos(key, p, ctx) != nullptr;
  if (family == "yield_condition") return create_yield_condition(key, p, ctx) != nullptr;
  if (family == "melting_temp_model") return create_melting_temperature_model(key, p, ctx) != nullptr;
  if (family == "specific_heat_model") return create_specific_heat_model(key, p, ctx) != nullptr;
  if (family == "damage_model") return create_damage_model(key, p, ctx) != nullptr;
  if (family == "kinematic_hardening_model") return create_kinematic_hardening_model(key, p, ctx) != nullptr;
  if (family == "internal_variable_model") return create_internal_variable_model(key, p, ctx) != nullptr;
  return false;
}

// The sub-model elements of a deck tree, depth first.
void collect_sub_models(const DeckNode& n, const std::set<std::string>& families,
                        std::vector<const DeckNode*>& out) {
  for (const DeckNode& c : n.children) {
    if (families.count(c.name) && c.attribute("type")) out.push_back(&c);
    collect_sub_models(c, families, out);
  }
}

// Each MaterialData file is read the way a deck includes it (the project's
// deck loader: <include> of the file, its <Uintah_Include> root replaced by
// its children), and each sub-model is built through the same parameter
// adapter the MPM deck reader uses; check_all_used() rejects any child the
// model did not read.
TEST(SubmodelContract, EveryMaterialDataFileCreatesItsSubModel) {
  const auto dir = std::filesystem::path(test::shared_dir()) / "decks/inputs/MPM/MaterialData";
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
  const std::set<std::string> families = {
      "flow_model",         "shear_modulus_model", "equation_of_state",         "yield_condition",
      "melting_temp_model", "specific_heat_model", "damage_model", "kinematic_hardening_model",
      "internal_variable_model"};
  int files = 0, models = 0;
  for (const auto& f : std::filesystem::recursive_directory_iterator(dir)) {
    if (f.path().extension() != ".xml") continue;
    const std::string name = f.path().filename().string();
    if (name.find("Template") != std::string::npos) continue;  // blank templates, not materials
    SCOPED_TRACE(name);
    const std::string wrapper =
        "<Uintah_specification><include href=\"" + name + "\"/></Uintah_specification>";
    std::unique_ptr<Deck> deck;
    try {
      deck = load_deck_from_string(wrapper, f.path().string(), f.path().parent_path().string());
    } catch (const DeckError& e) {
      // Known malformed file, included by no deck: MPM/MaterialData/
      // MurnaghanEOSANFO.xml closes <constitutive_model> as </consitutive_model>.
      EXPECT_EQ(name, "MurnaghanEOSANFO.xml") << e.what();
      continue;
    }
    std::vector<const DeckNode*> found;
    collect_sub_models(deck->root, families, found);
    for (const DeckNode* node : found) {
      const std::string family = node->name, key = *node->attribute("type");
      SCOPED_TRACE(family + " " + key);
      DeckModelParameters params(*node);
      try {
        ASSERT_TRUE(create(family, key, params)) << "unknown key";
        params.check_all_used(family);
      } catch (const DeckError& e) {
        // Known malformed value: SCGPlasticTantalum.xml writes <A>1.3-11</A>
        // (for 1.3e-11); Vaango and the deck reader reject it.
        EXPECT_EQ(name, "SCGPlasticTantalum.xml") << e.what();
        continue;
      }
      ++models;
    }
    if (!found.empty()) ++files;
  }
  EXPECT_GE(files, 90);  // 106 files at the time of writing, some holding several models
  std::cout << "MaterialData: " << files << " files, " << models << " sub-models created\n";
}

// The type lists of Vaango's schema for these families (constitutive_models.xml).
TEST(SubmodelContract, EverySchemaKeyIsRegistered) {
  const std::map<std::string, std::vector<std::string>> schema = {
      {"flow_model", {"linear", "johnson_cook", "mechanical_threshold_stress", "preston_tonks_wallace",
                      "steinberg_cochran_guinan", "zerilli_armstrong", "zerilli_armstrong_polymer"}},
      {"equation_of_state", {"default_hyper", "default_hypo", "mie_gruneisen", "mie_gruneisen_energy",
                             "borja_pressure", "air", "water", "granite"}},
      {"shear_modulus_model", {"borja_shear", "constant_shear", "mts_shear", "np_shear", "ptw_shear", "scg_shear"}},
      {"specific_heat_model", {"constant_Cp", "cubic_Cp", "copper_Cp", "steel_Cp"}},
      {"melting_temp_model", {"constant_Tm", "linear_Tm", "scg_Tm", "bps_Tm"}},
      {"damage_model", {"hancock_mackenzie", "johnson_cook"}},
      {"kinematic_hardening_model", {"none", "prager", "armstrong_frederick"}},
      {"internal_variable_model", {"metal_internal_var"}},
      {"yield_condition", {"von_mises", "gurson", "rousselier"}},
  };
  std::set<std::string> keys;
  auto add = [&](const std::string& fam, const std::vector<std::string>& k) { for (auto& x : k) keys.insert(fam + "/" + x); };
  add("flow_model", sub_model_keys(flow_stress_models()));
  add("equation_of_state", sub_model_keys(plasticity_eos_models()));
  add("shear_modulus_model", sub_model_keys(shear_modulus_models()));
  add("specific_heat_model", sub_model_keys(specific_heat_models()));
  add("melting_temp_model", sub_model_keys(melting_temperature_models()));
  add("damage_model", sub_model_keys(damage_models()));
  add("kinematic_hardening_model", sub_model_keys(kinematic_hardening_models()));
  add("internal_variable_model", sub_model_keys(internal_variable_models()));
  add("yield_condition", sub_model_keys(yield_conditions()));
  for (const auto& [fam, types] : schema)
    for (const auto& t : types) EXPECT_TRUE(keys.count(fam + "/" + t)) << fam << " " << t;
  // Deck aliases name the same model as their canonical key.
  EXPECT_EQ(canonical_sub_model(yield_conditions(), "vonMises"), "von_mises");
  EXPECT_EQ(canonical_sub_model(flow_stress_models(), "isotropic_hardening"), "linear");
  EXPECT_EQ(canonical_sub_model(flow_stress_models(), "mts_model"), "mechanical_threshold_stress");
  EXPECT_EQ(canonical_sub_model(flow_stress_models(), "no_such_model"), "");
}

// Bad input: a missing required parameter and a non-positive one are errors,
// schema-valid but unimplemented options are MissingFeature (logic_error here).
TEST(SubmodelContract, BadParametersFailLoudly) {
  RecordingParameters jc;
  jc.values = {{"A", 1}, {"B", 1}, {"C", 0}, {"n", 1}};  // no <m>
  EXPECT_THROW(create_flow_stress_model("johnson_cook", jc), std::invalid_argument);
  RecordingParameters g;
  g.values = {{"q1", 1.5}, {"q2", 1}, {"q3", -2}, {"k", 4}, {"f_c", 0.05}};
  EXPECT_THROW(create_yield_condition("gurson", g), std::invalid_argument);
  RecordingParameters none;
  EXPECT_THROW(create_shear_modulus_model("borja_shear", none), std::logic_error);
  EXPECT_THROW(create_plasticity_eos("default_hypo", none), std::invalid_argument);  // no κ anywhere
}

}  // namespace
}  // namespace tephra
