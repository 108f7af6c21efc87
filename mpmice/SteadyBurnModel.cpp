// <Model type="Steady_Burn"> in MPMICE (mpmice/SolidBurn.h): the WSB burn
// rate (mpmice/SteadyBurn.h) on the cells Uintah's Steady_Burn selects
// (HEChem/Steady_Burn.cc, read for the rule):
//   * a cell burns if its corner values w_n m_n satisfy min/max < 0.7, it
//     holds particles of the reactant, and some cell of its 3x3x3
//     neighbourhood with at most <BoundaryParticles> reactant particles has a
//     material with theta > 0.2 hotter than <IgnitionTemp>;
//   * T0 = the reactant temperature of the neighbour with the largest
//     reactant volume fraction, p = the equilibration pressure of the
//     neighbour with the largest product volume fraction; it burns if
//     p >= <ThresholdPressure>;
//   * dm = dt A m_WSB(p, T0, v_s), at most wsb_burnable_mass (the cell's
//     solid mass less V x 1e-12 kg/m^3);
//   * heat released to the product: (Qc + Qg) dm.
// Departure: the energy leaving with the burned mass is c_v T of the solid
// (its MPMICE specific heat, as in the solid's own cell energy), not
// SpecificHeatBoth x T as in Uintah, so the solid's cell temperature is not
// changed by the removal.
#include <algorithm>

#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/SolidBurn.h"
#include "mpmice/SteadyBurn.h"
#include "mpmice/WsbSurfaceCell.h"

namespace tephra {

namespace {

class SteadyBurnModel final : public SolidBurnModel {
 public:
  SteadyBurnModel(const WsbParams& wsb, const WsbIgnition& ignition, double threshold_pressure, std::size_t reactant,
                  std::size_t product)
      : SolidBurnModel("Steady_Burn", "SteadyBurn", reactant, product, wsb.Qc + wsb.Qg, ignition.ignition_temp),
        wsb_(wsb),
        ignition_(ignition),
        threshold_p_(threshold_pressure) {}

  bool select_cell(const double wm[8], BurnCell& cell) const override {
    const WsbSurface s = wsb_surface_cell(*this, ignition_, wm, cell);
    cell.temperature = s.T0;
    cell.pressure = s.pressure;
    return s.ignited && s.pressure >= threshold_p_;
  }

 protected:
  double burn_mass(const BurnCell& c) override {
    const double vs = c.in->mats[reactant()].sp_vol_CC[c.patch](c.c);
    const WsbState s = wsb_burn_rate(wsb_, c.pressure, c.temperature, vs);
    return std::min(c.in->dt * c.area * s.mass_flux, wsb_burnable_mass(c));
  }

 private:
  WsbParams wsb_;
  WsbIgnition ignition_;
  double threshold_p_;
};

}  // namespace

WsbParams read_wsb_params(ModelParams& mp) {
  WsbParams w;
  w.R = mp.positive("IdealGasConst");
  w.Ac = mp.positive("PreExpCondPh");
  w.Ec = mp.positive("ActEnergyCondPh");
  w.Bg = mp.positive("PreExpGasPh");
  w.Qc = mp.number("CondPhaseHeat");
  w.Qg = mp.number("GasPhaseHeat");
  w.kg = mp.positive("HeatConductGasPh");
  w.kc = mp.positive("HeatConductCondPh");
  w.Cp = mp.positive("SpecificHeatBoth");
  w.W = mp.positive("MoleWeightGasPh");
  return w;
}

WsbIgnition read_wsb_ignition(ModelParams& mp) {
  WsbIgnition ig;
  ig.boundary_particles = mp.number("BoundaryParticles");
  ig.ignition_temp = mp.positive("IgnitionTemp");
  return ig;
}

IceModelP make_steady_burn(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "Steady_Burn"), "Steady_Burn");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  check_reactant_product(mp, setup, r, p, "Steady_Burn");
  const WsbParams w = read_wsb_params(mp);
  const WsbIgnition ig = read_wsb_ignition(mp);
  const double threshold_p = mp.number("ThresholdPressure");
  mp.finish();
  return std::make_shared<SteadyBurnModel>(w, ig, threshold_p, r, p);
}

}  // namespace tephra
