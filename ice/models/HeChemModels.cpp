// High-explosive reaction models that need no solid: LightTime (programmed
// burn), JWLpp (Souers' JWL++ rate), ZeroOrder and IandG (Lee-Tarver
// ignition and growth). Each converts reactant into product cell by cell
// (ModelSupport.h convert_mass). Facts (parameters, defaults, the reacted
// fraction, the 20 % limit) from Uintah's Models/HEChem/*.cc.
#include <algorithm>
#include <cmath>

#include "core/grid/Loop.h"
#include "ice/models/ModelSupport.h"
#include "ice/models/SourceMaterials.h"

namespace tephra {

namespace {

// The state shared by the reactant -> product models: the two materials, the
// heat of reaction, the reacted fraction F and its change delF of the last
// step (labels "F" and "delF" on the reactant, as Uintah), and the mass and
// heat of the last step (Uintah's per-step sums totalMassBurned and
// totalHeatReleased), kept per patch (PatchSums) so that they are the same
// bits on any number of MPI ranks.
class Conversion : public IceModel, public SourceMaterials {
 public:
  void initialize(const Grid& g, const std::vector<IceMaterialFields>&) override {
    sums_.reset(g, 2);
    F_ = CellScalars(g, 0);
    delF_ = CellScalars(g, 0);
    F_.fill(0.0);
    delF_.fill(0.0);
  }
  std::set<std::string> labels() const override { return {"F", "delF", "totalMassBurned", "totalHeatReleased"}; }
  std::vector<ModelField> fields() const override {
    return {{"F", int(m0_), &F_}, {"delF", int(m0_), &delF_}};
  }
  // Per patch: column 0 the mass converted in the last step, column 1 its heat.
  std::vector<ModelSum> patch_sums() const override {
    return {{"totalMassBurned", &sums_, 0, 1}, {"totalHeatReleased", &sums_, 1, 1}};
  }
  std::vector<std::pair<std::string, CellScalars*>> state_fields() override { return {{"F", &F_}, {"delF", &delF_}}; }
  std::vector<std::pair<std::string, PatchSums*>> state_sums() override { return {{"burned_heat", &sums_}}; }
  std::vector<std::size_t> source_materials() const override { return {m0_, m1_}; }
  std::size_t reactant() const { return m0_; }
  std::size_t product() const { return m1_; }

 protected:
  // Every cell of every patch: rate(in, pi, c, F, dm_max) returns the mass
  // to convert (<= the reactant mass); the conversion is applied here.
  template <class Rate>
  void convert_cells(const IceModelInput& in, IceModelSources& out, Rate rate) {
    const Grid& g = in.grid;
    const double V = g.cell_volume();
    sums_.zero();
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      double& burned = sums_.at(pi, 0);
      double& heat = sums_.at(pi, 1);
      const IceMaterialFields& r = in.mats[m0_];
      const IceMaterialFields& p = in.mats[m1_];
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        const IntVec3 c(i, j, k);
        const double rct = r.rho_CC[pi](c) * V, prd = p.rho_CC[pi](c) * V;
        const double dm = rate(pi, c, rct, prd);
        if (!(dm > 0)) return;
        convert_mass(out, pi, c, m0_, m1_, dm, r.vel_CC[pi](c), in.cv_CC[m0_][pi](c) * r.temp_CC[pi](c),
                     r.sp_vol_CC[pi](c), E0_);
        burned += dm;
        heat += dm * E0_;
      });
    }
  }

  std::size_t m0_ = 0, m1_ = 0;
  double E0_ = 0;
  CellScalars F_, delF_;
  PatchSums sums_;
};

void read_pair(ModelParams& p, const IceSetup& s, std::size_t& m0, std::size_t& m1) {
  m0 = p.material("fromMaterial", s);
  m1 = p.material("toMaterial", s);
  if (m0 == m1) p.node().require_child("toMaterial").fail("fromMaterial and toMaterial must differ");
}

