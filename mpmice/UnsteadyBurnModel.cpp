// <Model type="Unsteady_Burn"> in MPMICE (mpmice/SolidBurn.h): the unsteady
// WSB rate (mpmice/UnsteadyBurn.h) on the cells Steady_Burn selects
// (mpmice/WsbSurfaceCell.h: an ignited surface cell whose gas pressure is at
// least <ThresholdPressure>), as Uintah's HEChem/Unsteady_Burn.cc (read for
// the rule):
//   * a cell that burned in the previous step continues from its own
//     (Ts, beta); a cell starting to burn takes them from the neighbour of
//     its 3x3x3 block that has burned the most steps (largest
//     UnsteadyBurn.BurningCell), or starts fresh (steady rate) if none has;
//   * dm = dt A m, at most wsb_burnable_mass; heat (Qc + Qg) dm.
// Saved fields: UnsteadyBurn.BurningCell (the number of consecutive steps
// the cell has burned, as Uintah's counter), UnsteadyBurn.SurfTemp (Ts),
// UnsteadyBurn.SurfTempGrad (beta), UnsteadyBurn.onSurface (area).
// Departure: Uintah carries Ts and beta on the reactant's particles
// (UnsteadyBurn.PartSurfTemp/PartSurfTempGrad) and rebuilds the cell values
// from the particles in the cell each step; here they stay on the cell (the
// burning surface moves through the cells by burning; a particle that moves
// into a cell does not bring its history: that cell restarts from its
// longest-burning neighbour). The particle labels are not provided.
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/SolidBurn.h"
#include "mpmice/UnsteadyBurn.h"
#include "mpmice/WsbSurfaceCell.h"

namespace tephra {

namespace {

class UnsteadyBurnModel final : public SolidBurnModel {
 public:
  UnsteadyBurnModel(const UnsteadyBurnParams& prm, const WsbIgnition& ignition, double threshold_pressure,
                    std::size_t reactant, std::size_t product)
      : SolidBurnModel("Unsteady_Burn", "UnsteadyBurn", reactant, product, prm.wsb.Qc + prm.wsb.Qg,
                       ignition.ignition_temp),
        prm_(prm),
        ignition_(ignition),
        threshold_p_(threshold_pressure) {}

  void initialize(const Grid& grid, const std::vector<IceMaterialFields>& mats) override {
    SolidBurnModel::initialize(grid, mats);
    for (CellScalars* f : {&ts_, &beta_, &count_, &old_ts_, &old_beta_, &old_count_}) *f = CellScalars(grid, 0);
  }

  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    std::swap(ts_, old_ts_);
    std::swap(beta_, old_beta_);
    std::swap(count_, old_count_);
    for (CellScalars* f : {&ts_, &beta_, &count_}) f->fill(0.0);
    SolidBurnModel::compute_sources(in, out);
  }

  bool select_cell(const double wm[8], BurnCell& cell) const override {
    const WsbSurface s = wsb_surface_cell(*this, ignition_, wm, cell);
    cell.temperature = s.T0;
    cell.pressure = s.pressure;
    return s.ignited && s.pressure >= threshold_p_;
  }

  std::set<std::string> labels() const override {
    std::set<std::string> l = SolidBurnModel::labels();
    l.insert({"UnsteadyBurn.SurfTemp", "UnsteadyBurn.SurfTempGrad"});
    return l;
  }

  std::vector<ModelField> fields() const override {
    return {{"UnsteadyBurn.onSurface", 0, &on_surface()},
            {"UnsteadyBurn.BurningCell", 0, &count_},
            {"UnsteadyBurn.SurfTemp", 0, &ts_},
            {"UnsteadyBurn.SurfTempGrad", 0, &beta_}};
  }

  std::vector<std::pair<std::string, CellScalars*>> state_fields() override {
    return {{"UnsteadyBurn.SurfTemp", &ts_}, {"UnsteadyBurn.SurfTempGrad", &beta_}, {"UnsteadyBurn.BurningCell", &count_}};
  }

 protected:
  double burn_mass(const BurnCell& c) override {
    const Grid& g = c.in->grid;
    UnsteadyBurnState st;  // fresh
    if (old_count_[c.patch](c.c) > 0) {
      st.Ts = old_ts_[c.patch](c.c);
      st.beta = old_beta_[c.patch](c.c);
    } else {
      double most = 0;
      for (int k = -1; k <= 1; ++k)
        for (int j = -1; j <= 1; ++j)
          for (int i = -1; i <= 1; ++i) {
            const IntVec3 n = c.c + IntVec3(i, j, k);
            const int owner = g.patch_owning_cell(n);  // the neighbour's own patch (extra cells: -1)
            if (owner < 0) continue;
            const double burned = old_count_[std::size_t(owner)](n);
            if (burned > most) {
              most = burned;
              st.Ts = old_ts_[std::size_t(owner)](n);
              st.beta = old_beta_[std::size_t(owner)](n);
            }
          }
    }
    const double vs = c.in->mats[reactant()].sp_vol_CC[c.patch](c.c);
    UnsteadyBurnRate rate;
    try {
      rate = unsteady_burn_rate(prm_, c.pressure, c.temperature, vs, c.in->dt, st);
    } catch (const NumericalFailure& e) {
      std::ostringstream os;
      os << "Unsteady_Burn in cell (" << c.c[0] << "," << c.c[1] << "," << c.c[2] << ") at step " << c.in->step
         << ": " << e.what();
      throw NumericalFailure(os.str());
    }
    ts_[c.patch](c.c) = st.Ts;
    beta_[c.patch](c.c) = st.beta;
    count_[c.patch](c.c) = old_count_[c.patch](c.c) + 1;
    return std::min(c.in->dt * c.area * rate.mass_flux, wsb_burnable_mass(c));
  }

 private:
  UnsteadyBurnParams prm_;
  WsbIgnition ignition_;
  double threshold_p_;
  CellScalars ts_, beta_, count_, old_ts_, old_beta_, old_count_;
};

}  // namespace

IceModelP make_unsteady_burn(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "Unsteady_Burn"), "Unsteady_Burn");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  check_reactant_product(mp, setup, r, p, "Unsteady_Burn");
  UnsteadyBurnParams prm;
  prm.wsb = read_wsb_params(mp);
  const WsbIgnition ig = read_wsb_ignition(mp);
  prm.Bm = mp.positive("BurnrateModCoef");
  prm.Nc = mp.positive("CondUnsteadyCoef");
  prm.Ng = mp.positive("GasUnsteadyCoef");
  const double threshold_p = mp.number("ThresholdPressure");
  mp.finish();
  return std::make_shared<UnsteadyBurnModel>(prm, ig, threshold_p, r, p);
}

}  // namespace tephra
