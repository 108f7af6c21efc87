// Source models on one material: <CFD><ICE><ADD_HEAT> (Uintah ICE's
// user-specified heat source) and PassiveScalar (a scalar carried with a
// material's mass). Facts from Uintah's ICE.cc accumulateEnergySourceSinks
// and Vaango's Models/FluidsBased/PassiveScalar.cc.
#include <cmath>

#include "core/geometry/GeometryPiece.h"
#include "core/grid/Loop.h"
#include "ice/models/ModelSupport.h"
#include "ice/models/SourceMaterials.h"

namespace tephra {

namespace {

// ADD_HEAT: for each listed material i, while t_start <= t <= t_final, every
// cell with theta > 0.001 gains the internal energy
//   dE = add_heat_coeff_i dt rho_CC V          [add_heat_coeff in W/kg].
// The sum of dE over the last step is the reduction "TotalHeatAdded" (a
// Tephra label; Uintah keeps no sum).
class AddHeat final : public IceModel, public SourceMaterials {
 public:
  AddHeat(const DeckNode& n, const IceSetup& s) {
    ModelParams p(n, "ADD_HEAT");
    const DeckNode& mats = p.child("add_heat_matls");
    const DeckNode& coeff = p.child("add_heat_coeff");
    for (double v : mats.as_doubles()) {
      if (v < 0 || v != std::floor(v) || v >= double(s.materials.size()))
        mats.fail("add_heat_matls: " + std::to_string(v) + " is not an ICE material index");
      mats_.push_back(std::size_t(v));
    }
    coeff_ = coeff.as_doubles();
    if (coeff_.size() != mats_.size()) coeff.fail("add_heat_coeff needs one value per add_heat_matls entry");
    t0_ = p.number("add_heat_t_start");
    t1_ = p.number("add_heat_t_final");
    p.finish();
  }
  std::string type() const override { return "ADD_HEAT"; }
  std::vector<std::size_t> source_materials() const override { return mats_; }
  void initialize(const Grid& g, const std::vector<IceMaterialFields>&) override { added_.reset(g, 1); }
  std::set<std::string> labels() const override { return {"TotalHeatAdded"}; }
  std::vector<ModelSum> patch_sums() const override { return {{"TotalHeatAdded", &added_, 0, 1}}; }
  std::vector<std::pair<std::string, PatchSums*>> state_sums() override { return {{"TotalHeatAdded", &added_}}; }
  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    added_.zero();
    if (in.time < t0_ || in.time > t1_) return;
    const Grid& g = in.grid;
    const double V = g.cell_volume();
    for (std::size_t i = 0; i < mats_.size(); ++i) {
      const std::size_t m = mats_[i];
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
        for_each_cell_serial(g.patches[pi].cells(), [&](int a, int b, int c) {
          if (!(in.mats[m].vol_frac_CC[pi](a, b, c) > 0.001)) return;
          const double dE = coeff_[i] * in.dt * in.mats[m].rho_CC[pi](a, b, c) * V;
          out.energy[m][pi](a, b, c) += dE;
          added_.at(pi, 0) += dE;
        });
    }
  }

