// <Model type="DDT1"> in MPMICE (mpmice/SolidBurn.h): the branch of each
// cell and its burned mass from mpmice/Ddt1.h (JWL++ detonation above
// <ThresholdPressureJWL>, WSB surface burning and, with <useCrackModel>,
// crack burning between <ThresholdPressureSB> and it), taken from the
// particles by the common burn machinery (ParticleBurn.cpp), so the
// particles lose exactly what the product gains in both branches.
//
// Saved fields (Vaango's labels, reactant material): F, delF (detonating
// cells), detonating (1/0), detLocalTo (1 where a neighbour detonates),
// burning and BurningCriteria (Vaango's codes: 2 conductive, 3 convective),
// onSurface (burning area), surfaceTemp (WSB Ts), crackedEnough,
// SteadyBurn.numPPC; sums totalMassBurned, totalHeatReleased.
// <useInductionTime> (Son's flame-spread induction time, mpmice/Ddt1.h):
// the deflagration branch waits for the cell's induction time; fields
// inductionTime, countTime, burning = 1 while warming up; checkpointed.
// Not implemented (MissingFeature, exit 3): <burnMaterial> other than
// <toMaterial>, <adjust_IO_intervals>. <rho0> (present in BurnRate.ups) is accepted and
// unused, as in Vaango (the 20 % cap uses the MPM material's density).
// Departures from Vaango: the conductive cap uses the solid's cell mass
// (Vaango compares with rho_r theta_r V, which is not the cell's mass); the
// energy leaving with the burned mass is the particles' c_v T (as for the
// other burn models, docs/mpmice.md).
#include <algorithm>
#include <stdexcept>

#include "core/deck/DeckNode.h"
#include "core/grid/Loop.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/Ddt1.h"
#include "mpmice/SimpleBurn.h"
#include "mpmice/SolidBurn.h"
#include "mpmice/SteadyBurn.h"
#include "mpmice/WsbSurfaceCell.h"

namespace tephra {

namespace {

struct Ddt1Params {
  WsbParams wsb;
  bool induction = false;          // <useInductionTime>
  Ddt1InductionParams induction_prm;
  double first_induction = 0;      // Uintah's sentinel of the first step: delt_init + 1e-20 [s]
  WsbIgnition ignition;
  Ddt1Thresholds thresholds;
  double G = 0, b = 0, E0 = 0;  // JWL++ rate constant [1/(s Pa^b)], exponent, heat of detonation [J/kg]
  double rho0 = 0;              // the MPM reactant's density [kg/m^3]
};

class Ddt1Model final : public SolidBurnModel {
 public:
  Ddt1Model(const Ddt1Params& prm, std::size_t reactant, std::size_t product)
      : SolidBurnModel("DDT1", "DDT1", reactant, product, prm.wsb.Qc + prm.wsb.Qg, prm.ignition.ignition_temp),
        prm_(prm) {}

  std::string required_particle_history() const override { return prm_.thresholds.crack_model ? "crackRad" : ""; }

  void initialize(const Grid& grid, const std::vector<IceMaterialFields>& mats) override {
    SolidBurnModel::initialize(grid, mats);
    for (CellScalars* f : {&F_, &delF_, &detonating_, &det_local_, &branch_, &ts_, &cracked_, &crack_, &burning_code_,
                           &induction_, &count_, &induction_old_, &count_old_, &warming_})
      *f = CellScalars(grid, 0);
    burning_old_ = CellScalars(grid, 1);  // read at the 3x3x3 neighbours (crack paths)
    burning_old_.fill(0.0);
    induction_.fill(prm_.first_induction);  // Uintah's initialize: every cell at the sentinel
  }

  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    for (CellScalars* f : {&F_, &delF_, &detonating_, &det_local_, &branch_, &ts_, &cracked_}) f->fill(0.0);
    if (prm_.induction) {  // last step's values become "old"; this step's start at 0 (Uintah's initialize(0.))
      std::swap(induction_old_, induction_);
      std::swap(count_old_, count_);
      for (std::size_t pi = 0; pi < in.grid.patches.size(); ++pi)
        for_each_cell_serial(in.grid.patches[pi].cells_with_extra(),
                             [&](int i, int j, int k) { burning_old_[pi](i, j, k) = burning_code_[pi](i, j, k); });
      if (prm_.thresholds.crack_model) support().exchange_cell_halo(burning_old_);  // neighbours on other patches
      induction_.fill(0.0);
      count_.fill(0.0);
    }
    if (prm_.thresholds.crack_model) {
      crack_.fill(0.0);
      if (!support().particle_history_max(reactant(), "crackRad", crack_))
        throw std::logic_error("DDT1: the reactant has no crackRad (checked when the deck is read)");
    }
    SolidBurnModel::compute_sources(in, out);
    // "burning": Vaango's code of the surface-burning cells (2 conductive, 3 convective).
    burning_code_.fill(0.0);
    for (std::size_t pi = 0; pi < in.grid.patches.size(); ++pi)
      for_each_cell_serial(in.grid.patches[pi].cells(), [&](int i, int j, int k) {
        const double b = branch_[pi](i, j, k);
        if (b == double(int(Ddt1Branch::Conductive)) || b == double(int(Ddt1Branch::Convective)))
          burning_code_[pi](i, j, k) = b;
        else if (warming_[pi](i, j, k) > 0)
          burning_code_[pi](i, j, k) = kDdt1WarmingUp;
      });
  }

