// The constitutive-model registry: Vaango type name -> creator.
#include <algorithm>
#include <functional>
#include <map>

#include "models/ModelParameters.h"
#include "models/solid/CnhMms.h"
#include "models/solid/CompMooneyRivlin.h"
#include "models/solid/CompNeoHookean.h"
#include "models/solid/CompNeoHookPlastic.h"
#include "models/solid/ElasticPlastic.h"
#include "models/solid/ElasticPlasticHP.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/HypoElastic.h"
#include "models/solid/RigidMaterial.h"
#include "models/solid/ViscoScram.h"
// chapter-3 special materials (solid-models)
#include "models/solid/IdealGasMaterial.h"
#include "models/solid/JwlppMPM.h"
#include "models/solid/MurnaghanMPM.h"
#include "models/solid/MwViscoElastic.h"
#include "models/solid/TransIsoHyper.h"
#include "models/solid/Water.h"
// round 2 (solid-models): MMS / damage variants
#include "models/solid/CnhDamage.h"
#include "models/solid/CnhpDamage.h"  // solids-b
#include "models/solid/ViscoTransIsoHyper.h"  // solids-b
#include "models/solid/ViscoPlastic.h"  // solids-b
#include "models/solid/PAlpha.h"  // solids-b
#include "models/solid/PolarOrthotropicHypoElastic.h"  // solids-b
#include "models/solid/ProgramBurn.h"  // solids-b
#include "models/solid/TabularEos.h"  // solids (VT §22.2)
#include "models/geo/CamClay.h"  // solids-geo
#include "models/geo/MohrCoulomb.h"  // solids-geo

namespace tephra {

namespace {
using Creator = std::function<ConstitutiveModelP(const ModelParameters&)>;

const std::map<std::string, Creator>& creators() {
  static const std::map<std::string, Creator> table = {
      {"cnh_mms", &CnhMms::create},
      {"comp_mooney_rivlin", &CompMooneyRivlin::create},
      {"comp_neo_hook", &CompNeoHookean::create},
      {"comp_neo_hook_plastic",
       [](const ModelParameters& p) { return CompNeoHookPlastic::create(p, "comp_neo_hook_plastic"); }},
      {"elastic_plastic", &ElasticPlastic::create},
      {"elastic_plastic_hp", &ElasticPlasticHP::create},
      {"hypo_elastic", &HypoElastic::create},
      {"rigid", &RigidMaterial::create},
      {"visco_scram", &ViscoScram::create},
      {"UCNH", [](const ModelParameters& p) { return CompNeoHookPlastic::create(p, "UCNH"); }},
      // chapter-3 special materials (solid-models)
      {"ideal_gas", &IdealGasMaterial::create},
      {"jwlpp_mpm", &JwlppMPM::create},
      {"murnaghanMPM", &MurnaghanMPM::create},
      {"mw_visco_elastic", &MwViscoElastic::create},
      {"trans_iso_hyper", &TransIsoHyper::create},
      {"water", &Water::create},
      // round 2 (solid-models): MMS / damage variants
      {"cnh_damage", &CnhDamage::create},
      {"cnhp_damage", &CnhpDamage::create},  // solids-b
      {"visco_trans_iso_hyper", &ViscoTransIsoHyper::create},  // solids-b
      {"visco_plastic", &ViscoPlastic::create},  // solids-b (SUVIC-I)
      {"p_alpha", &PAlpha::create},  // solids-b
      {"polar_orthotropic_hypoelastic", &PolarOrthotropicHypoElastic::create},  // solids-b
      {"program_burn", &ProgramBurn::create},  // solids-b
      {"hypo_elastic_mms", &HypoElastic::create_mms},
      {"camclay", &CamClay::create},  // solids-geo (VT ch. 20)
      {"mohr_coulomb", &MohrCoulomb::create},  // solids-geo (VT ch. 19)
      {"tabular_eos", &TabularEos::create},  // solids (VT §22.2)
  };
  return table;
}
}  // namespace

std::vector<std::string> constitutive_model_types() {
  std::vector<std::string> keys;
  for (const auto& [k, v] : creators()) keys.push_back(k);
  return keys;
}

// The type attribute values of Vaango's schema (ups_spec/constitutive_models.xml).
const std::vector<std::string>& vaango_constitutive_model_types() {
  static const std::vector<std::string> types = {
      "comp_mooney_rivlin", "comp_neo_hook", "comp_neo_hook_plastic", "elastic_plastic",
      "hypo_elastic", "hypo_elastic_fortran", "hypo_elastic_fracture", "hypo_elastic_mms",
      "elastic_plastic_hp", "ideal_gas", "membrane", "murnaghanMPM", "mw_visco_elastic", "rigid",
      "shell_CNH", "trans_iso_hyper", "visco_plastic", "visco_scram", "visco_trans_iso_hyper",
      "water", "kayenta", "diamm", "cnh_mms", "cnh_damage", "cnhp_damage", "UCNH", "program_burn",
      "jwlpp_mpm", "p_alpha", "nonlocal_drucker_prager", "Arenisca", "Arenisca3", "arena",
      "arena_mixture", "Arenisca4", "soil_model_brannon", "tabular_eos", "tabular_plasticity",
      "tabular_plasticity_cap", "mohr_coulomb", "camclay", "polar_orthotropic_hypoelastic",
      "viscoelastic_fortran"};
  return types;
}

ConstitutiveModelP create_constitutive_model(const std::string& type, const ModelParameters& params) {
  auto it = creators().find(type);
  if (it == creators().end()) return nullptr;
  return it->second(params);
}

}  // namespace tephra
