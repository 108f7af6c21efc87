// SimpleRxn: a two-gas ideal mixture ("air" and "fuel") described by a
// mixture fraction f (label "scalar-f", 0 = air, 1 = fuel) carried with the
// mass of one ICE ideal-gas material. Facts from Uintah's
// Models/FluidsBased/SimpleRxn.cc (own code):
//   - per cell, from f (at the top of the step and again after f is
//     advected, for the new temperature):
//       cv    = f cv_fuel + (1 - f) cv_air
//       R_mix = f R_fuel  + (1 - f) R_air,     gamma = R_mix / cv + 1
//     so the material's EOS is p = (gamma - 1) rho cv T = rho R_mix T and
//     c^2 = gamma R_mix T per cell (ice/models/IceModel.h CellIdealGas);
//   - at initialisation the density is the mixture's at f,
//       1/rho = f/rho_fuel + (1 - f)/rho_air   (rho_CC = rho_micro, theta = 1);
//   - the "reaction" is switched off in Uintah's code (f_src = 0); f changes
//     only by advection and by diffusion with <diffusivity> D:
//       src = dt D sum_d (f_{+d} - 2 f + f_{-d})/dx_d^2   (ModelSupport.h),
//     forward Euler, Delta t <= 1/(2 D sum 1/dx_d^2) through stable_timestep();
//   - sum over interior cells of M f is the reduction "sum_scalar_f".
// Departures / not built (MissingFeature, exit 3): per-cell thermal
// conductivity and viscosity (accepted only when the air and fuel values are
// both the material's own <thermal_conductivity>/<dynamic_viscosity>), the
// initial smoothing <initialize_diffusion_knob> > 1, <probePoints>.
// <f_stoichometric> is read and has no effect (as in Uintah).
#include <cmath>

#include "core/geometry/GeometryPiece.h"
#include "core/grid/Loop.h"
#include "ice/models/ModelSupport.h"

namespace tephra {

namespace {

class SimpleRxn final : public IceModel {
 public:
  // Layouts: <Model type="SimpleRxn"><SimpleRxn><material/><scalar name="f">
  // (Vaango's schema) or <material> directly in <Model> (what Uintah's code
  // reads); one of the two.
  SimpleRxn(const DeckNode& model, const IceSetup& s) {
    ModelParams outer(model, "SimpleRxn <Model>");
    const DeckNode& b = outer.child("SimpleRxn");
    ModelParams p(b, "SimpleRxn");
    if (model.child("material")) {
      if (b.child("material")) b.require_child("material").fail("SimpleRxn <material> given twice (<Model> and <SimpleRxn>)");
      m_ = outer.material("material", s);
    } else {
      m_ = p.material("material", s);
    }
    outer.finish();
    const IceMaterialSpec& spec = s.materials[m_];
    if (spec.eos_type != "ideal_gas")
      b.require_child("material").fail("SimpleRxn needs an ideal_gas material (material " + std::to_string(m_) +
                                       " has EOS '" + spec.eos_type + "')");
    const DeckNode& sc = p.child("scalar");
    p.finish();
    ModelParams q(sc, "SimpleRxn <scalar>");
    q.accept("test_conservation");  // Tephra always offers sum_scalar_f
    if (const DeckNode* e = sc.child("probePoints")) e->missing_feature("SimpleRxn <probePoints>");
    ModelParams k(q.child("constants"), "SimpleRxn <constants>");
    k.number("f_stoichometric");  // no effect: Uintah's reaction is hard-wired off
    rho_air_ = k.positive("rho_air");
    rho_fuel_ = k.positive("rho_fuel");
    cv_air_ = k.positive("cv_air");
    cv_fuel_ = k.positive("cv_fuel");
    R_air_ = k.positive("R_air");
    R_fuel_ = k.positive("R_fuel");
    D_ = k.number("diffusivity");
    if (D_ < 0) k.node().require_child("diffusivity").fail("diffusivity must be >= 0");
    const double knob = k.number("initialize_diffusion_knob", 0.0);
    if (knob > 1) k.node().require_child("initialize_diffusion_knob").missing_feature(
        "SimpleRxn initial smoothing (initialize_diffusion_knob > 1)");
    // Uintah's defaults for the transport properties are 0.
    const auto same = [&](const char* air, const char* fuel, double own, const char* what) {
      const double a = k.number(air, 0.0), f = k.number(fuel, 0.0);
      if (a != own || f != own)
        k.node().missing_feature(std::string("SimpleRxn per-cell ") + what + " (" + air + " = " + std::to_string(a) +
                                 ", " + fuel + " = " + std::to_string(f) + "; Tephra runs it only when both equal the "
                                 "material's own value " + std::to_string(own) + ")");
    };
    same("thermalCond_air", "thermalCond_fuel", spec.thermal_conductivity, "thermal conductivity");
    same("viscosity_air", "viscosity_fuel", spec.dynamic_viscosity, "viscosity");
    k.finish();
    q.accept("geom_object");
    GeometryRegistry geometry;
    for (const DeckNode* go : sc.children_named("geom_object")) {
      Region r;
      r.piece = geometry.parse_geom_object(*go);
      r.value = go->get_double("scalar");
      for (const DeckNode& c : go->children) {
        if (GeometryRegistry::is_piece_name(c.name) || c.name == "scalar") continue;
        c.fail("SimpleRxn <geom_object> holds a geometry piece and <scalar> only, not <" + c.name + ">");
      }
      regions_.push_back(std::move(r));
    }
    if (regions_.empty()) sc.fail("SimpleRxn needs at least one initial <geom_object> for scalar-f");
    q.finish();
    gas_.material = m_;
  }

