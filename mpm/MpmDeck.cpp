// make_mpm_component: the MPM parts of a deck -> an MpmComponent.
#include <algorithm>

#include "core/base/Log.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "core/geometry/GeometryPiece.h"
#include "mpm/DeckModelParameters.h"
#include "models/solid/CnhMms.h"
#include "mpm/MpmComponent.h"
#include "mpm/MpmDeckDrivers.h"
#include "mpm/mms/ManufacturedSolution.h"

namespace tephra {

namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

ConstitutiveModelP parse_constitutive_model(const DeckNode& cm) {
  const std::string type = cm.require_attribute("type");
  DeckModelParameters params(cm);
  ConstitutiveModelP model = create_constitutive_model(type, params);
  if (!model) {
    const auto& vaango = vaango_constitutive_model_types();
    if (std::find(vaango.begin(), vaango.end(), type) != vaango.end())
      cm.missing_feature("constitutive_model type '" + type + "' (implemented: " +
                         join(constitutive_model_types()) + ")");
    cm.fail("unknown constitutive_model type '" + type + "' (implemented: " + join(constitutive_model_types()) +
            ")");
  }
  // Read by parse_material (mpm/loads/BodyForceStress.h), not by the model.
  params.has("initialize_with_body_force");
  params.has("surface_reference_point");
  params.check_all_used("constitutive_model type '" + type + "'");
  return model;
}

ParticleSource parse_geom_object(const DeckNode& go, GeometryRegistry& geometry) {
  ParticleSource s;
  s.piece = geometry.parse_geom_object(go);
  s.res = go.get_int_vec3("res");
  if ((s.res.array() < 1).any()) go.require_child("res").fail("res must be >= 1 in every direction");
  s.velocity = go.get_vec3("velocity");
  s.temperature = go.get_double("temperature");
  s.color = go.get_double("color", 0.0);
  // Uintah's ParticleCreator gives a particle the mass rho0 V volumeFraction
  // (absent or -1: rho0 V). Only the value that changes nothing is read.
  if (const DeckNode* vf = go.child("volumeFraction")) {
    const double v = vf->as_double();
    if (v != 1.0 && v != -1.0)
      vf->missing_feature("MPM <geom_object><volumeFraction> other than 1 (Uintah's particle mass rho0 V volumeFraction)");
  }
  return s;
}

MpmMaterial parse_material(const DeckNode& mat, int index, GeometryRegistry& geometry) {
  MpmMaterial m;
  m.index = index;
  for (const DeckNode& c : mat.children) {
    if (c.name == "density") {
      m.density = c.as_double();
      if (!(m.density > 0.0)) c.fail("density must be > 0");
    } else if (c.name == "constitutive_model") {
      if (m.model) c.fail("a material has one <constitutive_model>");
      if (c.get_bool("initialize_with_body_force", false)) {
        // Eq. (2) of mpm/loads/BodyForceStress.h is isotropic linear elasticity.
        const std::string type = c.require_attribute("type");
        if (type != "hypo_elastic" && type != "comp_neo_hook" && type != "comp_mooney_rivlin")
          c.require_child("initialize_with_body_force")
              .missing_feature("<initialize_with_body_force> for constitutive_model type '" + type +
                               "' (implemented: hypo_elastic, comp_neo_hook, comp_mooney_rivlin)");
        m.body_force_surface = c.get_vec3("surface_reference_point");
      } else if (c.has_child("surface_reference_point")) {
        c.require_child("surface_reference_point").fail("<surface_reference_point> needs <initialize_with_body_force>true");
      }
      m.model = parse_constitutive_model(c);
    } else if (c.name == "thermal_conductivity") {
      m.thermal_conductivity = c.as_double();
    } else if (c.name == "specific_heat") {
      m.specific_heat = c.as_double();
    } else if (c.name == "C_p") {
      // Vaango's MPMMaterial: C_p, default = specific_heat (taken as C_v).
      // Stored; the MPM and MPMICE energy equations use specific_heat.
      m.specific_heat_p = c.as_double();
      if (!(m.specific_heat_p > 0.0)) c.fail("C_p must be > 0");
    } else if (c.name == "melt_temp" || c.name == "room_temp") {
      // Vaango's MPMMaterial T_melt and T_room: read by models with melting or
      // thermal terms; none of the implemented models uses them.
      const double T = c.as_double();
      if (!(T > 0.0)) c.fail(c.name + " must be > 0 K");
      (c.name == "melt_temp" ? m.melt_temperature : m.room_temperature) = T;
    } else if (c.name == "geom_object") {
      m.sources.push_back(parse_geom_object(c, geometry));
    } else if (c.name == "is_rigid" || c.name == "includeFlowWork" || c.name == "do_basic_damage") {
      if (c.as_bool()) c.missing_feature("MPM material <" + c.name + "> = true");
    } else {
      c.missing_feature("MPM material property <" + c.name + ">");
    }
  }
  if (!m.model) mat.fail("an MPM material needs a <constitutive_model>");
  if (!mat.has_child("density")) mat.fail("an MPM material needs a <density>");
  if (!mat.has_child("thermal_conductivity")) mat.fail("an MPM material needs a <thermal_conductivity>");
  if (!mat.has_child("specific_heat")) mat.fail("an MPM material needs a <specific_heat>");
  if (!mat.has_child("C_p")) m.specific_heat_p = m.specific_heat;
  if (m.sources.empty()) mat.fail("an MPM material needs at least one <geom_object>");
  return m;
}

// <run_MMS_problem>: every material must be cnh_mms (the body forces are
// derived for its stress law).
void attach_manufactured_solution(const DeckNode& mpm_flags, MpmSetup& setup) {
  const DeckNode& node = mpm_flags.require_child("run_MMS_problem");
  const auto& vaango = vaango_mms_names();
  const std::string& name = setup.flags.mms;
  if (std::find(vaango.begin(), vaango.end(), name) == vaango.end())
    node.fail("unknown run_MMS_problem '" + name + "' (Vaango's: " + join(vaango) + ")");
  for (MpmMaterial& m : setup.materials) {
    const auto* cnh = dynamic_cast<const CnhMms*>(m.model.get());
    if (!cnh)
      node.fail("run_MMS_problem '" + name + "' needs constitutive_model type 'cnh_mms' (its body force is "
                "derived for that stress law); material " + std::to_string(m.index) + " is '" +
                m.model->type() + "'");
    m.mms = make_mms(name, cnh->params(), m.density);
    if (!m.mms)
      node.missing_feature("run_MMS_problem '" + name + "' (implemented: " + join(implemented_mms_names()) + ")");
  }
}

}  // namespace

