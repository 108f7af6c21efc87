#include "mpm/MpmDeckDrivers.h"

#include <optional>
#include <string>

#include "core/base/Log.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "mpm/Axisymmetric.h"
#include "mpm/MpmComponent.h"

namespace tephra {

void read_loads_and_drivers(const Deck& deck, MpmSetup& setup) {
  const DeckNode& root = deck.root;
  // <PhysicalBC><MPM>: pressure (with <use_load_curves>) and force loads (mpm/loads/ParticleLoads.h).
  setup.loads = parse_particle_loads(root.child("PhysicalBC"), setup.flags.use_load_curves);
  if (!setup.loads.empty() && !setup.flags.mms.empty())
    root.require_child("PhysicalBC").missing_feature("<PhysicalBC> loads together with <run_MMS_problem>");
  // The loads flag particles by X = x - u, which a periodic wrap of x breaks.
  if (!setup.loads.empty() && (setup.grid.periodic.array() != 0).any())
    root.require_child("PhysicalBC").missing_feature("<PhysicalBC> loads with <periodic>");
  // Axisymmetric runs: per-radian pressure loads on <axisymmetric_side> and
  // <axisymmetric_end> cylinders (mpm/loads/ParticleLoads.h); force densities
  // (per kg) and velocity surfaces need no area. Other surfaces' areas are
  // not per radian: exit 3. An axisymmetric surface in a Cartesian run: DeckError.
  for (const PressureSurface& s : setup.loads.pressure) {
    const bool axi = s.kind == PressureSurface::Kind::AxiSide || s.kind == PressureSurface::Kind::AxiEnd;
    if (setup.flags.axisymmetric && !axi)
      root.require_child("PhysicalBC").missing_feature(
          "a <pressure> surface other than an <axisymmetric_side> or <axisymmetric_end> cylinder with <axisymmetric>");
    if (!setup.flags.axisymmetric && axi)
      root.require_child("PhysicalBC").fail(
          "<axisymmetric_side> / <axisymmetric_end> pressure surfaces need <MPM><axisymmetric>true");
  }
  if (setup.flags.axisymmetric && (!setup.loads.heat_flux.empty() || !setup.loads.moment.empty()))
    root.require_child("PhysicalBC").missing_feature("<heat_flux> or <moment> loads with <axisymmetric>");
  // <rotating_coordinate_system> (mpm/loads/RotatingFrame.h): Cartesian, non-periodic, no MMS.
  if (const DeckNode* mpm_flags = root.child("MPM"))
    if (const DeckNode* rot = mpm_flags->child("rotating_coordinate_system")) {
      setup.rotating_frame = parse_rotating_frame(*rot);
      if (setup.flags.axisymmetric) rot->missing_feature("a rotating coordinate system with <axisymmetric>");
      if ((setup.grid.periodic.array() != 0).any()) rot->missing_feature("a rotating coordinate system with <periodic>");
      if (!setup.flags.mms.empty()) rot->missing_feature("a rotating coordinate system with <run_MMS_problem>");
    }
  if (setup.flags.use_prescribed_deformation) {
    const DeckNode& mpm_flags = root.require_child("MPM");
    if (setup.flags.axisymmetric)
      mpm_flags.require_child("axisymmetric").missing_feature("axisymmetric MPM with a prescribed deformation");
    if (setup.flags.deformation_gradient != "first_order")
      mpm_flags.require_child("deformation_gradient")
          .missing_feature("a prescribed deformation with deformation_gradient algorithm '" +
                           setup.flags.deformation_gradient + "' (implemented: first_order)");
    setup.prescribed = read_prescribed_deformation(mpm_flags.require_child("prescribed_deformation_file"));
  }
  // AccStrainEnergy, PlasticWork and the energy ledger (mpm/EnergyLedger.h) are
  // summed every step (PlasticWork under MPI: over the ranks, per material),
  // g.stressFS in P2G, only when the deck saves them.
  setup.node_stress = false;
  if (const DeckNode* archiver = root.child("DataArchiver"))
    for (const DeckNode* save : archiver->children_named("save")) {
      if (save->attribute("label") == std::optional<std::string>("AccStrainEnergy")) setup.accumulate_strain_energy = true;
      if (save->attribute("label") == std::optional<std::string>("PlasticWork")) setup.accumulate_plastic_work = true;
      for (const char* l : energy_ledger_labels())
        if (save->attribute("label") == std::optional<std::string>(l)) setup.energy_ledger = true;
      if (save->attribute("label") == std::optional<std::string>("g.stressFS")) setup.node_stress = true;
    }
  // Axisymmetric (mpm/Axisymmetric.h): x = r >= 0, one hoop cell in z; every interpolator.
  if (setup.flags.axisymmetric) {
    const DeckNode& flag = root.require_child("MPM").require_child("axisymmetric");
    if (axisymmetric_stencil_width(setup.flags.interpolator.kind) == 0)
      flag.missing_feature("axisymmetric MPM with the '" + interpolator_name(setup.flags.interpolator.kind) +
                           "' interpolator");
    if (setup.grid.cells[2] != 1) flag.fail("axisymmetric MPM needs exactly one cell in z (the hoop direction)");
    if (setup.grid.lower[0] < 0.0) flag.fail("axisymmetric MPM: x is the radius, the grid must start at x >= 0");
    if ((setup.grid.periodic.array() != 0).any()) flag.missing_feature("axisymmetric MPM with periodic directions");
  }
  // Periodic directions (mpm/PeriodicGrid.h): every interpolator with a
  // translation-invariant support (ghost node layers); not the cubic
  // B-spline, whose splines are modified at the domain faces.
  if ((setup.grid.periodic.array() != 0).any() && periodic_ghost_layers(setup.flags.interpolator.kind) < 0)
    root.require_child("Grid").missing_feature("periodic MPM with the '" + interpolator_name(setup.flags.interpolator.kind) +
                              "' interpolator (boundary-modified splines; implemented: linear, gimp, cpgimp, cpdi, "
                              "cpti, 3rdorderBS)");
}

void check_body_force_stress(const Deck& deck, MpmSetup& setup) {
  bool any = false;
  for (const MpmMaterial& m : setup.materials) any = any || m.body_force_surface.has_value();
  if (!setup.flags.initialize_stress_using_body_force) {
    if (any)
      log::warning("a material asks <initialize_with_body_force> but <MPM><initialize_stress_using_body_force> "
                   "is not true: its particles start unstressed (as in Vaango)");
    return;
  }
  const DeckNode& flag = deck.root.require_child("MPM").require_child("initialize_stress_using_body_force");
  if (!any)
    log::warning(flag.file + ":" + std::to_string(flag.line) +
                 ": <initialize_stress_using_body_force> has no effect: no material has "
                 "<initialize_with_body_force>true (as in Vaango)");
  if (setup.rotating_frame) flag.missing_feature("<initialize_stress_using_body_force> with a rotating frame");
  if (!setup.flags.mms.empty()) flag.missing_feature("<initialize_stress_using_body_force> with <run_MMS_problem>");
  if (setup.flags.use_prescribed_deformation)
    flag.missing_feature("<initialize_stress_using_body_force> with a prescribed deformation");
}

void check_driver_combinations(const Deck&, MpmSetup&) {
  // Contact on periodic grids: normals and positions folded over the node
  // aliases (mpm/PeriodicGrid.h); friction_LR gathers the point cloud of a
  // node over its aliases (mpm/contact/FrictionLRContact.cpp).
  // Heat conduction works with axisymmetric stencils (in-plane gradients,
  // per-radian volumes: mpm/thermal/HeatConduction.cpp) and periodic grids
  // (folded temperature and rate, mpm/PeriodicGrid.h).
}

}  // namespace tephra