  bool select_cell(const double wm[8], BurnCell& cell) const override {
    const IceModelInput& in = *cell.in;
    const std::size_t pi = cell.patch;
    const IntVec3& c = cell.c;
    const WsbSurface s = wsb_surface_cell(*this, prm_.ignition, wm, cell);
    Ddt1CellState st;
    st.p = in.press_equil_CC[pi](c);
    st.reactant_fraction = in.mats[reactant()].vol_frac_CC[pi](c);
    for (int k = -1; k <= 1; ++k)
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
          if (in.press_equil_CC[pi](c + IntVec3(i, j, k)) > prm_.thresholds.jwl_pressure) st.detonation_next = true;
    st.ignited_surface = s.ignited;
    st.gas_pressure = s.pressure;
    st.hot_neighbour = s.hot_neighbour;
    if (prm_.thresholds.crack_model) st.cracked = crack_[pi](c) > ddt1_crack_threshold(st.p);
    Ddt1Branch br = ddt1_branch(prm_.thresholds, st);
    warming_[pi](c) = 0.0;
    if (prm_.induction && st.reactant_fraction > 1e-10 && st.p < prm_.thresholds.jwl_pressure &&
        st.p > prm_.thresholds.sb_pressure)
      br = induction_branch(wm, cell, s, st);
    if (st.reactant_fraction > 1e-10 && st.p < prm_.thresholds.jwl_pressure && st.p > prm_.thresholds.sb_pressure)
      det_local_[pi](c) = st.detonation_next ? 1.0 : 0.0;
    cracked_[pi](c) = st.cracked ? 1.0 : 0.0;
    branch_[pi](c) = double(int(br));
    cell.temperature = s.T0;
    cell.pressure = br == Ddt1Branch::Detonating ? st.p : s.pressure;
    cell.surface = br == Ddt1Branch::Conductive;  // the others need no corner-mass area
    return br != Ddt1Branch::None;
  }

