// The flow-stress registry: Vaango's keys (ups_spec/constitutive_models.xml)
// and the older spellings the decks use.
#include "models/plasticity/FlowStressModel.h"

namespace tephra {

const std::vector<SubModelEntry<FlowStressModel>>& flow_stress_models() {
  static const std::vector<SubModelEntry<FlowStressModel>> table = {
      {"linear", {"isotropic_hardening"}, &create_linear_flow},
      {"johnson_cook", {}, &create_johnson_cook_flow},
      {"mechanical_threshold_stress", {"mts_model"}, &create_mts_flow},
      {"preston_tonks_wallace", {}, &create_ptw_flow},
      {"steinberg_cochran_guinan", {}, &create_scg_flow},
      {"zerilli_armstrong", {}, &create_zerilli_armstrong_flow},
      {"zerilli_armstrong_polymer", {}, &create_zerilli_armstrong_polymer_flow},
  };
  return table;
}

FlowStressModelP create_flow_stress_model(const std::string& key, const ModelParameters& p,
                                          const SubModelContext& ctx) {
  const auto* e = find_sub_model(flow_stress_models(), key);
  return e ? e->create(p, ctx) : nullptr;
}

}  // namespace tephra
