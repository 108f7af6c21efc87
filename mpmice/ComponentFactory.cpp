#include "mpmice/ComponentFactory.h"

#include <map>

#include "core/base/Errors.h"
#include "ice/IceComponent.h"
#include "ice/models/IceModel.h"
#include "models/plasticity/SubModelFamilies.h"
#include "models/solid/ConstitutiveModel.h"
#include "mpm/MpmComponent.h"
#include "mpmice/BurnModels.h"
#include "mpmice/MpmIceComponent.h"

namespace tephra {

// SimulationComponent types of Vaango's schema. "mpm" and "ice" run today; the
// others are valid input that needs a component Tephra does not have yet.
std::unique_ptr<Component> make_component(const Deck& deck) {
  const DeckNode& sc = deck.root.require_child("SimulationComponent");
  std::string type = sc.require_attribute("type");
  if (type == "mpm") return make_mpm_component(deck);
  if (type == "ice") return make_ice_component(deck);
  if (type == "mpmice") return make_mpmice_component(deck);
  sc.missing_feature("SimulationComponent type '" + type + "' (only 'mpm', 'ice' and 'mpmice' run so far)");
}

std::vector<std::string> registered_keys(const std::string& family) {
  static const std::map<std::string, std::vector<std::string> (*)()> families = {
      {"SimulationComponent", [] { return std::vector<std::string>{"mpm", "ice", "mpmice"}; }},
      {"constitutive_model", [] { return constitutive_model_types(); }},
      {"EOS", [] { return equation_of_state_types(); }},
      {"Model",
       [] {  // the ICE models, then the MPMICE burn models (mpmice/BurnModels.h)
         std::vector<std::string> keys = ice_model_types();
         for (const auto& [type, factory] : mpmice_burn_model_factories()) keys.push_back(type + " (MPMICE)");
         return keys;
       }},
      {"contact", [] { return mpm_contact_types(); }},
      {"interpolator", [] { return mpm_interpolators(); }},
  };
  // The sub-model families of elastic_plastic(_hp) (models/plasticity/SubModelFamilies.h).
  if (auto keys = plasticity_sub_model_keys(family)) return *keys;
  auto it = families.find(family);
  if (it == families.end()) {
    std::string known;
    for (const auto& [k, v] : families) known += " " + k;
    for (const auto& k : plasticity_sub_model_families()) known += " " + k;
    throw UsageError("unknown family '" + family + "'; families:" + known);
  }
  return it->second();
}

}  // namespace tephra
