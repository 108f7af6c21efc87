// make_ice_component: the ICE parts of a deck -> an IceComponent.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>

#include "core/base/Log.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "ice/Exchange.h"
#include "ice/IceAxisymmetricDeck.h"
#include "ice/IceComponent.h"
#include "ice/models/IceModel.h"
#include "models/ModelParameters.h"

namespace tephra {

namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// ModelParameters over the children of <EOS>; a failure about a parameter that
// is not a child (gamma, specific_heat live beside <EOS>) is located at <EOS>.
// Every name asked for is recorded, so children no creator read are rejected.
class EosDeckParameters final : public ModelParameters {
 public:
  explicit EosDeckParameters(const DeckNode& n) : node_(n) {}
  bool has(const std::string& name) const override {
    used_.insert(name);
    return node_.has_child(name);
  }
  double get_double(const std::string& name) const override {
    used_.insert(name);
    return node_.get_double(name);
  }
  double get_double(const std::string& name, double fallback) const override {
    used_.insert(name);
    return node_.get_double(name, fallback);
  }
  bool get_bool(const std::string& name, bool fallback) const override {
    used_.insert(name);
    return node_.get_bool(name, fallback);
  }
  [[noreturn]] void fail(const std::string& name, const std::string& message) const override {
    const DeckNode* c = node_.child(name);
    (c ? *c : node_).fail(message);
  }
  [[noreturn]] void missing_feature(const std::string& name, const std::string& what) const override {
    const DeckNode* c = node_.child(name);
    (c ? *c : node_).missing_feature(what);
  }
  bool used(const std::string& name) const { return used_.count(name) > 0; }