// LightTime (programmed burn). A cell at distance d from the starting plane
// (direction_if_plane != 0: the plane through starting_location with that
// normal) or point (direction_if_plane = 0) is reached by the front at
// t_b = d/D; from then on its reacted fraction is
//   F = (t - t_b)/delta_L,   delta_L = 1.5 V^(1/3)/D   (the front is ~1.5 cells thick),
// set to 1 above 0.96, and the mass converted in the step is
//   dm = min((F - F_old)(M_r + M_p), M_r),   F_old = M_p/(M_r + M_p).
// Only cells holding reactant and product (theta_r + theta_p > 0.99) react
// unless react_mixed_cells (default true). t is the time at the start of the
// step (Uintah's simTime from the old data warehouse).
class LightTime final : public Conversion {
 public:
  LightTime(const DeckNode& model, const IceSetup& s) {
    const DeckNode* b = model.child("LightTime");
    if (!b) model.fail("Model type LightTime needs a <LightTime> block");
    ModelParams p(*b, "LightTime");
    read_pair(p, s, m0_, m1_);
    D_ = p.positive("D");
    E0_ = p.positive("E0");
    start_ = p.vec3("starting_location");
    dir_ = p.vec3("direction_if_plane");
    mixed_ = p.flag("react_mixed_cells", true);
    p.accept("AMR_Refinement_Criteria");  // refinement flag only: no AMR in Tephra
    p.finish();
    tiny_ = 2.0 * s.materials[m0_].tiny_rho * s.materials[m0_].sources[0].density;
  }
  std::string type() const override { return "LightTime"; }
  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    const Grid& g = in.grid;
    const double delta_L = 1.5 * std::cbrt(g.cell_volume()) / D_;
    const bool plane = dir_.norm() > 0;
    const double inv_n = plane ? 1.0 / dir_.norm() : 1.0;
    const double t = in.time;
    F_.fill(0.0);
    delF_.fill(0.0);
    convert_cells(in, out, [&](std::size_t pi, const IntVec3& c, double rct, double prd) {
      const Vec3 x = g.lower + (c.cast<double>() + Vec3::Constant(0.5)).cwiseProduct(g.dx);
      const double dist = plane ? std::abs(dir_.dot(x - start_)) * inv_n : (x - start_).norm();
      const double t_b = dist / D_;
      const double theta = in.mats[m0_].vol_frac_CC[pi](c) + in.mats[m1_].vol_frac_CC[pi](c);
      double dm = 0;
      if (theta > (mixed_ ? 0.0 : 0.99) && t >= t_b && rct > tiny_ * g.cell_volume()) {
        double F = (t - t_b) / delta_L;
        if (F > 0.96) F = 1.0;
        const double dF = F - prd / (rct + prd);
        F_[pi](c) = F;
        delF_[pi](c) = dF;
        dm = std::min(dF * (rct + prd), rct);
      }
      if (rct <= tiny_ * g.cell_volume()) {
        F_[pi](c) = 1.0;
        delF_[pi](c) = 0.0;
      }
      return dm;
    });
  }

 private:
  double D_ = 0, tiny_ = 0;
  Vec3 start_, dir_;
  bool mixed_ = true;
};

// The pressure-triggered rate laws (JWLpp, ZeroOrder): where p_eq >
// ThresholdPressure and theta_r > ThresholdVolFrac (default 0.01),
//   F = M_p/(M_r + M_p),  delF = rate(p, F) dt,
//   dm = min(delF (M_r + M_p), M_r, 0.2 rho0 V)
// (the 20 % of a cell per step limit, Souers, "JWL++: a simple reactive flow
// code package for detonation", p. 55, as Uintah).
class PressureRate : public Conversion {
 protected:
  void read_common(ModelParams& p, const IceSetup& s) {
    read_pair(p, s, m0_, m1_);
    threshold_p_ = p.number("ThresholdPressure");
    threshold_theta_ = p.number("ThresholdVolFrac", 0.01);
    G_ = p.positive("G");
    b_ = p.number("b");
    E0_ = p.number("E0");
    rho0_ = p.positive("rho0");
    active_ = p.flag("Active", true);
    p.finish();
  }
  template <class Law>
  void run(const IceModelInput& in, IceModelSources& out, Law law) {
    F_.fill(0.0);
    delF_.fill(0.0);
    if (!active_) return;
    const double V = in.grid.cell_volume();
    convert_cells(in, out, [&](std::size_t pi, const IntVec3& c, double rct, double prd) {
      const double p = in.press_equil_CC[pi](c);
      if (!(p > threshold_p_ && in.mats[m0_].vol_frac_CC[pi](c) > threshold_theta_)) return 0.0;
      const double F = prd / (rct + prd);
      const double dF = law(p, F) * in.dt;
      F_[pi](c) = F;
      delF_[pi](c) = dF;
      return std::min({dF * (rct + prd), rct, 0.2 * rho0_ * V});
    });
  }
  double threshold_p_ = 0, threshold_theta_ = 0.01, G_ = 0, b_ = 0, rho0_ = 0;
  bool active_ = true;
};

// JWL++ (Souers et al. 2000): dF/dt = G p^b (1 - F) while F < 0.99.
class Jwlpp final : public PressureRate {
 public:
  Jwlpp(const DeckNode& model, const IceSetup& s) {
    ModelParams p(model_block(model, "JWLpp"), "JWLpp");
    read_common(p, s);
  }
  std::string type() const override { return "JWLpp"; }
  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    run(in, out, [&](double p, double F) { return (F >= 0 && F < 0.99) ? G_ * std::pow(p, b_) * (1 - F) : 0.0; });
  }
};

