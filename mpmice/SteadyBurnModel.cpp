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
//   * dm = dt A m_WSB(p, T0, v_s), at most the cell's solid mass less
//     V x 1e-12 kg/m^3 (Uintah's MIN_MASS_IN_A_CELL = V d_TINY_RHO; the
//     value 1e-12 is assumed here, as in Simple_Burn);
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

namespace tephra {

namespace {

constexpr double kMinCellDensity = 1e-12;  // [kg/m^3] Uintah's d_TINY_RHO in MIN_MASS_IN_A_CELL (assumed)

class SteadyBurnModel final : public SolidBurnModel {
 public:
  SteadyBurnModel(const WsbParams& wsb, double ignition_temp, double threshold_pressure, double boundary_particles,
                  std::size_t reactant, std::size_t product)
      : SolidBurnModel("Steady_Burn", "SteadyBurn", reactant, product, wsb.Qc + wsb.Qg, ignition_temp),
        wsb_(wsb),
        ignition_(ignition_temp),
        threshold_p_(threshold_pressure),
        bp_(boundary_particles) {}

  bool select_cell(const double wm[8], BurnCell& cell) const override {
    double mx = 1e-100, mn = 1e100;
    for (int n = 0; n < 8; ++n) mx = std::max(mx, wm[n]), mn = std::min(mn, wm[n]);
    if (!(mn / mx < 0.7 && cell.particles > 0)) return false;
    const IceModelInput& in = *cell.in;
    const std::size_t pi = cell.patch, r = reactant(), q = product();
    bool ignited = false;
    double max_r = -1, max_p = -1;
    for (int k = -1; k <= 1; ++k)
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
          const IntVec3 n = cell.c + IntVec3(i, j, k);
          if (in.mats[r].vol_frac_CC[pi](n) > max_r) {
            max_r = in.mats[r].vol_frac_CC[pi](n);
            cell.temperature = in.mats[r].temp_CC[pi](n);
          }
          if (in.mats[q].vol_frac_CC[pi](n) > max_p) {
            max_p = in.mats[q].vol_frac_CC[pi](n);
            cell.pressure = in.press_equil_CC[pi](n);
          }
          if (!ignited && particles_in(pi, n) <= bp_)
            for (std::size_t m = 0; m < in.mats.size(); ++m)
              if (in.mats[m].vol_frac_CC[pi](n) > 0.2 && in.mats[m].temp_CC[pi](n) > ignition_) {
                ignited = true;
                break;
              }
        }
    return ignited && cell.pressure >= threshold_p_;
  }

 protected:
  double burn_mass(const BurnCell& c) override {
    const double vs = c.in->mats[reactant()].sp_vol_CC[c.patch](c.c);
    const WsbState s = wsb_burn_rate(wsb_, c.pressure, c.temperature, vs);
    const double min_mass = c.in->grid.cell_volume() * kMinCellDensity;
    return std::min(c.in->dt * c.area * s.mass_flux, std::max(0.0, c.solid_mass - min_mass));
  }

 private:
  WsbParams wsb_;
  double ignition_, threshold_p_, bp_;
};

}  // namespace

IceModelP make_steady_burn(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "Steady_Burn"), "Steady_Burn");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  check_reactant_product(mp, setup, r, p, "Steady_Burn");
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
  const double bp = mp.number("BoundaryParticles");
  const double threshold_p = mp.number("ThresholdPressure");
  const double ignition = mp.positive("IgnitionTemp");
  mp.finish();
  return std::make_shared<SteadyBurnModel>(w, ignition, threshold_p, bp, r, p);
}

}  // namespace tephra