 private:
  const DeckNode& node_;
  mutable std::set<std::string> used_;
};

double positive(const DeckNode& parent, const char* name) {
  const DeckNode& n = parent.require_child(name);
  const double v = n.as_double();
  if (!(v > 0.0)) n.fail(std::string(name) + " must be > 0");
  return v;
}

IceSource parse_source(const DeckNode& go, GeometryRegistry& geometry) {
  IceSource s;
  s.piece = geometry.parse_geom_object(go);
  s.res = go.get_int_vec3("res", IntVec3::Constant(2));
  if ((s.res.array() < 1).any()) go.require_child("res").fail("res must be >= 1 in every direction");
  s.velocity = go.get_vec3("velocity");
  s.density = positive(go, "density");
  s.pressure = positive(go, "pressure");
  s.temperature = positive(go, "temperature");
  if (const DeckNode* vf = go.child("volumeFraction")) {
    // -1 is Uintah's "absent" (GeometryObject's default), so it is read as absent.
    const double v = vf->as_double();
    if (v != -1.0) {
      if (!(v >= 0.0 && v <= 1.0)) vf->fail("volumeFraction must be in [0, 1] (or -1, absent)");
      s.volume_fraction = v;
    }
  }
  for (const DeckNode& c : go.children) {
    if (GeometryRegistry::is_piece_name(c.name)) continue;
    static const std::set<std::string> known = {"res", "velocity", "density", "pressure", "temperature",
                                                "volumeFraction"};
    if (!known.count(c.name)) c.missing_feature("ICE <geom_object> initial value <" + c.name + ">");
  }
  return s;
}

// <SpecificHeatModel type="Polynomial|Debye|Component"> (ups_spec/ice_spec.xml;
// parameters and defaults as Uintah's ICE SpecificHeatModel constructors).
IceSpecificHeatP parse_specific_heat(const DeckNode& n) {
  const std::string type = n.require_attribute("type");
  if (type == "Polynomial") {
    const int order = n.require_child("MaxOrder").as_int();
    if (order < 0) n.require_child("MaxOrder").fail("MaxOrder must be >= 0");
    const std::vector<double> a = n.require_child("coefficient").as_doubles();
    if (a.size() != static_cast<std::size_t>(order) + 1)
      n.require_child("coefficient").fail("Polynomial <coefficient> needs MaxOrder + 1 = " + std::to_string(order + 1) +
                                          " values, has " + std::to_string(a.size()));
    const double Tmin = n.child("Tmin") ? n.child("Tmin")->as_double() : 0.0;
    const double Tmax = n.child("Tmax") ? n.child("Tmax")->as_double() : 1.0e6;
    if (!(Tmin < Tmax)) n.fail("Polynomial specific heat needs Tmin < Tmax");
    for (const DeckNode& c : n.children)
      if (c.name != "MaxOrder" && c.name != "coefficient" && c.name != "Tmin" && c.name != "Tmax")
        c.fail("SpecificHeatModel Polynomial has no parameter <" + c.name + ">");
    return make_polynomial_cv(order, a, Tmin, Tmax);
  }
  if (type == "Debye") {
    const int atoms = n.require_child("Atoms").as_int();
    const double TD = n.require_child("DebyeTemperature").as_double();
    if (atoms <= 0) n.require_child("Atoms").fail("Atoms must be > 0");
    if (!(TD > 0)) n.require_child("DebyeTemperature").fail("DebyeTemperature must be > 0");
    for (const DeckNode& c : n.children)
      if (c.name != "Atoms" && c.name != "DebyeTemperature") c.fail("SpecificHeatModel Debye has no parameter <" + c.name + ">");
    return make_debye_cv(atoms, TD);
  }
  if (type == "Component") {
    const auto& names = component_cv_species();
    std::vector<double> X(names.size(), 0.0);
    double sum = 0;
    for (const DeckNode& c : n.children) {
      const auto it = std::find(names.begin(), names.end(), c.name);
      if (it == names.end()) c.fail("SpecificHeatModel Component has no parameter <" + c.name + ">");
      const double x = c.as_double();
      if (x < 0) c.fail("mole fraction must be >= 0");
      X[static_cast<std::size_t>(it - names.begin())] = x;
      sum += x;
    }
    // Uintah: the fractions must add to 1 within 1e-12.
    if (std::abs(sum - 1.0) > 1e-12) n.fail("Component mole fractions add to " + std::to_string(sum) + ", not 1");
    return make_component_cv(X);
  }
  n.fail("unknown SpecificHeatModel type '" + type + "' (Debye, Component, Polynomial)");
}

IceMaterialSpec parse_material(const DeckNode& mat, int index, GeometryRegistry& geometry) {
  IceMaterialSpec m;
  m.index = index;
  m.name = mat.attribute("name").value_or("");
  m.gamma = positive(mat, "gamma");
  m.cv = positive(mat, "specific_heat");
  if (const DeckNode* shm = mat.child("SpecificHeatModel")) {
    m.cv_model = parse_specific_heat(*shm);
    // Component defines gamma (mole-fraction mix, constant in T); it replaces <gamma> (Uintah getGamma).
    if (auto gm = m.cv_model->gamma()) m.gamma = *gm;
  }
  m.dynamic_viscosity = mat.require_child("dynamic_viscosity").as_double();
  m.thermal_conductivity = mat.require_child("thermal_conductivity").as_double();
  if (m.dynamic_viscosity < 0) mat.require_child("dynamic_viscosity").fail("dynamic_viscosity must be >= 0");
  if (m.thermal_conductivity < 0) mat.require_child("thermal_conductivity").fail("thermal_conductivity must be >= 0");
  for (const DeckNode& c : mat.children) {
    if (c.name == "EOS") {
      m.eos_type = c.require_attribute("type");
      EosDeckParameters params(c);
      m.eos = create_equation_of_state(m.eos_type, params, {m.gamma, m.cv});
      if (!m.eos) {
        const auto& vaango = vaango_equation_of_state_types();
        if (std::find(vaango.begin(), vaango.end(), m.eos_type) != vaango.end())
          c.missing_feature("EOS type '" + m.eos_type + "' (implemented: " + join(equation_of_state_types()) + ")");
        c.fail("unknown EOS type '" + m.eos_type + "' (implemented: " + join(equation_of_state_types()) + ")");
      }
      for (const DeckNode& p : c.children) {
        if (params.used(p.name)) continue;
        // Vaango's JWL reads no <C> (only JWLC has that term), yet stock decks
        // (MPMICE/BurnRate.ups) write one: accept it the way Vaango does, and say so.
        if (m.eos_type == "JWL" && p.name == "C") {
          log::warning(p.location().str() + ": <C> is not a JWL parameter (Vaango ignores it); ignored");
          continue;
        }
        p.fail("EOS type '" + m.eos_type + "' has no parameter <" + p.name + ">");
      }
    } else if (c.name == "geom_object") {
      m.sources.push_back(parse_source(c, geometry));
    } else if (c.name == "tiny_rho") {
      m.tiny_rho = positive(mat, "tiny_rho");
    } else if (c.name == "SpecificHeatModel" || c.name == "gamma" || c.name == "specific_heat" || c.name == "dynamic_viscosity" ||
               c.name == "thermal_conductivity") {
    } else if (c.name == "isSurroundingMatl") {
      m.surrounding = c.as_bool();  // IceSetup.h: recorded; the pressure BC uses the mixture density
    } else if (c.name == "includeFlowWork") {
      if (c.as_bool()) c.missing_feature("ICE material <" + c.name + "> = true");
    } else {
      c.missing_feature("ICE material property <" + c.name + ">");
    }
  }
  if (!m.eos) mat.require_child("EOS");
  if (m.sources.empty()) mat.fail("an ICE material needs at least one <geom_object>");
  return m;
}

// <exchange_coefficients><momentum>/<heat>: the upper triangle K_01, K_02, ...,
// K_12, ... row by row (Uintah's order), n(n-1)/2 values.
std::vector<double> parse_coefficients(const DeckNode* ec, const char* name, int n) {
  std::vector<double> C(static_cast<std::size_t>(n * n), 0.0);
  if (n < 2) return C;
  if (!ec) return C;
  const DeckNode* node = ec->child(name);
  if (!node) ec->fail(std::string("<exchange_coefficients> needs <") + name + ">");
  const std::vector<double> v = node->as_doubles();
  if (v.size() != static_cast<std::size_t>(n * (n - 1) / 2))
    node->fail(std::string("<") + name + "> needs n(n-1)/2 = " + std::to_string(n * (n - 1) / 2) +
               " values for " + std::to_string(n) + " materials");
  std::size_t k = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (v[k] < 0) node->fail(std::string("<") + name + "> values must be >= 0");
      C[a * n + b] = C[b * n + a] = v[k++];
    }
  return C;
}

