#pragma once
// The sub-model families of the composed metal models (elastic_plastic, elastic_plastic_hp;
// Vaango's factories), by the deck element that selects them, for `tephra --list FAMILY`:
// equation_of_state, shear_modulus_model, yield_condition, flow_model, internal_variable_model,
// kinematic_hardening_model, damage_model, melting_temp_model, specific_heat_model,
// stability_check. Each lists its canonical keys and the older spellings decks use (aliases).
#include <optional>
#include <string>
#include <vector>

namespace tephra {

// The family names above, in that order.
const std::vector<std::string>& plasticity_sub_model_families();
// Every accepted key of `family` (canonical names, then aliases, per row); nullopt if unknown.
std::optional<std::vector<std::string>> plasticity_sub_model_keys(const std::string& family);

}  // namespace tephra
