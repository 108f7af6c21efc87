// <Model type="DDT0"> in MPMICE (mpmice/SolidBurn.h): the branch of each cell
// and its burned mass from mpmice/Ddt0.h (JWL++ detonation above
// <ThresholdPressureJWL>, Simple_Burn surface burning between
// <ThresholdPressureSB> and it, with Uintah's optional crack term), taken
// from the particles by the common burn machinery (ParticleBurn.cpp), so the
// particles lose exactly what the product gains in both branches.
//
// Deck layout: Uintah reads the parameters from a <DDT0> block inside the
// <Model>; the flat layout (parameters directly in <Model>) is accepted too,
// as for the other burn models (model_block, ice/models/ModelSupport.h).
// Saved fields (Uintah's labels, reactant material): F, delF (detonating
// cells), detonating (1/0), burning (1 where T > ThresholdTemp in a
// deflagration cell), onSurface (burning area), surfaceTemp (T); sums
// totalMassBurned, totalHeatReleased.
// Departures from Uintah: the energy leaving with the burned mass is the
// particles' c_v T (as for the other burn models, docs/mpmice.md); the
// momentum is the particles' (not rho v_CC of the cell).
#include <algorithm>
#include <stdexcept>

#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/Ddt0.h"
#include "mpmice/Ddt1.h"
#include "mpmice/SimpleBurn.h"
#include "mpmice/SolidBurn.h"

namespace tephra {

namespace {

constexpr double kTinyCornerMass = 1e-12;  // Uintah's d_TINY_RHO in the surface test [kg] (as SolidBurn.cpp)
constexpr double kBurnThetaMin = 0.2;      // a material counts for the burning temperature above this volume fraction

class Ddt0Model final : public SolidBurnModel {
 public:
  Ddt0Model(const Ddt0Params& prm, std::size_t reactant, std::size_t product)
      : SolidBurnModel("DDT0", "DDT0", reactant, product, prm.enthalpy, prm.threshold_temperature), prm_(prm) {}

  std::string required_particle_history() const override { return prm_.crack_model ? "crackRad" : ""; }

  void initialize(const Grid& grid, const std::vector<IceMaterialFields>& mats) override {
    SolidBurnModel::initialize(grid, mats);
    for (CellScalars* f : {&F_, &delF_, &detonating_, &burning_, &ts_, &branch_, &cracked_, &crack_})
      *f = CellScalars(grid, 0);
  }

  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    for (CellScalars* f : {&F_, &delF_, &detonating_, &burning_, &ts_, &branch_, &cracked_}) f->fill(0.0);
    if (prm_.crack_model) {
      crack_.fill(0.0);
      if (!support().particle_history_max(reactant(), "crackRad", crack_))
        throw std::logic_error("DDT0: the reactant has no crackRad (checked when the deck is read)");
    }
    SolidBurnModel::compute_sources(in, out);
  }

  bool select_cell(const double wm[8], BurnCell& cell) const override {
    const IceModelInput& in = *cell.in;
    const std::size_t pi = cell.patch;
    const IntVec3& c = cell.c;
    const double p = in.press_equil_CC[pi](c);
    const bool cracked = prm_.crack_model && crack_[pi](c) > ddt1_crack_threshold(p);
    const bool surface = simple_burn_surface_cell(wm, kTinyCornerMass) || cracked;
    const Ddt0Branch br = ddt0_branch(prm_, p, in.mats[reactant()].vol_frac_CC[pi](c), surface);
    branch_[pi](c) = double(int(br));
    cracked_[pi](c) = cracked ? 1.0 : 0.0;
    cell.pressure = p;
    cell.surface = br == Ddt0Branch::Deflagrating;  // detonation needs no burning area
    if (br == Ddt0Branch::Deflagrating) {
      double T = 0;
      for (std::size_t m = 0; m < in.mats.size(); ++m) {
        const double Tm = in.mats[m].temp_CC[pi](c);
        if (in.mats[m].vol_frac_CC[pi](c) > kBurnThetaMin && Tm > prm_.threshold_temperature && Tm > T) T = Tm;
      }
      cell.temperature = T;
      ts_[pi](c) = T;
      if (T > prm_.threshold_temperature) burning_[pi](c) = 1.0;
    }
    return br != Ddt0Branch::None;
  }

