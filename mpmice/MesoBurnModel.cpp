// <Model type="MesoBurn"> in MPMICE (mpmice/SolidBurn.h; Uintah's
// HEChem/MesoBurn.cc, read for the rules): Steady_Burn's WSB surface burning
// ignited by per-particle induction clocks (mpmice/MesoBurn.h).
//   * every step, before the cells: each reactant particle's clock advances
//     (start-of-step T_p); a cell's induced / inducedMass / inductionTime are
//     the count / 8 (<resolution>), the mass and the smallest tau of its
//     induced particles;
//   * a cell burns when it is a WSB surface cell (min/max corner mass < 0.7,
//     particles in it; mpmice/WsbSurfaceCell.h), it holds induced particles,
//     some 3x3x3 neighbour with at most <BoundaryParticles> reactant
//     particles has a material hotter than 470 K (any volume fraction), and
//     the gas pressure p (neighbour with the largest product volume fraction)
//     is >= <ThresholdPressure>;
//   * dm = dt A m_WSB(p, T0, v_s) (T0 from the neighbour with the largest
//     reactant volume fraction, A the corner-mass area), at most the cell's
//     inducedMass less V x 1e-12 kg/m^3 (Uintah's cap: only induced mass
//     burns), and at most the solid's cell mass; heat released (Qc + Qg) dm.
// The clocks live in the model, keyed by p.particleID (Uintah: particle
// variables). Saved fields (Uintah's labels): MesoBurn.BurningCell,
// MesoBurn.SurfTemp, MesoBurn.numPPC, MesoBurn.inductionTime,
// MesoBurn.induced, MesoBurn.inducedMass; sums totalMassBurned,
// totalHeatReleased, totalSurfaceArea (here the summed burning area; Uintah
// adds the surface temperatures into it).
// Not implemented (MissingFeature, exit 3): MesoBurn on MPI ranks (the clocks
// do not migrate with the particles). The clocks are in the checkpoint
// (save_arrays). In axisymmetric MPMICE the masses, the area (mpmice/
// AxisymmetricBurn.h) and the minimum cell mass are per radian. <AfterMelting> is read; Uintah only
// checks with it that the reactant is elastic_plastic_hp and does not use it
// in the rate: no effect here.
#include <algorithm>
#include <unordered_map>

#include "core/base/Errors.h"
#include "core/io/StateArchive.h"
#include "core/deck/DeckNode.h"
#include "core/grid/Loop.h"
#include "core/parallel/Ranks.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/MesoBurn.h"
#include "mpmice/SolidBurn.h"
#include "mpmice/SteadyBurn.h"
#include "mpmice/WsbSurfaceCell.h"

namespace tephra {

namespace {

struct MesoBurnParams {
  WsbParams wsb;
  MesoInduction induction;
  double boundary_particles = 0, threshold_pressure = 0;
  double resolution = 8;
};

class MesoBurnModel final : public SolidBurnModel {
 public:
  MesoBurnModel(const MesoBurnParams& prm, std::size_t reactant, std::size_t product)
      : SolidBurnModel("MesoBurn", "MesoBurn", reactant, product, prm.wsb.Qc + prm.wsb.Qg, 0.0), prm_(prm) {}

  void initialize(const Grid& grid, const std::vector<IceMaterialFields>& mats) override {
    SolidBurnModel::initialize(grid, mats);
    for (CellScalars* f : {&burning_, &ts_, &induced_, &induced_mass_, &induction_time_}) *f = CellScalars(grid, 0);
    area_sums_.reset(grid, 1);
  }

  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    advance_clocks(in);
    for (CellScalars* f : {&burning_, &ts_}) f->fill(0.0);
    SolidBurnModel::compute_sources(in, out);
    area_sums_.zero();
    for (std::size_t pi = 0; pi < in.grid.patches.size(); ++pi)
      for_each_cell_serial(in.grid.patches[pi].cells(),
                           [&](int i, int j, int k) { area_sums_.at(pi, 0) += on_surface()[pi](i, j, k); });
  }

  bool select_cell(const double wm[8], BurnCell& cell) const override {
    WsbIgnition ig;  // wsb_surface_cell's own ignition test is not MesoBurn's: only T0, p and the surface are used
    ig.ignition_temp = kMesoInductionTemperature;
    ig.boundary_particles = prm_.boundary_particles;
    const WsbSurface s = wsb_surface_cell(*this, ig, wm, cell);
    const IceModelInput& in = *cell.in;
    const std::size_t pi = cell.patch;
    bool burning = false;
    if (s.on_surface && induced_[pi](cell.c) > 0)
      for (int k = -1; k <= 1 && !burning; ++k)
        for (int j = -1; j <= 1 && !burning; ++j)
          for (int i = -1; i <= 1 && !burning; ++i) {
            const IntVec3 n = cell.c + IntVec3(i, j, k);
            if (particles_in(pi, n) > prm_.boundary_particles) continue;
            for (std::size_t m = 0; m < in.mats.size(); ++m)
              if (in.mats[m].temp_CC[pi](n) > kMesoInductionTemperature) burning = true;
          }
    cell.temperature = s.T0;
    cell.pressure = s.pressure;
    if (!(burning && s.pressure >= prm_.threshold_pressure)) return false;
    burning_[pi](cell.c) = 1.0;
    return true;
  }

