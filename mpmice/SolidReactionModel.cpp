// <Model type="SolidReactionModel"> in MPMICE (mpmice/SolidBurn.h): the
// Arrhenius-type bulk reaction of Uintah's SolidReactionModel (rate laws in
// mpmice/SolidReaction.h) in every cell that holds the MPM reactant - no
// burning surface - taken from the particles by the common burn machinery
// (ParticleBurn.cpp), so the particles lose exactly what the product gains.
//
// Deck: <Model type="SolidReactionModel"><SolidReactionModel> <fromMaterial>
// <toMaterial> <E0> <RateConstantModel type=...> <RateModel type=...>
// (Uintah's layout; the flat layout is accepted too, model_block).
// Saved fields: F, delF (Uintah's labels, reactant material); sums
// totalMassBurned, totalHeatReleased.
// Not implemented (MissingFeature, exit 3): an ICE <fromMaterial> (Uintah
// lets an ICE material react too), the Diffusion rate model of dimension 4
// (Uintah has no formula for it).
// Departures from Uintah: T_r is the reactant's cell temperature of this
// step (the MPM projection; Uintah reads the old ICE temp_CC label); the
// energy and momentum leaving with the mass are the particles' c_v T and
// m v (docs/mpmice.md); 0 x inf (k = 0 where f is infinite) burns nothing.
#include <algorithm>
#include <cmath>

#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/SolidBurn.h"
#include "mpmice/SolidReaction.h"

namespace tephra {

namespace {

class SolidReactionMpmModel final : public SolidBurnModel {
 public:
  SolidReactionMpmModel(const RateConstantLaw& k, const RateModelLaw& f, double E0, std::size_t reactant,
                        std::size_t product)
      : SolidBurnModel("SolidReactionModel", "SolidReactionModel", reactant, product, E0, 0.0), k_(k), f_(f) {}

  void initialize(const Grid& grid, const std::vector<IceMaterialFields>& mats) override {
    SolidBurnModel::initialize(grid, mats);
    F_ = CellScalars(grid, 0);
    delF_ = CellScalars(grid, 0);
  }

  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    F_.fill(0.0);
    delF_.fill(0.0);
    SolidBurnModel::compute_sources(in, out);
  }

  // Every cell with reactant mass reacts (Uintah: every cell of the patch).
  bool select_cell(const double /*wm*/[8], BurnCell& cell) const override {
    cell.surface = false;
    cell.temperature = cell.in->mats[reactant()].temp_CC[cell.patch](cell.c);
    return cell.solid_mass > 0;
  }

  std::set<std::string> labels() const override { return {"totalMassBurned", "totalHeatReleased", "F", "delF"}; }
  std::vector<ModelField> fields() const override { return {{"F", 0, &F_}, {"delF", 0, &delF_}}; }

 protected:
  double burn_mass(const BurnCell& c) override {
    const double Mr = c.solid_mass;
    const double Mp = c.in->mats[product()].rho_CC[c.patch](c.c) * c.volume;  // per radian when axisymmetric
    const double F = Mp / (Mr + Mp);
    const double delF = solid_reaction_delF(k_, f_, c.temperature, F, c.in->dt);
    F_[c.patch](c.c) = F;
    delF_[c.patch](c.c) = delF;
    const double dm = std::min(delF * (Mr + Mp), Mr);
    return std::isnan(dm) ? 0.0 : dm;  // 0 x inf: no rate (header)
  }

 private:
  RateConstantLaw k_;
  RateModelLaw f_;
  CellScalars F_, delF_;
};

RateConstantLaw read_rate_constant(const DeckNode& node) {
  const std::string type = node.require_attribute("type");
  ModelParams mp(node, "SolidReactionModel <RateConstantModel type=\"" + type + "\">");
  RateConstantLaw k;
  if (type == "Arrhenius") k.kind = RateConstantLaw::Kind::Arrhenius;
  else if (type == "ModifiedArrhenius") k.kind = RateConstantLaw::Kind::ModifiedArrhenius;
  else node.fail("unknown RateConstantModel type '" + type + "' (Arrhenius, ModifiedArrhenius)");
  k.A = mp.number("A");
  k.Ea = mp.number("Ea");
  if (k.kind == RateConstantLaw::Kind::ModifiedArrhenius) k.b = mp.number("b");
  mp.finish();
  return k;
}

RateModelLaw read_rate_model(const DeckNode& node) {
  using K = RateModelLaw::Kind;
  const std::string type = node.require_attribute("type");
  ModelParams mp(node, "SolidReactionModel <RateModel type=\"" + type + "\">");
  RateModelLaw f;
  if (type == "AvaramiErofeev" || type == "Power") {
    f.kind = type == "Power" ? K::Power : K::AvaramiErofeev;
    f.a = mp.number("a");
    f.b = mp.number("b");
  } else if (type == "ContractingCylinder") {
    f.kind = K::ContractingCylinder;
  } else if (type == "ContractingSphere") {
    f.kind = K::ContractingSphere;
  } else if (type == "Diffusion") {
    f.kind = K::Diffusion;
    const double d = mp.number("dimension");
    const DeckNode& dn = node.require_child("dimension");
    if (!(d == 1 || d == 2 || d == 3 || d == 4)) dn.fail("Diffusion <dimension> must be 1, 2, 3 or 4");
    if (d == 4) dn.missing_feature("SolidReactionModel Diffusion rate model of dimension 4 (Ginstling-Brounshtein)");
    f.dimension = int(d);
  } else if (type == "NthOrder") {
    f.kind = K::NthOrder;
    const double n = mp.number("n");
    if (!(n >= 0 && n == std::floor(n) && n < 1000))
      node.require_child("n").fail("NthOrder <n> must be a non-negative integer (Uintah multiplies (1 - F) n times)");
    f.n = int(n);
  } else if (type == "ProutTompkins") {
    f.kind = K::ProutTompkins;
    f.q = mp.number("q");
    f.n_real = mp.number("n");
    f.m = mp.number("m");
    mp.number("p", 0.0);  // read, not used by the rate (mpmice/SolidReaction.h)
  } else {
    node.fail("unknown RateModel type '" + type +
              "' (AvaramiErofeev, ContractingCylinder, ContractingSphere, Diffusion, NthOrder, Power, ProutTompkins)");
  }
  mp.finish();
  return f;
}

}  // namespace

IceModelP make_solid_reaction_model(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "SolidReactionModel"), "SolidReactionModel");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  if (!setup.materials[r].lagrangian)
    mp.node().require_child("fromMaterial").missing_feature("SolidReactionModel with an ICE <fromMaterial>");
  check_reactant_product(mp, setup, r, p, "SolidReactionModel");
  const double E0 = mp.number("E0");
  const RateConstantLaw k = read_rate_constant(mp.child("RateConstantModel"));
  const RateModelLaw f = read_rate_model(mp.child("RateModel"));
  mp.finish();
  return std::make_shared<SolidReactionMpmModel>(k, f, E0, r, p);
}

}  // namespace tephra