std::string lower(std::string v) {
  for (char& ch : v) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return v;
}

// <TimestepControl> (Vaango's spelling; Uintah's ICE.cc reads <TimeStepControl>).
void parse_timestep_control(const DeckNode& tc, IceSetup& s) {
  const DeckNode& scheme = tc.require_child("Scheme_for_delT_calc");
  const std::string v = scheme.as_string();
  if (v == "aggressive") s.delt_scheme = DeltScheme::Aggressive;
  else if (v == "conservative") s.delt_scheme = DeltScheme::Conservative;
  else scheme.fail("Scheme_for_delT_calc must be 'aggressive' or 'conservative'");
  const DeckNode& knob = tc.require_child("knob_for_speedSound");
  s.delt_knob = knob.as_double();
  if (!(s.delt_knob >= 0.0 && s.delt_knob <= 1.0)) knob.fail("knob_for_speedSound must be in [0, 1]");
  for (const DeckNode& c : tc.children)
    if (c.name != "Scheme_for_delT_calc" && c.name != "knob_for_speedSound")
      c.missing_feature("<TimestepControl><" + c.name + ">");
}

// <ImplicitSolver> (ice_spec.xml): outer iterations and the hypre parameters.
// Parameters that only tune Uintah's own CG solver (initial_tolerance,
// criteria, norm) or hypre internals Tephra leaves at hypre's defaults (jump,
// logging, setupFrequency) are read and have no effect; docs/algorithms/ice.md says so.
void parse_implicit_solver(const DeckNode& is, IceSetup& s) {
  ImplicitSettings& im = s.implicit;
  im.enabled = true;
  const DeckNode& mo = is.require_child("max_outer_iterations");
  im.max_outer_iterations = mo.as_int();
  if (im.max_outer_iterations < 1) mo.fail("max_outer_iterations must be >= 1");
  const DeckNode& ot = is.require_child("outer_iteration_tolerance");
  im.outer_iteration_tolerance = ot.as_double();
  if (!(im.outer_iteration_tolerance > 0)) ot.fail("outer_iteration_tolerance must be > 0");
  if (const DeckNode* r = is.child("iters_before_timestep_restart")) {
    im.iters_before_timestep_restart = r->as_int();
    if (im.iters_before_timestep_restart < 1) r->fail("iters_before_timestep_restart must be >= 1");
  }
  const DeckNode& p = is.require_child("Parameters");
  if (auto var = p.attribute("variable"); var && *var != "implicitPressure")
    p.fail("<Parameters variable> must be 'implicitPressure'");
  HypreSettings& h = im.hypre;
  for (const DeckNode& c : p.children) {
    if (c.name == "solver") {
      const std::string v = lower(c.as_string());
      if (v == "cg" || v == "gmres" || v == "pfmg" || v == "smg") h.solver = v;
      else if (v == "sparsemsg" || v == "hybrid" || v == "amg") c.missing_feature("hypre solver '" + c.as_string() + "'");
      else c.fail("unknown solver '" + c.as_string() + "' (cg, gmres, pfmg, smg)");
    } else if (c.name == "preconditioner") {
      const std::string v = lower(c.as_string());
      if (v == "none" || v == "pfmg" || v == "smg" || v == "jacobi") h.preconditioner = v;
      else c.fail("unknown preconditioner '" + c.as_string() + "' (none, pfmg, smg, jacobi)");
    } else if (c.name == "tolerance") {
      h.tolerance = c.as_double();
      if (!(h.tolerance > 0)) c.fail("tolerance must be > 0");
    } else if (c.name == "maxiterations") {
      h.max_iterations = c.as_int();
      if (h.max_iterations < 1) c.fail("maxiterations must be >= 1");
    } else if (c.name == "npre") {
      h.npre = c.as_int();
    } else if (c.name == "npost") {
      h.npost = c.as_int();
    } else if (c.name == "skip") {
      h.skip = c.as_int();
    } else if (c.name == "relax_type") {
      h.relax_type = c.as_int();
      if (h.relax_type < 0 || h.relax_type > 3) c.fail("relax_type must be 0..3");
    } else if (c.name == "norm" || c.name == "criteria" || c.name == "initial_tolerance" || c.name == "jump" ||
               c.name == "logging" || c.name == "setupFrequency" || c.name == "outputEquations") {
      // See the comment above: accepted, no effect on the hypre solve.
    } else {
      c.missing_feature("<ImplicitSolver><Parameters><" + c.name + ">");
    }
  }
  if (!p.has_child("solver")) p.fail("<Parameters> needs <solver>");
  if (!p.has_child("tolerance")) p.fail("<Parameters> needs <tolerance>");
  // Uintah's bullet-proofing: the inner tolerance must be below the outer one.
  if (h.tolerance >= im.outer_iteration_tolerance)
    p.require_child("tolerance").fail("the solver <tolerance> must be smaller than <outer_iteration_tolerance>");
  for (const DeckNode& c : is.children)
    if (c.name != "max_outer_iterations" && c.name != "outer_iteration_tolerance" &&
        c.name != "iters_before_timestep_restart" && c.name != "Parameters")
      c.missing_feature("<ImplicitSolver><" + c.name + ">");
}