  std::set<std::string> labels() const override {
    return {"totalMassBurned",      "totalHeatReleased",     "totalSurfaceArea", "MesoBurn.BurningCell",
            "MesoBurn.SurfTemp",    "MesoBurn.numPPC",       "MesoBurn.inductionTime", "MesoBurn.induced",
            "MesoBurn.inducedMass"};
  }
  std::vector<ModelField> fields() const override {
    return {{"MesoBurn.BurningCell", 0, &burning_},        {"MesoBurn.SurfTemp", 0, &ts_},
            {"MesoBurn.numPPC", 0, &particles_per_cell_field()}, {"MesoBurn.inductionTime", 0, &induction_time_},
            {"MesoBurn.induced", 0, &induced_},            {"MesoBurn.inducedMass", 0, &induced_mass_}};
  }
  std::vector<ModelSum> patch_sums() const override {
    return {{"totalMassBurned", &burn_sums(), 0, 1},
            {"totalHeatReleased", &burn_sums(), 1, 1},
            {"totalSurfaceArea", &area_sums_, 0, 1}};
  }
  // The clocks in the checkpoint: ids (ascending), tau and time_induced.
  void save_arrays(StateArchive& a, const std::string& prefix) const override {
    std::vector<long long> ids;
    ids.reserve(clocks_.size());
    for (const auto& [id, clock] : clocks_) ids.push_back(id);
    std::sort(ids.begin(), ids.end());
    std::vector<double> tau(ids.size()), t(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const MesoClock& c = clocks_.at(ids[i]);
      tau[i] = c.tau;
      t[i] = c.time_induced;
    }
    a.put(prefix + "MesoBurn.clock_id", std::move(ids));
    a.put(prefix + "MesoBurn.clock_tau", std::move(tau));
    a.put(prefix + "MesoBurn.clock_time", std::move(t));
  }
  void load_arrays(const StateArchive& a, const std::string& prefix) override {
    const std::vector<long long>& ids = a.ints(prefix + "MesoBurn.clock_id");
    const std::vector<double>& tau = a.doubles(prefix + "MesoBurn.clock_tau");
    const std::vector<double>& t = a.doubles(prefix + "MesoBurn.clock_time");
    if (tau.size() != ids.size() || t.size() != ids.size())
      throw RuntimeFailure("checkpoint: MesoBurn clock arrays of different lengths");
    clocks_.clear();
    for (std::size_t i = 0; i < ids.size(); ++i) clocks_[ids[i]] = MesoClock{tau[i], t[i]};
  }

 protected:
  double burn_mass(const BurnCell& c) override {
    const IceModelInput& in = *c.in;
    const double vs = in.mats[reactant()].sp_vol_CC[c.patch](c.c);
    const WsbState w = wsb_burn_rate(prm_.wsb, c.pressure, c.temperature, vs);
    ts_[c.patch](c.c) = w.surface_temperature;
    const double min_mass = c.volume * 1e-12;  // Uintah's MIN_MASS_IN_A_CELL (WsbSurfaceCell.h); per radian when axisymmetric
    const double dm = in.dt * c.area * w.mass_flux;
    const double induced = induced_mass_[c.patch](c.c);
    return std::max(0.0, dm + min_mass > induced ? induced - min_mass : dm);
  }

 private:
  void advance_clocks(const IceModelInput& in) {
    for (CellScalars* f : {&induced_, &induced_mass_}) f->fill(0.0);
    induction_time_.fill(kMesoInitialInductionTime);
    support().reactant_particles(reactant(), particles_);
    std::unordered_map<long long, MesoClock> next;
    next.reserve(particles_.size());
    for (const BurnParticle& p : particles_) {
      MesoClock clock;
      if (auto it = clocks_.find(p.id); it != clocks_.end()) clock = it->second;
      if (meso_advance_clock(clock, prm_.induction, p.temperature, in.dt)) {
        double& t = induction_time_[p.patch](p.cell);
        t = std::min(t, clock.tau);
        induced_[p.patch](p.cell) += 1.0 / prm_.resolution;
        induced_mass_[p.patch](p.cell) += p.mass;
      }
      next[p.id] = clock;
    }
    clocks_.swap(next);  // burned-out (deleted) particles drop out
  }

  MesoBurnParams prm_;
  std::unordered_map<long long, MesoClock> clocks_;
  std::vector<BurnParticle> particles_;
  CellScalars induced_, induced_mass_, induction_time_;
  mutable CellScalars burning_, ts_;  // written by select_cell / burn_mass
  PatchSums area_sums_;
};

}  // namespace

IceModelP make_meso_burn(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model, "MesoBurn");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  check_reactant_product(mp, setup, r, p, "MesoBurn");
  if (launched_rank_count() > 1)
    model.missing_feature("MesoBurn on MPI ranks (the particles' induction clocks do not migrate)");
  MesoBurnParams prm;
  prm.wsb = read_wsb_params(mp);
  prm.boundary_particles = mp.number("BoundaryParticles");
  prm.threshold_pressure = mp.number("ThresholdPressure");
  prm.induction.Qc = prm.wsb.Qc;
  prm.induction.Ta = mp.positive("Ta");
  prm.induction.k = mp.positive("k");
  prm.induction.Cv = mp.positive("Cv");
  mp.flag("AfterMelting", false);  // read, no effect (header)
  prm.resolution = mp.number("resolution", 8);
  if (!(prm.resolution > 0)) model.require_child("resolution").fail("MesoBurn <resolution> must be > 0");
  mp.finish();
  return std::make_shared<MesoBurnModel>(prm, r, p);
}

}  // namespace tephra