  // Uintah's DDT1 burn logic with <useInductionTime> for a cell in the
  // deflagration window (mpmice/Ddt1.h): updates this step's induction and
  // exposure times of the cell and returns its branch (None while warming up).
  Ddt1Branch induction_branch(const double wm[8], const BurnCell& cell, const WsbSurface& s,
                              const Ddt1CellState& st) const {
    const IceModelInput& in = *cell.in;
    const std::size_t pi = cell.patch;
    const IntVec3& c = cell.c;
    const Vec3 dx = in.grid.dx;
    const double IC = prm_.induction_prm.IC;
    const bool crack = prm_.thresholds.crack_model && st.cracked;
    const auto burned = [](double code) { return code == kDdt1Conductive || code == kDdt1Convective; };
    double mx = 1e-100, mn = 1e100;  // Uintah's d_SMALL_NUM bounds (WsbSurfaceCell.cpp)
    for (int n = 0; n < 8; ++n) mx = std::max(mx, wm[n]), mn = std::min(mn, wm[n]);
    const double min_over_max = mn / mx;
    double ignited_from = 0;  // NOTDEFINED
    bool exceeded = false, calculate = false;
    double A = 12345e100;  // Uintah's "unset" values
    if (burned(burning_old_[pi](c))) {  // burning since last step: carry on
      induction_[pi](c) = induction_old_[pi](c);
      count_[pi](c) = count_old_[pi](c) + in.dt;
      exceeded = true;
      ignited_from = burning_old_[pi](c);
    } else if (min_over_max < 0.7 && cell.particles > 0) {  // on the surface
      const Vec3 normal = simple_burn_surface_normal(wm, dx);
      double cos_gas_max = -1, cos_cell_max = -1, theta_gas = 0, theta_cell = 0;
      double A_cell = 12345e100, A_gas = 12350e100, from_hot_cell = 0;
      // Uintah's loop order (x outermost, z innermost; materials inside):
      // the last assignment of theta wins.
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
          for (int k = -1; k <= 1; ++k) {
            const IntVec3 n = c + IntVec3(i, j, k);
            const Vec3 h(i * dx[0], j * dx[1], k * dx[2]);
            if (s.ignited) {  // hot gas next to the surface
              calculate = true;
              for (std::size_t m = 0; m < in.mats.size(); ++m) {
                if (in.mats[m].vol_frac_CC[pi](c) > 0.2 && in.mats[m].temp_CC[pi](c) > prm_.ignition.ignition_temp) {
                  theta_gas = 0.0;
                } else if (in.mats[m].vol_frac_CC[pi](n) > 0.2 &&
                           in.mats[m].temp_CC[pi](n) > prm_.ignition.ignition_temp) {
                  double cs = 0;
                  const double th = ddt1_induction_angle(normal, h, cs);
                  if (cs > cos_gas_max) cos_gas_max = cs, theta_gas = th;
                }
                A_gas = ddt1_induction_factor(IC, theta_gas);
              }
            }
            if (crack && burned(burning_old_[pi](n))) {  // a burning neighbour, cracked cell
              calculate = true;
              for (std::size_t m = 0; m < in.mats.size(); ++m)
                if (in.mats[m].temp_CC[pi](n) > prm_.ignition.ignition_temp) {
                  double cs = 0;
                  const double th = ddt1_induction_angle(normal, h, cs);
                  if (cs > cos_cell_max) cos_cell_max = cs, theta_cell = th, from_hot_cell = burning_old_[pi](n);
                }
              A_cell = ddt1_induction_factor(IC, theta_cell);
            }
          }
      if (calculate) {
        A = std::min(A_cell, A_gas);
        ignited_from = A == A_gas ? kDdt1Conductive : from_hot_cell;
      }
    } else if (prm_.thresholds.crack_model && min_over_max >= 0.7) {  // inside the solid: crack burning
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
          for (int k = -1; k <= 1; ++k)
            if (crack && burned(burning_old_[pi](c + IntVec3(i, j, k)))) {
              calculate = true;
              A = IC;
              ignited_from = kDdt1Convective;
            }
    }
    if (calculate) {
      const double tau_new = ddt1_induction_time(prm_.induction_prm, (dx[0] + dx[1] + dx[2]) / 3, A, s.pressure);
      double& tau = induction_[pi](c);
      tau = tau_new;
      if (induction_old_[pi](c) != prm_.first_induction) tau = 0.2 * tau_new + 0.8 * induction_old_[pi](c);
      count_[pi](c) = std::max(count_[pi](c), count_old_[pi](c) + in.dt);
      if (count_[pi](c) >= tau) exceeded = true;
    }
    if (!st.detonation_next && s.ignited && s.pressure >= prm_.thresholds.sb_pressure && exceeded &&
        ignited_from == kDdt1Conductive)
      return Ddt1Branch::Conductive;
    if (!st.detonation_next && crack && st.hot_neighbour && exceeded && ignited_from == kDdt1Convective)
      return Ddt1Branch::Convective;
    if (count_[pi](c) < induction_[pi](c) && count_[pi](c) > 0) warming_[pi](c) = 1.0;
    return Ddt1Branch::None;
  }

  std::set<std::string> labels() const override {
    return {"totalMassBurned", "totalHeatReleased", "F",           "delF",          "detonating",
            "detLocalTo",      "burning",           "BurningCriteria", "onSurface", "surfaceTemp",
            "crackedEnough",   "SteadyBurn.numPPC", "inductionTime", "countTime"};
  }

  std::vector<ModelField> fields() const override {
    return {{"F", 0, &F_},
            {"delF", 0, &delF_},
            {"detonating", 0, &detonating_},
            {"detLocalTo", 0, &det_local_},
            {"burning", 0, &burning_code_},
            {"BurningCriteria", 0, &burning_code_},
            {"onSurface", 0, &on_surface()},
            {"surfaceTemp", 0, &ts_},
            {"crackedEnough", 0, &cracked_},
            {"SteadyBurn.numPPC", 0, &particles_per_cell_field()},
            {"inductionTime", 0, &induction_},
            {"countTime", 0, &count_}};
  }

  // Restart: the induction state carries over (burning_code_ is last step's "burning").
  std::vector<std::pair<std::string, CellScalars*>> state_fields() override {
    if (!prm_.induction) return {};
    return {{"DDT1.inductionTime", &induction_}, {"DDT1.countTime", &count_}, {"DDT1.burning", &burning_code_}};
  }