 private:
  std::vector<std::size_t> mats_;
  std::vector<double> coeff_;
  double t0_ = 0, t1_ = 0;
  PatchSums added_;  // per patch (exact across MPI ranks)
};

// PassiveScalar: a scalar q (label "scalar-<name>") carried with the mass of
// one material. Initial value: <scalar> of the first <initialization>
// <geom_object> containing the cell centre, 0 elsewhere. Per step the model
// source is the exact first-order decay over dt,
//   src = q (exp(-k dt) - 1),      k = <constants><decayRate> (default 0),
// and the ICE step advects q with the material's mass fluxes (compatible
// fluxes), so sum M q changes only by sum M src and by boundary fluxes.
// Reduction "totalSum_scalar-<name>" = sum over interior cells of M q.
// Diffusion (<constants><diffusivity> D, default 0): forward Euler on the
// cell values with the 7-point Laplacian,
//   src += dt D sum_d (q_{+d} - 2 q + q_{-d}) / dx_d^2,
// so that where rho is uniform and the gas at rest q obeys q_t = D lap q
// (the heat equation; zero-gradient extra cells make the walls no-flux).
// Stable for dt <= 1 / (2 D sum_d 1/dx_d^2) (stable_timestep()). Sum M q is
// conserved by it where rho is uniform (the Laplacian is a difference of
// face fluxes); with varying rho only sum q is.
// Not yet (exit 3): exponentialDecay, interiorSources and the non-uniform
// initialisations.
class PassiveScalar final : public IceModel, public SourceMaterials {
 public:
  // Two layouts: Vaango's code reads <PassiveScalar><material/><scalar name>
  // ... <initialization><geom_object>; Vaango's schema (ups_spec Models.xml,
  // the layout `tephra --validate` accepts) puts <scalar name> directly in
  // <Model> with <material> and the <geom_object>s inside it.
  PassiveScalar(const DeckNode& model, const IceSetup& s) {
    const DeckNode* b = model.child("PassiveScalar");
    const DeckNode* scp = nullptr;
    if (b) {
      ModelParams p(*b, "PassiveScalar");
      m_ = p.material("material", s);
      scp = &p.child("scalar");
      p.finish();
    } else {
      ModelParams p(model, "PassiveScalar");
      scp = &p.child("scalar");
      p.finish();
    }
    const DeckNode& sc = *scp;
    name_ = "scalar-" + sc.require_attribute("name");
    ModelParams q(sc, "PassiveScalar <scalar>");
    if (!b) m_ = q.material("material", s);
    q.accept("test_conservation");  // Tephra always offers totalSum_<name>
    q.flag("reinitializeDomain", false);
    if (const DeckNode* c = sc.child("constants")) {
      q.accept("constants");
      ModelParams k(*c, "PassiveScalar <constants>");
      decay_ = k.number("decayRate", 0.0);
      if (decay_ < 0) c->require_child("decayRate").fail("decayRate must be >= 0");
      diffusivity_ = k.number("diffusivity", 0.0);
      if (diffusivity_ < 0) c->require_child("diffusivity").fail("diffusivity must be >= 0");
      k.accept("AMR_Refinement_Criteria");  // refinement flag only: no AMR in Tephra
      k.accept("initialize_diffusion_knob");
      k.finish();
    }
    if (const DeckNode* e = sc.child("exponentialDecay")) e->missing_feature("PassiveScalar <exponentialDecay>");
    if (const DeckNode* e = sc.child("interiorSources")) e->missing_feature("PassiveScalar <interiorSources>");
    if (const DeckNode* e = sc.child("reaction_constants")) e->missing_feature("PassiveScalar <reaction_constants>");
    if (const DeckNode* e = sc.child("doTableTest")) e->missing_feature("PassiveScalar <doTableTest>");
    std::vector<const DeckNode*> objects;
    if (b) {
      const DeckNode& init = q.child("initialization");
      for (const DeckNode& go : init.children) {
        if (go.name != "geom_object") go.fail("<initialization> holds <geom_object>s only");
        objects.push_back(&go);
      }
    } else {
      q.accept("geom_object");
      objects = sc.children_named("geom_object");
    }
    q.finish();
    GeometryRegistry geometry;
    for (const DeckNode* go : objects) {
      Region r;
      r.piece = geometry.parse_geom_object(*go);
      r.value = go->get_double("scalar");
      for (const DeckNode& c : go->children) {
        if (GeometryRegistry::is_piece_name(c.name) || c.name == "scalar") continue;
        c.missing_feature("PassiveScalar initialisation <" + c.name + "> (uniform <scalar> only)");
      }
      regions_.push_back(std::move(r));
    }
    if (regions_.empty()) sc.fail("PassiveScalar needs at least one initial <geom_object>");
  }
  std::string type() const override { return "PassiveScalar"; }
  std::vector<std::size_t> source_materials() const override { return {m_}; }
  void initialize(const Grid& g, const std::vector<IceMaterialFields>& mats) override {
    grid_ = &g;
    mats_ = &mats;
    q_ = CellScalars(g, 2);
    src_ = CellScalars(g, 2);
    q_.fill(0.0);
    src_.fill(0.0);
    // Every stored cell (ghosts too: the first step's diffusion reads the
    // neighbours across patch boundaries before any halo exchange of q).
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(q_[pi].with_ghosts(), [&](int i, int j, int k) {
        const Vec3 x = g.lower + (Vec3(i, j, k) + Vec3::Constant(0.5)).cwiseProduct(g.dx);
        for (const Region& r : regions_)
          if (r.piece->inside(x)) {
            q_[pi](i, j, k) = r.value;
            break;
          }
      });
  }
  void compute_sources(const IceModelInput& in, IceModelSources&) override {
    const Grid& g = in.grid;
    const double f = std::exp(-decay_ * in.dt) - 1.0;
    const Vec3 w = in.dt * diffusivity_ * g.dx.cwiseProduct(g.dx).cwiseInverse();  // dt D / dx_d^2
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        const auto& q = q_[pi];
        double s = f * q(i, j, k);
        if (diffusivity_ > 0) s += scalar_laplacian_step(q, w, i, j, k);
        src_[pi](i, j, k) = s;
      });
  }
  double stable_timestep() const override {
    return grid_ ? scalar_diffusion_stable_timestep(diffusivity_, grid_->dx) : std::numeric_limits<double>::infinity();
  }
  std::vector<TransportedScalar> transported() override { return {{m_, &q_, &src_}}; }
  std::set<std::string> labels() const override { return {name_, "totalSum_" + name_}; }
  std::vector<ModelField> fields() const override { return {{name_, int(m_), &q_}}; }
  // totalSum = sum rho V q over the interior cells, one partial per patch.
  std::vector<ModelSum> patch_sums() const override {
    const Grid& g = *grid_;
    total_.reset(g, 1);
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        total_.at(pi, 0) += (*mats_)[m_].rho_CC[pi](i, j, k) * g.cell_volume() * q_[pi](i, j, k);
      });
    return {{"totalSum_" + name_, &total_, 0, 1}};
  }
  std::vector<std::pair<std::string, CellScalars*>> state_fields() override { return {{name_, &q_}}; }

 private:
  struct Region {
    GeometryPieceP piece;
    double value = 0;
  };
  std::size_t m_ = 0;
  std::string name_;
  double decay_ = 0;
  double diffusivity_ = 0;
  const Grid* grid_ = nullptr;
  const std::vector<IceMaterialFields>* mats_ = nullptr;
  std::vector<Region> regions_;
  CellScalars q_, src_;
  mutable PatchSums total_;  // filled when the sums are asked for
};

}  // namespace

IceModelP make_add_heat(const DeckNode& n, const IceSetup& s) { return std::make_shared<AddHeat>(n, s); }
IceModelP make_passive_scalar(const DeckNode& m, const IceSetup& s) { return std::make_shared<PassiveScalar>(m, s); }

}  // namespace tephra