  std::set<std::string> labels() const override {
    return {"totalMassBurned", "totalHeatReleased", "F", "delF", "detonating", "burning", "onSurface", "surfaceTemp"};
  }

  std::vector<ModelField> fields() const override {
    return {{"F", 0, &F_},           {"delF", 0, &delF_},          {"detonating", 0, &detonating_},
            {"burning", 0, &burning_}, {"onSurface", 0, &on_surface()}, {"surfaceTemp", 0, &ts_}};
  }

 protected:
  double burn_mass(const BurnCell& c) override {
    const IceModelInput& in = *c.in;
    const std::size_t pi = c.patch;
    // The cell's volume in the model's mass units: V, or r_c dx dy per radian
    // (axisymmetric, mpmice/AxisymmetricBurn.h). Uintah's crack term is a mass
    // per Cartesian cell per step; per radian the cell holds c.volume / V_cart
    // of it (r_c / dz: the ratio of the per-radian to the Cartesian cell mass).
    const double V = c.volume;
    const double crack_cells = V / in.grid.cell_volume();  // exactly 1 in Cartesian runs
    const double Mp = in.mats[product()].rho_CC[pi](c.c) * V;
    if (Ddt0Branch(int(branch_[pi](c.c))) == Ddt0Branch::Detonating) {
      const Ddt0Detonation d = ddt0_detonation(prm_, c.pressure, c.solid_mass, Mp, V, in.dt);
      F_[pi](c.c) = d.F;
      delF_[pi](c.c) = d.delF;
      detonating_[pi](c.c) = 1.0;
      return d.mass;
    }
    const double total = c.solid_mass + Mp;
    const double F = total > 0 ? Mp / total : 0.0;
    return std::min(ddt0_deflagration_mass(prm_, in.dt, c.area, c.pressure, c.temperature, F,
                                           cracked_[pi](c.c) > 0, crack_cells),
                    c.solid_mass);
  }

  double heat_of_reaction(std::size_t pi, const IntVec3& c) const override {
    return Ddt0Branch(int(branch_[pi](c))) == Ddt0Branch::Detonating ? prm_.E0 : prm_.enthalpy;
  }

 private:
  Ddt0Params prm_;
  // Per-cell state of the last step (mutable: select_cell, a const query of
  // the common machinery, records the branch and the diagnostics it decides).
  mutable CellScalars F_, delF_, detonating_, burning_, ts_, branch_, cracked_, crack_;
};

}  // namespace

IceModelP make_ddt0(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "DDT0"), "DDT0");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  check_reactant_product(mp, setup, r, p, "DDT0");
  Ddt0Params prm;
  prm.jwl_pressure = mp.positive("ThresholdPressureJWL");
  prm.G = mp.positive("G");
  prm.b = mp.number("b");
  prm.E0 = mp.number("E0");
  prm.volume_fraction = mp.number("ThresholdVolFrac", 0.01);
  prm.enthalpy = mp.number("Enthalpy");
  prm.burn_coeff = mp.number("BurnCoeff");
  prm.ref_pressure = mp.positive("refPressure");
  prm.threshold_temperature = mp.number("ThresholdTemp");
  prm.sb_pressure = mp.number("ThresholdPressureSB");
  prm.crack_model = mp.flag("useCrackModel", false);
  if (prm.crack_model) {
    prm.g_crack = mp.number("Gcrack");
    prm.n_crack = mp.number("nCrack");
    mp.number("CrackVolThreshold", 1e-14);  // read, no effect (mpmice/Ddt0.h)
  }
  mp.finish();
  prm.rho0 = setup.materials[r].sources.empty() ? 0.0 : setup.materials[r].sources[0].density;
  return std::make_shared<Ddt0Model>(prm, r, p);
}

}  // namespace tephra