// Top-level <Solver type=...>: which linear solver runs the pressure
// equation. Everything runs on hypre's structured interface: 'hypre' takes
// <Parameters> as given; 'CGSolver' (Uintah's own Jacobi-preconditioned CG)
// maps to hypre PCG with diagonal scaling; 'direct' maps to PCG with an SMG
// preconditioner (an exact solve to round-off, the purpose of Uintah's
// direct solver on small problems).
void apply_solver_type(const DeckNode& root, IceSetup& s) {
  const DeckNode* sv = root.child("Solver");
  if (!sv) return;
  const std::string type = sv->require_attribute("type");
  if (type == "hypre") return;
  if (type == "hypreamr") sv->missing_feature("Solver type 'hypreamr' (AMR)");
  if (type == "CGSolver") {
    s.implicit.hypre.solver = "cg";
    s.implicit.hypre.preconditioner = "jacobi";
  } else if (type == "direct") {
    s.implicit.hypre.solver = "cg";
    s.implicit.hypre.preconditioner = "smg";
  } else {
    sv->fail("unknown Solver type '" + type + "' (CGSolver, direct, hypre)");
  }
}

void parse_cfd(const DeckNode& root, IceSetup& s) {
  const DeckNode& cfd = root.require_child("CFD");
  for (const DeckNode& c : cfd.children) {
    if (c.name == "cfl") {
      s.cfl = c.as_double();
      // Uintah accepts any positive cfl. Above the stable limit (docs/algorithms/ice.md:
      // Sod is stable to 1.0 with the aggressive step) the run stops with exit 4
      // when a cell would lose more than its content (check_outflux) or the
      // state turns non-physical (check_state).
      if (!(s.cfl > 0.0)) c.fail("cfl must be > 0");
      if (s.cfl > 1.0) log::warning(c.location().str() + ": cfl " + std::to_string(s.cfl) + " > 1 is beyond the stability limit of explicit ICE");
    } else if (c.name == "ICE") {
      for (const DeckNode& i : c.children) {
        if (i.name == "advection") {
          const std::string type = i.require_attribute("type");
          if (type == "FirstOrder") s.advection = AdvectionOrder::First;
          else if (type == "SecondOrder") s.advection = AdvectionOrder::Second;
          else if (type == "FirstOrderGPU") i.missing_feature("advection type 'FirstOrderGPU'");
          else i.fail("unknown advection type '" + type + "' (FirstOrder, SecondOrder)");
          for (const char* a : {"useCompatibleFluxes", "compatibleFluxes"})
            if (auto v = i.attribute(a); v && *v != "true")
              i.missing_feature(std::string("advection ") + a + "=\"" + *v + "\" (Tephra always uses compatible fluxes)");
        } else if (i.name == "max_iteration_equilibration") {
          s.max_iter_equilibration = i.as_int();
          if (s.max_iter_equilibration < 1) i.fail("max_iteration_equilibration must be >= 1");
        } else if (i.name == "TimestepControl") {
          parse_timestep_control(i, s);
        } else if (i.name == "ImplicitSolver") {
          parse_implicit_solver(i, s);
        } else if (i.name == "ClampSpecificVolume") {
          s.clamp_sp_vol = i.as_bool();
        } else if (i.name == "conserveTotalEnergy") {
          s.conserve_total_energy = i.as_bool();
        } else if (i.name == "ADD_HEAT") {
          // read with the models (ice/models/FluidModels.cpp)
        } else {
          i.missing_feature("<CFD><ICE><" + i.name + ">");
        }
      }
    } else if (c.name == "CanAddICEMaterial") {
      if (c.as_bool()) c.missing_feature("<CanAddICEMaterial> true");
    } else {
      c.missing_feature("<CFD><" + c.name + ">");
    }
  }
  if (!cfd.has_child("cfl")) cfd.fail("<CFD> needs <cfl>");
  const DeckNode& ice = cfd.require_child("ICE");
  ice.require_child("advection");
  // Uintah: the speed-of-sound knob defaults to 0.5 when running implicit.
  if (s.implicit.enabled && !ice.has_child("TimestepControl")) s.delt_knob = 0.5;
  if (s.implicit.enabled) apply_solver_type(root, s);
}