// Zero order in F: dF/dt = G p^b while F < 1.
class ZeroOrder final : public PressureRate {
 public:
  ZeroOrder(const DeckNode& model, const IceSetup& s) {
    ModelParams p(model_block(model, "ZeroOrder"), "ZeroOrder");
    read_common(p, s);
  }
  std::string type() const override { return "ZeroOrder"; }
  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    run(in, out, [&](double p, double F) { return (F >= 0 && F < 1.0) ? G_ * std::pow(p, b_) : 0.0; });
  }
};

// Lee-Tarver ignition and growth (Lee & Tarver 1980; Tarver et al. 1985), the
// three-term form of Uintah's IandG, where p_eq > ThresholdPressure:
//   dF/dt = I (1-F)^b (rho_r/rho0 - 1 - a)^x              F < Figmax
//         + G1 (1-F)^c F^d p^y                             F < FG1max
//         + G2 (1-F)^e F^g p^z                   FG2min <= F < 0.99
// rho_r = 1/v_r the reactant micro density; dm = min(dF (M_r+M_p) , M_r,
// 0.2 rho0 V). The ignition term needs compression beyond a: Tephra drops it
// when rho_r/rho0 - 1 - a <= 0 (Uintah raises a negative base to the
// power x, a NaN for non-integer x).
class IgnitionGrowth final : public Conversion {
 public:
  IgnitionGrowth(const DeckNode& model, const IceSetup& s) {
    const DeckNode* blk = model.child("IandG");
    if (!blk) model.fail("Model type IandG needs an <IandG> block");
    ModelParams p(*blk, "IandG");
    read_pair(p, s, m0_, m1_);
    I_ = p.positive("I");
    G1_ = p.positive("G1");
    G2_ = p.positive("G2");
    a_ = p.number("a");
    b_ = p.number("b");
    c_ = p.number("c");
    d_ = p.number("d");
    e_ = p.number("e");
    g_ = p.number("g");
    x_ = p.number("x");
    y_ = p.number("y");
    z_ = p.number("z");
    Figmax_ = p.number("Figmax");
    FG1max_ = p.number("FG1max");
    FG2min_ = p.number("FG2min");
    rho0_ = p.positive("rho0");
    E0_ = p.number("E0");
    threshold_p_ = p.number("ThresholdPressure");
    p.finish();
  }
  std::string type() const override { return "IandG"; }
  // dF/dt at a state (the rate law above; public for the unit test).
  double rate(double F, double rho_r, double p) const {
    double r = 0;
    const double eta = rho_r / rho0_ - 1.0 - a_;
    if (F >= 0 && F < Figmax_ && eta > 0) r += I_ * std::pow(1 - F, b_) * std::pow(eta, x_);
    if (F >= 0 && F < FG1max_) r += G1_ * std::pow(1 - F, c_) * std::pow(F, d_) * std::pow(p, y_);
    if (F >= FG2min_ && F < 0.99) r += G2_ * std::pow(1 - F, e_) * std::pow(F, g_) * std::pow(p, z_);
    return r;
  }
  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    F_.fill(0.0);
    delF_.fill(0.0);
    const double V = in.grid.cell_volume();
    convert_cells(in, out, [&](std::size_t pi, const IntVec3& c, double rct, double prd) {
      const double p = in.press_equil_CC[pi](c);
      if (!(p > threshold_p_)) return 0.0;
      const double F = prd / (rct + prd);
      const double dF = rate(F, 1.0 / in.mats[m0_].sp_vol_CC[pi](c), p) * in.dt;
      F_[pi](c) = F;
      delF_[pi](c) = dF;
      return std::min({dF * (rct + prd), rct, 0.2 * rho0_ * V});
    });
  }

 private:
  double I_, G1_, G2_, a_, b_, c_, d_, e_, g_, x_, y_, z_, Figmax_, FG1max_, FG2min_, rho0_, threshold_p_;
};

}  // namespace

IceModelP make_light_time(const DeckNode& m, const IceSetup& s) { return std::make_shared<LightTime>(m, s); }
IceModelP make_jwlpp(const DeckNode& m, const IceSetup& s) { return std::make_shared<Jwlpp>(m, s); }
IceModelP make_zero_order(const DeckNode& m, const IceSetup& s) { return std::make_shared<ZeroOrder>(m, s); }
IceModelP make_ignition_growth(const DeckNode& m, const IceSetup& s) { return std::make_shared<IgnitionGrowth>(m, s); }

}  // namespace tephra
