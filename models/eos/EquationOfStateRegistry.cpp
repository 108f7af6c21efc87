// EOS registry: Vaango type name -> creator.
#include <map>

#include "models/eos/EquationOfState.h"
#include "models/eos/EosModels.h"
#include "models/eos/IdealGas.h"

namespace tephra {

namespace {

using Creator = EquationOfStateP (*)(const ModelParameters&, const EosMaterialConstants&);

const std::map<std::string, Creator>& creators() {
  static const std::map<std::string, Creator> m = {
      {"ideal_gas",
       [](const ModelParameters& p, const EosMaterialConstants& c) -> EquationOfStateP {
         // Vaango's optional <gas_constant> is not used by its ideal gas
         // either (p follows from gamma and cv); reject it rather than ignore it.
         if (p.has("gas_constant")) p.missing_feature("gas_constant", "ideal_gas <gas_constant>");
         if (!(c.gamma > 1.0)) p.fail("gamma", "ideal_gas needs gamma > 1");
         if (!(c.cv > 0.0)) p.fail("specific_heat", "ideal_gas needs specific_heat > 0");
         return std::make_unique<IdealGas>(c.gamma, c.cv);
       }},
      {"hard_sphere_gas", make_hard_sphere_gas},
      {"TST", make_tst},
      {"JWL", make_jwl},
      {"JWLC", make_jwlc},
      {"Murnaghan", make_murnaghan},
      {"BirchMurnaghan", make_birch_murnaghan},
      {"Gruneisen", make_gruneisen},
      {"Tillotson", make_tillotson},
      {"Thomsen_Hartka_water", make_thomsen_hartka_water},
      {"KnaussSeaWater", make_knauss_sea_water},
      // KumariDass: not registered. Vaango's KumariDass.cc is not a usable
      // EOS (rho(p) does not depend on p, p(rho0) = 1/lambda instead of 0,
      // dp/drho < 0 for lambda B0 > B0'); a deck naming it gets MissingFeature.
  };
  return m;
}

}  // namespace

EquationOfStateP create_equation_of_state(const std::string& type, const ModelParameters& params,
                                          const EosMaterialConstants& constants) {
  auto it = creators().find(type);
  if (it == creators().end()) return nullptr;
  return it->second(params, constants);
}

std::vector<std::string> equation_of_state_types() {
  std::vector<std::string> v;
  for (const auto& [k, c] : creators()) v.push_back(k);
  return v;
}

const std::vector<std::string>& vaango_equation_of_state_types() {
  static const std::vector<std::string> v = {"ideal_gas", "hard_sphere_gas", "TST", "Thomsen_Hartka_water",
                                             "JWL", "JWLC", "Murnaghan", "BirchMurnaghan", "Gruneisen",
                                             "Tillotson", "KnaussSeaWater", "KumariDass"};
  return v;
}

}  // namespace tephra
