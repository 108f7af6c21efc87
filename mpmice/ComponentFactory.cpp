#include "mpmice/ComponentFactory.h"

#include <map>

#include "core/base/Errors.h"

namespace tephra {

std::unique_ptr<Component> make_component(const Deck& deck) {
  const DeckNode& sc = deck.root.require_child("SimulationComponent");
  std::string type = sc.require_attribute("type");
  sc.missing_feature("SimulationComponent type '" + type + "'");
}

std::vector<std::string> registered_keys(const std::string& family) {
  static const std::map<std::string, std::vector<std::string>> families = {
      {"SimulationComponent", {}}, {"constitutive_model", {}}, {"EOS", {}},
      {"Model", {}},               {"contact", {}},            {"interpolator", {}},
  };
  auto it = families.find(family);
  if (it == families.end()) {
    std::string known;
    for (const auto& [k, v] : families) known += " " + k;
    throw UsageError("unknown family '" + family + "'; families:" + known);
  }
  return it->second;
}

}  // namespace tephra