IceFaceBc resolve(const BoundaryConditions& bcs, GridFace face, int m, const char* label, const DeckNode& grid_node) {
  IceFaceBc out;
  const BoundaryCondition* bc = bcs.find(face, m, label);
  if (!bc) bc = bcs.find(face, m, "Symmetric");
  if (!bc) {
    for (const BoundaryCondition* b : bcs.on_face(face, m))
      if (b->kind == BCKind::Symmetry) bc = b;
  }
  if (!bc)
    grid_node.fail(std::string("ICE material ") + std::to_string(m) + " has no boundary condition for label '" +
                   label + "' on face " + face_name(face));
  if (bc->region.kind != FaceRegion::Side)
    throw MissingFeature(bc->where, "ICE boundary conditions on part of a face (circle, rectangle, ...)");
  out.kind = bc->kind;
  switch (bc->kind) {
    case BCKind::Symmetry: return out;
    case BCKind::Dirichlet:
    case BCKind::Neumann:
      if (!bc->has_value) throw DeckError(bc->where, std::string("a ") + bc_kind_name(bc->kind) + " condition needs a <value>");
      out.scalar = bc->scalar;
      out.vector = bc->vector;
      if (std::string(label) == "Velocity" && !bc->is_vector)
        throw DeckError(bc->where, "a Velocity condition needs a vector <value> [u, v, w]");
      if (std::string(label) != "Velocity" && bc->is_vector)
        throw DeckError(bc->where, std::string("a ") + label + " condition needs a scalar <value>");
      return out;
    case BCKind::LODI:
      if (std::string(label) == "SpecificVol")
        throw DeckError(bc->where, "LODI is not a SpecificVol condition (use computeFromDensity)");
      return out;
    case BCKind::ComputeFromDensity:
      if (std::string(label) != "SpecificVol")
        throw MissingFeature(bc->where, std::string("computeFromDensity for label '") + label + "' (only SpecificVol)");
      return out;
    default:
      throw MissingFeature(bc->where, std::string("ICE boundary condition var=\"") + bc_kind_name(bc->kind) + "\"");
  }
}

