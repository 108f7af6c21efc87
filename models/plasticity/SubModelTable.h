#pragma once
// One registry row of a sub-model family: Vaango's canonical key, the older
// spellings decks still use (aliases of the same model), and the creator.
// Lookup is exact (keys are case sensitive, as Vaango's factories are).
#include <memory>
#include <string>
#include <vector>

#include "models/ModelParameters.h"
#include "models/plasticity/PlasticState.h"

namespace tephra {

template <class Model>
struct SubModelEntry {
  std::string name;                  // canonical key (Vaango's schema)
  std::vector<std::string> aliases;  // older spellings found in decks
  std::unique_ptr<Model> (*create)(const ModelParameters&, const SubModelContext&);
};

template <class Model>
const SubModelEntry<Model>* find_sub_model(const std::vector<SubModelEntry<Model>>& table, const std::string& key) {
  for (const auto& e : table) {
    if (e.name == key) return &e;
    for (const auto& a : e.aliases)
      if (a == key) return &e;
  }
  return nullptr;
}

// Every accepted key (canonical names and aliases), for "valid keys are ..." messages.
template <class Model>
std::vector<std::string> sub_model_keys(const std::vector<SubModelEntry<Model>>& table) {
  std::vector<std::string> keys;
  for (const auto& e : table) {
    keys.push_back(e.name);
    keys.insert(keys.end(), e.aliases.begin(), e.aliases.end());
  }
  return keys;
}

// The canonical name of a key (an alias maps to its model), "" if unknown.
template <class Model>
std::string canonical_sub_model(const std::vector<SubModelEntry<Model>>& table, const std::string& key) {
  const auto* e = find_sub_model(table, key);
  return e ? e->name : std::string();
}

// A required positive/finite parameter helper used by the creators.
inline double positive_parameter(const ModelParameters& p, const std::string& name) {
  const double v = p.get_double(name);
  if (!(v > 0.0)) p.fail(name, "must be positive");
  return v;
}

}  // namespace tephra
