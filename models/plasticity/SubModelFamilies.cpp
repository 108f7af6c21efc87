#include "models/plasticity/SubModelFamilies.h"

#include "models/plasticity/FlowStressModel.h"
#include "models/plasticity/PlasticityEos.h"
#include "models/plasticity/StabilityCheck.h"
#include "models/plasticity/SubModelTable.h"
#include "models/plasticity/ThermalModels.h"
#include "models/plasticity/YieldCondition.h"
#include "models/solid/ViscoPlastic.h"

namespace tephra {

const std::vector<std::string>& plasticity_sub_model_families() {
  static const std::vector<std::string> f = {
      "equation_of_state", "shear_modulus_model",       "yield_condition", "flow_model",          "internal_variable_model",
      "kinematic_hardening_model", "damage_model", "melting_temp_model", "specific_heat_model", "stability_check",
      "viscoplastic_flow_model"};  // the last: visco_plastic's (models/solid/ViscoPlastic.h)
  return f;
}

std::optional<std::vector<std::string>> plasticity_sub_model_keys(const std::string& family) {
  if (family == "equation_of_state") return sub_model_keys(plasticity_eos_models());
  if (family == "shear_modulus_model") return sub_model_keys(shear_modulus_models());
  if (family == "yield_condition") return sub_model_keys(yield_conditions());
  if (family == "flow_model") return sub_model_keys(flow_stress_models());
  if (family == "internal_variable_model") return sub_model_keys(internal_variable_models());
  if (family == "kinematic_hardening_model") return sub_model_keys(kinematic_hardening_models());
  if (family == "damage_model") return sub_model_keys(damage_models());
  if (family == "melting_temp_model") return sub_model_keys(melting_temperature_models());
  if (family == "specific_heat_model") return sub_model_keys(specific_heat_models());
  if (family == "stability_check") return sub_model_keys(stability_checks());
  if (family == "viscoplastic_flow_model") return viscoplastic_flow_model_keys();
  return std::nullopt;
}

}  // namespace tephra