  std::string type() const override { return "SimpleRxn"; }

  void initialize(const Grid& g, const std::vector<IceMaterialFields>& mats) override {
    grid_ = &g;
    mats_ = &mats;
    f_ = CellScalars(g, 2);
    src_ = CellScalars(g, 2);
    cv_ = CellScalars(g, 2);  // the layout of the ICE cell fields (row pointers are shared)
    gamma_ = CellScalars(g, 2);
    src_.fill(0.0);
    // f = <scalar> of the last region containing the cell centre (Uintah
    // loops over the regions in order, each overwriting), 0 elsewhere; every
    // stored cell (the first diffusion reads across patch boundaries).
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(f_[pi].with_ghosts(), [&](int i, int j, int k) {
        const Vec3 x = g.lower + (Vec3(i, j, k) + Vec3::Constant(0.5)).cwiseProduct(g.dx);
        double v = 0;
        for (const Region& r : regions_)
          if (r.piece->inside(x)) v = r.value;
        f_[pi](i, j, k) = v;
      });
    gas_.cv = &cv_;
    gas_.gamma = &gamma_;
    update_cell_properties();
  }

  // 1/rho = f/rho_fuel + (1 - f)/rho_air in every stored cell of the material.
  void initialize_state(std::vector<IceMaterialFields>& mats) override {
    IceMaterialFields& m = mats[m_];
    for (std::size_t pi = 0; pi < grid_->patches.size(); ++pi) {
      const double* f = f_[pi].data();
      double* rho = m.rho_CC[pi].data();
      double* v = m.sp_vol_CC[pi].data();
      for (std::size_t c = 0; c < f_[pi].size(); ++c) {
        v[c] = f[c] / rho_fuel_ + (1.0 - f[c]) / rho_air_;
        rho[c] = 1.0 / v[c];
      }
    }
  }

  const CellIdealGas* cell_ideal_gas() const override { return &gas_; }

  void update_cell_properties() override {
    for (std::size_t pi = 0; pi < grid_->patches.size(); ++pi) {
      const double* f = f_[pi].data();
      double* cv = cv_[pi].data();
      double* gamma = gamma_[pi].data();
      for (std::size_t c = 0; c < f_[pi].size(); ++c) {
        cv[c] = f[c] * cv_fuel_ + (1.0 - f[c]) * cv_air_;
        gamma[c] = (f[c] * R_fuel_ + (1.0 - f[c]) * R_air_) / cv[c] + 1.0;
      }
    }
  }

  void compute_sources(const IceModelInput& in, IceModelSources&) override {
    const Grid& g = in.grid;
    const Vec3 w = in.dt * D_ * g.dx.cwiseProduct(g.dx).cwiseInverse();  // dt D / dx_d^2
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        src_[pi](i, j, k) = D_ > 0 ? scalar_laplacian_step(f_[pi], w, i, j, k) : 0.0;
      });
  }
  double stable_timestep() const override {
    return grid_ ? scalar_diffusion_stable_timestep(D_, grid_->dx) : std::numeric_limits<double>::infinity();
  }
  std::vector<TransportedScalar> transported() override { return {{m_, &f_, &src_}}; }
  std::set<std::string> labels() const override { return {"scalar-f", "sum_scalar_f"}; }
  std::vector<ModelField> fields() const override { return {{"scalar-f", int(m_), &f_}}; }
  void reductions(const std::set<std::string>& l, std::map<std::string, std::vector<double>>& out) const override {
    if (!l.count("sum_scalar_f")) return;
    const Grid& g = *grid_;
    double sum = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        sum += (*mats_)[m_].rho_CC[pi](i, j, k) * g.cell_volume() * f_[pi](i, j, k);
      });
    out["sum_scalar_f"] = {sum};
  }
  // Restart: f carries over; cv and gamma follow from it.
  std::vector<std::pair<std::string, CellScalars*>> state_fields() override { return {{"scalar-f", &f_}}; }

 private:
  struct Region {
    GeometryPieceP piece;
    double value = 0;
  };
  std::size_t m_ = 0;
  double rho_air_ = 0, rho_fuel_ = 0, cv_air_ = 0, cv_fuel_ = 0, R_air_ = 0, R_fuel_ = 0, D_ = 0;
  std::vector<Region> regions_;
  const Grid* grid_ = nullptr;
  const std::vector<IceMaterialFields>* mats_ = nullptr;
  CellScalars f_, src_, cv_, gamma_;
  CellIdealGas gas_;
};

}  // namespace

IceModelP make_simple_rxn(const DeckNode& m, const IceSetup& s) { return std::make_shared<SimpleRxn>(m, s); }

}  // namespace tephra