// <LODI> (Uintah's read_LODI_BC_inputs): press_infinity required, sigma
// default 0.27, Li_scale default 1, material by name or index. Uintah's
// checks: a LODI face needs the block; the Pressure condition belongs to
// material 0; the other LODI labels to the LODI material.
void read_lodi(const BoundaryConditions& bcs, IceSetup& s) {
  const BoundaryCondition* first = nullptr;
  for (const BoundaryCondition& b : bcs.list) {
    if (b.kind != BCKind::LODI) continue;
    if (!first) first = &b;
    if (b.material == kAllMaterials)
      throw DeckError(b.where, "a LODI condition needs the material's id, not id=\"all\" (Uintah)");
  }
  if (!first) {
    if (bcs.lodi) log::warning(bcs.lodi->where.str() + ": <LODI> block but no face uses var=\"LODI\"; ignored");
    return;
  }
  if (!bcs.lodi) throw DeckError(first->where, "var=\"LODI\" needs a <LODI> block in <BoundaryConditions>");
  if (s.implicit.enabled) throw MissingFeature(first->where, "LODI boundary conditions with <ImplicitSolver>");
  const LodiParameters& lp = *bcs.lodi;
  LodiSettings& L = s.lodi;
  L.enabled = true;
  L.press_infinity = lp.press_infinity;
  L.sigma = lp.sigma;
  if (lp.li_scale) L.li_scale = *lp.li_scale;
  if (!(L.press_infinity > 0)) throw DeckError(lp.where, "<LODI><press_infinity> must be > 0");
  if (!(L.sigma >= 0)) throw DeckError(lp.where, "<LODI><sigma> must be >= 0");
  L.material = -1;
  for (std::size_t m = 0; m < s.materials.size(); ++m)
    if (s.materials[m].name == lp.material) L.material = int(m);
  if (L.material < 0) {
    char* end = nullptr;
    const long v = std::strtol(lp.material.c_str(), &end, 10);
    if (end && *end == '\0' && !lp.material.empty() && v >= 0 && v < long(s.materials.size())) L.material = int(v);
  }
  if (L.material < 0) throw DeckError(lp.where, "<LODI><material> '" + lp.material + "' is not an ICE material");
  for (const BoundaryCondition& b : bcs.list) {
    if (b.kind != BCKind::LODI) continue;
    if (b.label == "Pressure" && b.material != 0)
      throw DeckError(b.where, "the LODI Pressure condition must have id=\"0\" (Uintah)");
    if (b.label != "Pressure" && b.material != L.material)
      throw DeckError(b.where, "LODI conditions must belong to the <LODI> material " + std::to_string(L.material));
  }
}

}  // namespace

std::vector<std::string> ice_advection_types() { return {"FirstOrder", "SecondOrder"}; }

std::unique_ptr<IceComponent> make_ice_component(const Deck& deck) {
  if (const DeckNode* mpm = deck.root.require_child("MaterialProperties").child("MPM"))
    mpm->missing_feature("MPM materials in an ICE run (use mpmice)");
  return std::make_unique<IceComponent>(read_ice_setup(deck, {}));
}