std::unique_ptr<MpmComponent> make_mpm_component(const Deck& deck) {
  const DeckNode& root = deck.root;
  MpmSetup setup;
  const DeckNode& grid_node = root.require_child("Grid");
  setup.grid = make_grid(grid_node);

  setup.flags = parse_mpm_flags(root.child("MPM"));
  // Loads, prescribed deformation, AccStrainEnergy, axisymmetric and periodic options (mpm/MpmDeckDrivers.cpp).
  read_loads_and_drivers(deck, setup);
  // GIMP, CPDI and quadratic B-spline supports reach past the particle's
  // cell: a particle near a domain face weights the node layer of the extra
  // cells. (4thorderBS does not: its face-modified splines stay inside.) A
  // periodic direction has ghost node layers instead (mpm/PeriodicGrid.h).
  const InterpolatorKind kind = setup.flags.interpolator.kind;
  if (kind != InterpolatorKind::Linear && kind != InterpolatorKind::CubicBspline &&
      (setup.grid.extra_cells.array() < 1 && setup.grid.periodic.array() == 0).any())
    grid_node.fail("the MPM interpolator '" + interpolator_name(setup.flags.interpolator.kind) +
                   "' needs <extraCells> >= 1 in every direction (its support reaches the node layer "
                   "outside the domain)");
  if (const DeckNode* pc = root.child("PhysicalConstants")) setup.gravity = pc->get_vec3("gravity", Vec3::Zero());

  const DeckNode& props = root.require_child("MaterialProperties");
  const DeckNode& mpm = props.require_child("MPM");
  GeometryRegistry geometry;
  for (const DeckNode& c : mpm.children)
    if (c.name == "material") setup.materials.push_back(parse_material(c, int(setup.materials.size()), geometry));
  // Axisymmetric particles (mpm/Axisymmetric.cpp, Vaango's rule): each holds
  // r dx dy / (res_x res_y) per radian whatever its z, so <res> z > 1 seeds
  // that many full radians and the material's mass is res_z x rho V, in
  // Vaango as here. A deck converted from a planar one ([2,2,2]) rarely
  // means it: warn, naming the element.
  if (setup.flags.axisymmetric)
    for (const MpmMaterial& m : setup.materials)
      for (const ParticleSource& src : m.sources)
        if (src.res[2] != 1)
          log::warning(mpm.file + ":" + std::to_string(mpm.line) + ": axisymmetric MPM: material " +
                       std::to_string(m.index) + " has a <geom_object> with <res> z = " + std::to_string(src.res[2]) +
                       ": each z-layer carries a full radian (Vaango's rule), so its mass is " +
                       std::to_string(src.res[2]) + " x rho V; use <res> [nx, ny, 1]");
  for (const DeckNode& c : mpm.children) {
    if (c.name == "material") {
      continue;
    } else if (c.name == "contact") {
      ContactModelP model = parse_contact(c, int(setup.materials.size()));
      if (model && setup.contact)
        c.missing_feature("a second non-null <contact> model (Vaango's composite contact)");
      if (model) setup.contact = std::move(model);
    } else if (c.name == "thermal_contact") {
      setup.thermal_contact = true;  // Vaango STThermalContact (mpm/thermal/HeatConduction.h)
    } else {
      c.missing_feature("<MaterialProperties><MPM><" + c.name + ">");
    }
  }
  if (setup.materials.empty()) mpm.fail("<MaterialProperties><MPM> has no <material>");
  // Friction heating divides the frictional work by c_v m_g (mpm/contact/FrictionHeating.h).
  if (setup.flags.contact_friction_heating)
    for (const DeckNode& c : mpm.children)
      if (c.name == "material" && !(c.get_double("specific_heat") > 0.0))
        c.require_child("specific_heat").fail("<do_contact_friction_heating>true needs specific_heat > 0");
  check_driver_combinations(deck, setup);
  for (MpmMaterial& m : setup.materials)
    m.bcs = parse_grid_boundary_conditions(grid_node.child("BoundaryConditions"), m.index);
  for (MpmMaterial& m : setup.materials)
    m.bcs.set_extra_nodes = setup.flags.interpolator.kind != InterpolatorKind::Linear;
  if (!setup.flags.mms.empty()) attach_manufactured_solution(root.require_child("MPM"), setup);
  check_body_force_stress(deck, setup);
  return std::make_unique<MpmComponent>(std::move(setup));
}

}  // namespace tephra
