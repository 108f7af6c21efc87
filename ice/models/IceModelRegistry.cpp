// <Models><Model type=...> -> IceModel, keyed by Vaango's type names.
#include <algorithm>
#include <cmath>
#include <map>

#include "core/deck/DeckNode.h"
#include "ice/models/ModelSupport.h"

namespace tephra {

namespace {

using Factory = IceModelP (*)(const DeckNode&, const IceSetup&);

const std::map<std::string, Factory>& factories() {
  static const std::map<std::string, Factory> f = {
      {"IandG", make_ignition_growth}, {"JWLpp", make_jwlpp},
      {"LightTime", make_light_time},  {"PassiveScalar", make_passive_scalar},
      {"ZeroOrder", make_zero_order},  {"mass_momentum_energy_src", make_mass_mom_eng_src},
      {"SimpleRxn", make_simple_rxn},
  };
  return f;
}

// Vaango's other <Model type> values (ups_spec/Models.xml): valid input that
// Tephra does not run yet (exit 3). In MPMICE decks Simple_Burn,
// Steady_Burn, Unsteady_Burn, DDT0, DDT1, Test and SolidReactionModel are
// run by mpmice/'s factories, tried first (mpmice_burn_model_factories). The EOS names in that list are not
// models at all (Vaango's schema lists them there by mistake).
const std::vector<std::string>& vaango_types() {
  static const std::vector<std::string> v = {"AdiabaticTable", "Radiation", "Simple_Burn",
                                             "Steady_Burn", "Test", "Unsteady_Burn",
                                             "flameSheet_rxn", "DDT0", "DDT1", "SolidReactionModel", "MesoBurn"};
  return v;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

std::vector<std::string> ice_model_types() {
  std::vector<std::string> keys;
  for (const auto& [k, f] : factories()) keys.push_back(k);
  keys.push_back("ADD_HEAT");  // <CFD><ICE><ADD_HEAT>, not a <Model>
  std::sort(keys.begin(), keys.end());
  return keys;
}

const DeckNode& model_block(const DeckNode& model, const char* block_name) {
  const DeckNode* b = model.child(block_name);
  if (!b) return model;
  // Both layouts at once would leave it open which parameters count.
  for (const DeckNode& c : model.children)
    if (c.name != block_name) c.fail(std::string("parameters both in <Model> and in its <") + block_name + "> block");
  return *b;
}

// A material by name (the name attribute of an ICE <material>) or by index.
std::size_t ModelParams::material(const char* name, const IceSetup& setup) {
  used_.insert(name);
  const DeckNode& n = block_.require_child(name);
  const std::string v = n.as_string();
  for (std::size_t m = 0; m < setup.materials.size(); ++m)
    if (!setup.materials[m].name.empty() && setup.materials[m].name == v) return m;
  if (auto i = parse_integer(v); i && *i >= 0 && std::size_t(*i) < setup.materials.size()) return std::size_t(*i);
  std::string names;
  for (const IceMaterialSpec& s : setup.materials) names += (names.empty() ? "" : ", ") + (s.name.empty() ? "(unnamed)" : s.name);
  n.fail("no ICE material named '" + v + "' (materials: " + names + ")");
}

std::vector<IceModelP> parse_ice_models(const DeckNode& root, const IceSetup& setup, const IceModelFactories& extra) {
  std::vector<IceModelP> out;
  if (const DeckNode* cfd = root.child("CFD"))
    if (const DeckNode* ice = cfd->child("ICE"))
      if (const DeckNode* ah = ice->child("ADD_HEAT")) out.push_back(make_add_heat(*ah, setup));
  const DeckNode* models = root.child("Models");
  if (!models) return out;
  for (const DeckNode& m : models->children) {
    if (m.name != "Model") m.fail("<Models> holds <Model> elements only");
    const std::string type = m.require_attribute("type");
    if (auto e = extra.find(type); e != extra.end()) {
      out.push_back(e->second(m, setup));
      continue;
    }
    auto it = factories().find(type);
    if (it != factories().end()) {
      out.push_back(it->second(m, setup));
      // A per-cell ideal gas (SimpleRxn) owns its material's gamma and cv: one model per material.
      if (const CellIdealGas* gas = out.back()->cell_ideal_gas())
        for (std::size_t o = 0; o + 1 < out.size(); ++o)
          if (const CellIdealGas* other = out[o]->cell_ideal_gas(); other && other->material == gas->material)
            m.fail("two models set the mixture properties of ICE material " + std::to_string(gas->material));
      continue;
    }
    const auto& v = vaango_types();
    if (std::find(v.begin(), v.end(), type) != v.end())
      m.missing_feature("Model type '" + type + "' (implemented: " + join(ice_model_types()) + ")");
    m.fail("unknown Model type '" + type + "' (implemented: " + join(ice_model_types()) + ")");
  }
  return out;
}

}  // namespace tephra
