#include "mpm/MpmFlags.h"

#include <map>
#include <sstream>
#include <string>

#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

// Flags whose value cannot change what this slice computes (output-only
// flags, thermal flags while no implemented model depends on temperature,
// limits that only act on states the run stops on anyway). Accepted with any
// valid value.
const char* const kNoEffect[] = {
    "withColor", "computeScaleFactor", "computeNodalHeatFlux",
    "DoTransientImplicitHeatConduction", "DoThermalExpansion",
    "interpolateParticleTempToGridEveryStep",
    "min_grid_level", "max_grid_level",
    "CanAddMPMMaterial",
};

// Flags of Vaango's implicit integrator (ImpMPM) that its explicit SerialMPM
// never reads, so they cannot change an explicit run (the implicit integrator
// itself is a MissingFeature): <dynamic>, <solver>, the Newton convergence
// criteria, <do_implicit_heat_conduction>, and <do_grid_reset>. The last one
// matters to ImpMPM only (false: the grid nodes follow the displacement);
// Vaango's explicit SerialMPM reads it in problemSetup and uses it for nothing
// but an unused initial gDisplacement label, and resets the grid every step
// (docs/models/plasticity.md, "Deck A4").
const char* const kImplicitOnly[] = {
    "dynamic", "solver", "convergence_criteria_disp", "convergence_criteria_energy",
    "do_implicit_heat_conduction", "do_grid_reset",
};

// Flags that change the physics, with Vaango's default (MPMFlags). Accepted
// only with the default value.
const std::map<std::string, std::string>& physics_defaults() {
  static const std::map<std::string, std::string> table = {
      {"time_integrator", "explicit"},
      {"create_new_particles", "false"},
      {"manual_new_material", "false"},
      {"DoImplicitHeatConduction", "false"},
      {"UseGradientEnhancedVelocityProjection", "false"},
      {"InsertParticles", "false"},
      {"minimum_mass_for_acc", "0"},
      {"use_CBDI_boundary_condition", "false"},
      {"AMR", "false"},
  };
  return table;
}

// True when `text` denotes the same value as the default `def` (booleans and
// numbers compared by value, anything else as text).
bool equals_default(const std::string& text, const std::string& def) {
  if (auto b = parse_bool(def)) {
    auto t = parse_bool(text);
    return t && *t == *b;
  }
  if (auto d = parse_double(def)) {
    auto t = parse_double(text);
    return t && *t == *d;
  }
  return text == def;
}

}  // namespace