 protected:
  double burn_mass(const BurnCell& c) override {
    const IceModelInput& in = *c.in;
    const std::size_t pi = c.patch;
    // The cell's volume in the model's mass units: V, or r_c dx dy per radian
    // (axisymmetric, mpmice/AxisymmetricBurn.h): the product's cell mass, the
    // 20 % cap 0.2 rho0 V and the convective area V / 0.002 m all scale with it.
    const double V = c.volume;
    const auto br = Ddt1Branch(int(branch_[pi](c.c)));
    if (br == Ddt1Branch::Detonating) {
      const double Mp = in.mats[product()].rho_CC[pi](c.c) * V;
      const Ddt1Detonation d = ddt1_detonation(prm_.G, prm_.b, c.pressure, c.solid_mass, Mp, prm_.rho0, V, in.dt);
      F_[pi](c.c) = d.F;
      delF_[pi](c.c) = d.delF;
      detonating_[pi](c.c) = 1.0;
      return d.mass;
    }
    const double vs = in.mats[reactant()].sp_vol_CC[pi](c.c);
    const WsbState w = wsb_burn_rate(prm_.wsb, c.pressure, c.temperature, vs);
    ts_[pi](c.c) = w.surface_temperature;
    const double area = br == Ddt1Branch::Conductive ? c.area : ddt1_convective_area(V);
    return std::min(in.dt * area * w.mass_flux, wsb_burnable_mass(c));
  }

  double heat_of_reaction(std::size_t pi, const IntVec3& c) const override {
    return Ddt1Branch(int(branch_[pi](c))) == Ddt1Branch::Detonating ? prm_.E0 : prm_.wsb.Qc + prm_.wsb.Qg;
  }

 private:
  Ddt1Params prm_;
  // Per-cell state of the last step (mutable: select_cell, a const query of
  // the common machinery, records the branch and the diagnostics it decides).
  mutable CellScalars F_, delF_, detonating_, det_local_, branch_, ts_, cracked_, crack_;
  CellScalars burning_code_;
  // <useInductionTime>: this step's and last step's induction time and
  // exposure time per cell, last step's burning code, this step's warming-up cells.
  mutable CellScalars induction_, count_, warming_;
  CellScalars induction_old_, count_old_, burning_old_;
};

// Uintah's first-step sentinel of the induction time: <Time><delt_init> (or
// <max_initial_delt>, else 0) + 1e-20.
double first_step_sentinel(const DeckNode& model) {
  const DeckNode* root = &model;
  while (root->parent) root = root->parent;
  double delt_init = 0;
  if (const DeckNode* time = root->child("Time")) {
    if (const DeckNode* d = time->child("delt_init")) delt_init = std::stod(d->text);
    else if (const DeckNode* m = time->child("max_initial_delt")) delt_init = std::stod(m->text);
  }
  return delt_init + 1e-20;
}

}  // namespace

IceModelP make_ddt1(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "DDT1"), "DDT1");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  check_reactant_product(mp, setup, r, p, "DDT1");
  if (const DeckNode* bm = mp.node().child("burnMaterial")) {
    const std::size_t q = mp.material("burnMaterial", setup);
    if (q != p) bm->missing_feature("DDT1 <burnMaterial> other than <toMaterial>");
  }
  Ddt1Params prm;
  prm.wsb = read_wsb_params(mp);
  prm.ignition = read_wsb_ignition(mp);
  prm.thresholds.jwl_pressure = mp.positive("ThresholdPressureJWL");
  prm.thresholds.sb_pressure = mp.number("ThresholdPressureSB");
  prm.thresholds.volume_fraction = mp.number("ThresholdVolFrac", 0.01);
  prm.G = mp.positive("G");
  prm.b = mp.number("b");
  prm.E0 = mp.number("E0");
  prm.thresholds.crack_model = mp.flag("useCrackModel", false);
  if (prm.thresholds.crack_model) {
    mp.positive("Gcrack");  // read, unused (Vaango's crack mass term is commented out)
    mp.positive("nCrack");
    mp.number("CrackVolThreshold", 1e-14);
  }
  prm.induction = mp.flag("useInductionTime", false);
  if (prm.induction) {  // Uintah requires the four constants with useInductionTime
    prm.induction_prm.IC = mp.number("IgnitionConst");
    prm.induction_prm.PS = mp.positive("PressureShift");
    prm.induction_prm.Fb = mp.positive("PreexpoConst");
    prm.induction_prm.Fc = mp.number("ExponentialConst");
    prm.first_induction = first_step_sentinel(model);
  } else {
    for (const char* unused : {"IgnitionConst", "PressureShift", "PreexpoConst", "ExponentialConst"})
      if (mp.node().child(unused)) mp.accept(unused);
  }
  if (const DeckNode* adj = mp.node().child("adjust_IO_intervals")) adj->missing_feature("DDT1 <adjust_IO_intervals>");
  mp.accept("rho0");  // BurnRate.ups gives it; Vaango's DDT1 does not read it
  mp.finish();
  prm.rho0 = setup.materials[r].sources.empty() ? 0.0 : setup.materials[r].sources[0].density;
  return std::make_shared<Ddt1Model>(prm, r, p);
}

}  // namespace tephra