IceSetup read_ice_setup(const Deck& deck, std::vector<IceMaterialSpec> solids, const IceModelFactories& models) {
  const DeckNode& root = deck.root;
  IceSetup s;
  s.materials = std::move(solids);
  const DeckNode& grid_node = root.require_child("Grid");
  s.grid = make_grid(grid_node);
  // A periodic direction has no extra cells (make_grid enforces it): its
  // ghosts are filled by the halo exchange's periodic wrap, and no boundary
  // condition is read for its two faces.
  for (int d = 0; d < 3; ++d) {
    if (!s.grid.periodic[d] && s.grid.extra_cells[d] != 1)
      grid_node.missing_feature("ICE with extraCells != 1 in a non-periodic direction (ICE needs exactly one layer "
                                "of extra cells)");
  }
  parse_cfd(root, s);
  if (const DeckNode* pc = root.child("PhysicalConstants")) {
    s.gravity = pc->get_vec3("gravity", Vec3::Zero());
    s.reference_pressure = pc->get_double("reference_pressure", 101325.0);
  }

  const DeckNode& props = root.require_child("MaterialProperties");
  const DeckNode& ice = props.require_child("ICE");
  GeometryRegistry geometry;
  // MPMICE: geometry labels are deck-wide (Uintah), so an ICE geom_object may
  // refer to a piece labelled in an MPM material: read those first.
  if (!s.materials.empty())
    if (const DeckNode* mpm = props.child("MPM"))
      for (const DeckNode& mat : mpm->children)
        if (mat.name == "material")
          for (const DeckNode& go : mat.children)
            if (go.name == "geom_object") geometry.parse_geom_object(go);
  for (const DeckNode& c : ice.children) {
    if (c.name == "material") {
      s.materials.push_back(parse_material(c, int(s.materials.size()), geometry));
      if (s.materials.back().surrounding) {
        // Uintah silently keeps the last one; two background materials is a deck error.
        if (s.surrounding_material >= 0)
          c.require_child("isSurroundingMatl").fail("a second ICE material with <isSurroundingMatl> true (material " +
                                                    std::to_string(s.surrounding_material) + " is already the surrounding material)");
        s.surrounding_material = int(s.materials.size()) - 1;
      }
    } else {
      c.missing_feature("<MaterialProperties><ICE><" + c.name + ">");
    }
  }
  if (s.materials.empty() ||
      std::none_of(s.materials.begin(), s.materials.end(), [](const IceMaterialSpec& m) { return !m.lagrangian; }))
    ice.fail("<MaterialProperties><ICE> has no <material>");
  if (s.materials.size() > std::size_t(kMaxExchangeMaterials))
    ice.missing_feature("more than 16 materials in the exchange (MPM + ICE)");

  const int n = int(s.materials.size());
  const DeckNode* ec = nullptr;
  if (const DeckNode* ep = props.child("exchange_properties")) {
    for (const DeckNode& c : ep->children) {
      if (c.name == "exchange_coefficients") {
        ec = &c;
        for (const DeckNode& k : c.children)
          if (k.name != "momentum" && k.name != "heat") k.missing_feature("<exchange_coefficients><" + k.name + ">");
      } else if (c.name == "heatExchangeCoeff") {  // Uintah: constant (default) or variable
        const std::string model = lower(c.text);
        if (model == "variable") s.variable_heat_exchange = true;
        else if (model != "constant") c.fail("<heatExchangeCoeff> must be 'constant' or 'variable'");
      } else {
        c.missing_feature("<exchange_properties><" + c.name + ">");
      }
    }
  }
  if (n > 1 && !ec) props.fail("two or more materials need <exchange_properties><exchange_coefficients>");
  s.K = parse_coefficients(ec, "momentum", n);
  // variable: the per-cell coefficients replace <heat>, which Uintah then does not read.
  s.H = s.variable_heat_exchange ? std::vector<double>(std::size_t(n * n), 0.0) : parse_coefficients(ec, "heat", n);

  const BoundaryConditions bcs = parse_boundary_conditions(grid_node);
  if (bcs.sine || bcs.micro_slip)
    grid_node.require_child("BoundaryConditions").missing_feature("ICE sine / micro-slip boundary conditions");
  static const char* labels[kBcLabels] = {"Pressure", "Velocity", "Temperature", "Density", "SpecificVol"};
  for (const BoundaryCondition& b : bcs.list) {
    if (b.material != kAllMaterials && (b.material < 0 || b.material >= n))
      throw DeckError(b.where, "boundary condition for material " + std::to_string(b.material) + " but the deck has " +
                          std::to_string(n) + " ICE material(s)");
    const bool known = b.label == "Symmetric" ||
                       std::find(std::begin(labels), std::end(labels), b.label) != std::end(labels);
    if (!known) throw MissingFeature(b.where, "ICE boundary condition label '" + b.label + "'");
  }
  s.bcs.resize(n);
  for (int m = 0; m < n; ++m)
    for (int f = 0; f < 6; ++f) {
      if (s.grid.periodic[face_axis(static_cast<GridFace>(f))]) continue;  // default IceFaceBc: never applied
      for (int l = 0; l < kBcLabels; ++l) {
        // Pressure is one field shared by all materials: Uintah reads its BC
        // from material 0 (or id="all").
        const int mat = l == kBcPressure ? 0 : m;
        s.bcs[m][f][l] = resolve(bcs, static_cast<GridFace>(f), mat, labels[l], grid_node);
      }
    }
  s.models = parse_ice_models(root, s, models);
  read_lodi(bcs, s);
  read_ice_axisymmetric(root, s);  // <MPM><axisymmetric> (ice/IceAxisymmetricDeck.h)
  return s;
}

}  // namespace tephra