MpmFlags parse_mpm_flags(const DeckNode* mpm) {
  MpmFlags flags;
  if (!mpm) return flags;
  for (const DeckNode& c : mpm->children) {
    bool no_effect = false;
    for (const char* n : kNoEffect) no_effect = no_effect || c.name == n;
    for (const char* n : kImplicitOnly) no_effect = no_effect || c.name == n;
    if (no_effect) continue;

    if (c.name == "boundary_traction_faces") {
      // A list of Vaango face names, "[zminus,zplus]".
      std::string list = c.text;
      for (char& ch : list)
        if (ch == '[' || ch == ']' || ch == ',') ch = ' ';
      std::istringstream words(list);
      static const char* faces[6] = {"xminus", "xplus", "yminus", "yplus", "zminus", "zplus"};
      for (std::string w; words >> w;) {
        int f = 0;
        while (f < 6 && w != faces[f]) ++f;
        if (f == 6) c.fail("boundary_traction_faces: '" + w + "' is not one of xminus, xplus, yminus, yplus, zminus, zplus");
        flags.boundary_traction_faces.push_back(f);
      }
      continue;
    }

    if (c.name == "time_integrator") {
      if (c.text == "explicit") continue;
      if (c.text == "implicit" || c.text == "fracture")
        c.missing_feature("MPM time_integrator '" + c.text + "' (only explicit is implemented)");
      c.fail("time_integrator must be explicit, implicit or fracture, not '" + c.text + "'");
    }
    if (c.name == "interpolator") {
      bool found = false;
      // cpgimp (contiguous-particle GIMP, theory manual eq. 1.93) is Tephra's
      // addition: Vaango's gimp keeps the particle domain at its initial size.
      for (InterpolatorKind k : {InterpolatorKind::Linear, InterpolatorKind::Gimp, InterpolatorKind::Cpdi,
                                 InterpolatorKind::QuadraticBspline, InterpolatorKind::CpGimp, InterpolatorKind::Cpti,
                                 InterpolatorKind::CubicBspline})
        if (c.text == interpolator_name(k)) {
          flags.interpolator.kind = k;
          found = true;
        }
      if (found) continue;
      static const char* known[] = {"fast_cpdi", "axisym_cpdi", "axisym_cpti",
                                    "axisym_linear", "axisym_gimp", "fast_axisym_cpdi"};
      for (const char* k : known)
        if (c.text == k)
          c.missing_feature("MPM interpolator '" + c.text +
                            "' (implemented: linear, gimp, cpdi, cpti, 3rdorderBS, 4thorderBS, cpgimp)");
      c.fail("unknown MPM interpolator '" + c.text +
             "' (implemented: linear, gimp, cpdi, cpti, 3rdorderBS, 4thorderBS, cpgimp)");
    }
    if (c.name == "cpdi_lcrit") {
      flags.interpolator.cpdi_lcrit = c.as_double();
      if (!(flags.interpolator.cpdi_lcrit > 0.0)) c.fail("cpdi_lcrit must be > 0");
      continue;
    }
    if (c.name == "run_MMS_problem") {
      // Checked against the implemented solutions in make_mpm_component.
      if (c.text != "none") flags.mms = c.text;
      continue;
    }
    if (c.name == "artificial_viscosity") { flags.artificial_viscosity = c.as_bool(); continue; }
    if (c.name == "artificial_viscosity_heating") { flags.artificial_viscosity_heating = c.as_bool(); continue; }
    if (c.name == "use_load_curves") { flags.use_load_curves = c.as_bool(); continue; }
    // mpm/loads/BodyForceStress.h; the materials opt in (checked in make_mpm_component).
    if (c.name == "initialize_stress_using_body_force") {
      flags.initialize_stress_using_body_force = c.as_bool();
      continue;
    }
    if (c.name == "axisymmetric") { flags.axisymmetric = c.as_bool(); continue; }
    if (c.name == "do_contact_friction_heating") { flags.contact_friction_heating = c.as_bool(); continue; }
    if (c.name == "collinear_bimaterial_contact_normals") {
      flags.collinear_contact_normals = c.as_bool();
      continue;
    }
    if (c.name == "test_for_neg_temps_mpm" || c.name == "testForNegTemps_mpm") {
      flags.test_for_negative_temperatures = c.as_bool();
      continue;
    }
    if (c.name == "use_prescribed_deformation" || c.name == "UsePrescribedDeformation") {
      flags.use_prescribed_deformation = c.as_bool();
      continue;
    }
    // The file is read in make_mpm_component; the exact increment is always
    // used (mpm/PrescribedDeformation.h), so <exact_deformation> has no effect.
    if (c.name == "prescribed_deformation_file") continue;
    // Read in make_mpm_component (mpm/loads/RotatingFrame.h).
    if (c.name == "rotating_coordinate_system") continue;
    if (c.name == "exact_deformation" || c.name == "exactDeformation") { c.as_bool(); continue; }
    if (c.name == "do_explicit_heat_conduction" || c.name == "DoExplicitHeatConduction") {
      flags.explicit_heat_conduction = c.as_bool();
      continue;
    }
    if (c.name == "minimum_particle_mass" || c.name == "maximum_particle_velocity") {
      const double v = c.as_double();
      if (!(v > 0.0)) c.fail(c.name + " must be > 0");
      (c.name == "minimum_particle_mass" ? flags.minimum_particle_mass : flags.maximum_particle_velocity) = v;
      continue;
    }
    if (c.name == "do_pressure_stabilization" || c.name == "DoPressureStabilization") {
      flags.pressure_stabilization = c.as_bool();
      continue;
    }
    if (c.name == "delete_rogue_particles") { flags.delete_rogue_particles = c.as_bool(); continue; }
    if (c.name == "artificial_damping_coeff") {
      flags.artificial_damping_coeff = c.as_double();
      if (!(flags.artificial_damping_coeff >= 0.0)) c.fail("artificial_damping_coeff must be >= 0");
      continue;
    }
    if (c.name == "artificial_viscosity_coeff1" || c.name == "artificial_viscosity_coeff2") {
      const double a = c.as_double();
      if (!(a >= 0.0)) c.fail(c.name + " must be >= 0");
      (c.name == "artificial_viscosity_coeff1" ? flags.artificial_viscosity_coeff1
                                               : flags.artificial_viscosity_coeff2) = a;
      continue;
    }
    if (c.name == "erosion") {
      // <erosion algorithm="none"/>
      const std::string alg = c.attribute("algorithm").value_or("none");
      if (!erosion_algorithm_from_name(alg, flags.erosion))
        c.missing_feature("MPM erosion algorithm '" + alg +
                          "' (implemented: none, ZeroStress, AllowNoTension, AllowNoShear, KeepStress)");
      continue;
    }
    if (c.name == "deformation_gradient") {
      // <deformation_gradient algorithm="taylor_series"> <num_terms>5</num_terms> </deformation_gradient>
      const std::string alg = c.attribute("algorithm").value_or("first_order");
      if (alg != "first_order" && alg != "subcycling" && alg != "taylor_series" && alg != "cayley_hamilton")
        c.fail("deformation_gradient algorithm must be first_order, subcycling, taylor_series or cayley_hamilton, not '" +
               alg + "'");
      flags.deformation_gradient = alg;
      for (const DeckNode& t : c.children) {
        if (t.name != "num_terms") t.fail("unknown element <" + t.name + "> in <deformation_gradient> (known: num_terms)");
        flags.deformation_gradient_terms = t.as_int();
        if (flags.deformation_gradient_terms < 1 || flags.deformation_gradient_terms > 20)
          t.fail("num_terms must be in [1, 20]");
      }
      continue;
    }
    auto it = physics_defaults().find(c.name);
    if (it == physics_defaults().end())
      c.missing_feature("MPM flag <" + c.name + ">");
    if (!equals_default(c.text, it->second))
      c.missing_feature("MPM flag <" + c.name + "> = '" + c.text + "' (only the default '" + it->second +
                        "' is implemented)");
  }
  // Vaango (MPMFlags::readMPMFlags): <artificial_viscosity>true turns the
  // heating on unless <artificial_viscosity_heating> says otherwise, and
  // heating without the viscosity is an input error.
  const DeckNode* heating = mpm->child("artificial_viscosity_heating");
  if (!heating) flags.artificial_viscosity_heating = flags.artificial_viscosity;
  else if (flags.artificial_viscosity_heating && !flags.artificial_viscosity)
    heating->fail("artificial_viscosity_heating needs <artificial_viscosity>true");
  return flags;
}

}  // namespace tephra
