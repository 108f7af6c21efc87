// The coupled MPMICE step (Vaango theory manual sec. 26.1.3) and the
// component plumbing (time step, output, reductions, restart).
#include "mpmice/MpmIceComponent.h"

#include <algorithm>
#include <memory>

#include "core/base/Errors.h"
#include "core/base/PhaseTimers.h"
#include "core/sim/StepRedo.h"

namespace tephra {

MpmIceComponent::MpmIceComponent(std::unique_ptr<MpmComponent> mpm, std::unique_ptr<IceComponent> ice, double p_ref)
    : mpm_(std::move(mpm)), ice_(std::move(ice)), p_ref_(p_ref) {
  mpm_->set_coupling(this);
  ice_->set_lagrangian_state_fill([this](IceComponent&) { solid_state_to_cells(); });
  for (const IceModelP& m : ice_->models())
    if (auto* burn = dynamic_cast<SolidBurnModel*>(m.get())) burn->attach(this);
}

// Particles first (seeded, stresses at F = I, projected to the nodes), then
// the cells: the solids' cell state from those nodes, the fluids' from their
// geom_objects, and the equilibration pressure over all materials.
void MpmIceComponent::initialize() {
  mpm_->initialize();
  // Under mpirun ICE takes MPM's patch owners, so that every particle of a
  // rank lies in the rank's own cells (docs/parallel.md "MPMICE on ranks").
  ice_->adopt_layout(mpm_->layout());
  ice_->initialize();
  initialized_ = true;
  particle_pressure_.assign(mpm_->materials().size(), {});
  for (std::size_t s = 0; s < particle_pressure_.size(); ++s)
    particle_pressure_[s].assign(mpm_->materials()[s].particles.size(), 0.0);
}

// The smaller of the two components' steps (Uintah's MPMICE takes the minimum).
double MpmIceComponent::stable_timestep() const {
  return std::min(mpm_->stable_timestep(), ice_->stable_timestep());
}

// The coupled step, in the order of sec. 26.1.3. MpmComponent::advance runs
// the MPM step and calls back (mpm/MpmCoupling.h) where the coupled order
// needs the cells:
//   1.    P2G of the particles (MPM), then nodes -> cells for each solid
//         (solid_state_to_cells)                        after_interpolate_to_grid
//   2.    equilibration pressure over all materials (solids via SolidEos)
//   3.    face velocities u*, face momentum exchange
//   4.    burn models (<Models>: Simple_Burn): the mass each surface cell
//         burns leaves the particles (burn_particles) and joins the product
//         gas as ICE model sources                          (in coupled_pressure_phases)
//   5.    pressure increment delP, p = p_eq + delP
//   6.    face pressure p*
//   7.    p_CC -> particles; f_int,g from sigma_p + (p_p - p_ref) I  add_internal_forces
//         (the stress update itself follows the grid velocity, MPM step 10)
//   8-11. Lagrangian values with the -theta grad p* force, momentum and heat
//         exchange among all materials, specific volume   after_integrate_grid
//   12.   advection of the fluids
//   13.   solid du_c, dT_c -> nodes (v*_g) and particles (T_p)
//   14.   grid BCs, G2P, x_p and v_p (MPM)
//
// Step redo (core/sim/StepRedo.h): with the implicit pressure or source
// models, a phase that cannot complete the step (the implicit solve: outer
// iterations past iters_before_timestep_restart or a linear solve short of
// its tolerance; a non-positive Lagrangian specific volume of a fluid) throws
// StepRedoRequest. The whole coupled step is then put back to its start
// (save_step_start / restore_step_start below: what the step reads before it
// writes it) and [t, t + dt] is run as two coupled steps of dt/2
// (Uintah's MPMICE::recomputeDelT halves delT), at most kMaxStepHalvings
// deep, then NumericalFailure (exit 4) naming the step, the cell and the why.
void MpmIceComponent::advance(double t, double dt, int step) {
  if (!ice_->redoes_failed_steps()) {
    mpm_->advance(t, dt, step);
    return;
  }
  StepRedo redo;
  redo.who = "MPMICE";
  redo.snapshot = [this]() -> std::function<void()> {
    PhaseTimers::Scope timer(phase_timers(), "MPMICE: step-redo snapshot");
    save_step_start();
    return [this] { restore_step_start(); };
  };
  redo.attempt = [this, step](double t0, double h) { mpm_->advance(t0, h, step); };
  try {
    advance_with_redo(redo, t, dt, step);
  } catch (const NumericalFailure&) {
    step_redos_ += redo.redos;  // the redos before the limit count too
    throw;
  }
  step_redos_ += redo.redos;
}

// What a redone step must put back (session 19; before, the whole restart
// archive, save_state, ~20 MB of fresh vectors per step on JWLppCuRS2d):
// MPM's particle columns and run totals (MpmComponent::StepStart; the node
// arrays are reset by P2G before any read), ICE's fluid state, pressure and
// model state (IceComponent::StepStart; the solids' cell state is left out:
// solid_state_to_cells rewrites it from the particles first in every step,
// in every cell with its extra cells, and the ghosts by exchange), and the
// burn models' arrays. The other members this class writes in a step
// (particle_pressure_, node_temperature_, the flux and burn scratch grids)
// are written before they are read. Copies into buffers kept across steps.
// Proof: test_mpmice_implicit and test_mpmice_redo (forced redos, the
// state bit-equal to the run that took the two dt/2 steps).
void MpmIceComponent::save_step_start() {
  mpm_->save_step_start(mpm_start_);
  ice_->save_step_start(ice_start_, false);
  for (std::size_t k = 0; k < ice_->models().size(); ++k)
    if (auto* b = dynamic_cast<const SolidBurnModel*>(ice_->models()[k].get()))
      b->save_arrays(burn_start_, "mpmice.burn" + std::to_string(k) + ".");
}

void MpmIceComponent::restore_step_start() {
  mpm_->restore_step_start(mpm_start_);
  ice_->restore_step_start(ice_start_);
  for (std::size_t k = 0; k < ice_->models().size(); ++k)
    if (auto* b = dynamic_cast<SolidBurnModel*>(ice_->models()[k].get()))
      b->load_arrays(burn_start_, "mpmice.burn" + std::to_string(k) + ".");
}

void MpmIceComponent::after_interpolate_to_grid(double t, double dt, int step) {
  PhaseTimers& T = phase_timers();
  ice_->set_coupled_step_time(t);  // the models' time (Test's startTime, ADD_HEAT's window, LightTime)
  { PhaseTimers::Scope s(T, "MPMICE: nodes to cells");        solid_state_to_cells(); }
  { PhaseTimers::Scope s(T, "MPMICE: solid volume fluxes");   solid_mass_fluxes(dt); }
  ice_->coupled_pressure_phases(dt, step);
  { PhaseTimers::Scope s(T, "MPMICE: pressure to particles"); pressure_to_particles(); }
}

void MpmIceComponent::after_integrate_grid(double dt, int step) {
  ice_->coupled_transport_phases(dt, step);
  PhaseTimers::Scope s(phase_timers(), "MPMICE: cell changes to nodes");
  cell_changes_to_nodes_and_particles();
}

void MpmIceComponent::fill_output(const std::set<std::string>& labels, OutputFrame& frame) const {
  std::set<std::string> mpm_labels, ice_labels;
  const std::set<std::string> mk = mpm_->known_labels(), ik = ice_->known_labels();
  for (const std::string& l : labels) {
    if (mk.count(l)) mpm_labels.insert(l);
    else if (ik.count(l)) ice_labels.insert(l);
  }
  ice_->fill_output(ice_labels, frame);
  mpm_->fill_output(mpm_labels, frame);
  // g.temperature when MPM does not hold it (no heat conduction): the step-1
  // node temperature of the coupled step.
  if (labels.count("g.temperature") && !mk.count("g.temperature"))
    for (std::size_t s = 0; s < node_temperature_.size(); ++s) {
      GridFieldArray g;
      g.location = GridLocation::Node;
      g.data.label = "g.temperature";
      g.data.material = mpm_->materials()[s].index;
      g.data.components = 1;
      g.data.values = mpm_->whole_node_array(node_temperature_[s], 1);  // from the rank boxes under mpirun
      mpm_->mark_node_pieces(g);  // per-rank output: the nodes this rank writes
      frame.grid_fields.push_back(std::move(g));
    }
}

// Reductions over both: TotalMass, TotalMomentum, KineticEnergy (and any
// other label both own) are the sums of the particle and the fluid values
// (the solids' cell copies are not counted: IceComponent skips lagrangian
// materials); a label only one side has is that side's value.
std::map<std::string, std::vector<double>> MpmIceComponent::reductions(const std::set<std::string>& labels) const {
  std::map<std::string, std::vector<double>> out = mpm_->reductions(labels);
  for (const auto& [label, v] : ice_->reductions(labels)) {
    auto it = out.find(label);
    if (it == out.end() || it->second.size() != v.size()) {
      out[label] = v;
      continue;
    }
    for (std::size_t i = 0; i < v.size(); ++i) it->second[i] += v[i];
  }
  return out;
}

std::set<std::string> MpmIceComponent::known_labels() const {
  std::set<std::string> s = mpm_->known_labels();
  for (const std::string& l : ice_->known_labels()) s.insert(l);
  s.insert("g.temperature");  // fill_output
  return s;
}

void MpmIceComponent::save_state(StateArchive& archive) const {
  mpm_->save_state(archive);
  ice_->save_state(archive);
  for (std::size_t k = 0; k < ice_->models().size(); ++k)
    if (auto* b = dynamic_cast<const SolidBurnModel*>(ice_->models()[k].get()))
      b->save_arrays(archive, "mpmice.burn" + std::to_string(k) + ".");
}

// A restart on a fresh component (tephra --restart) first initializes both
// parts together (MPM's layout to ICE, the solids' cell state from the
// particles): ICE's own load_state would otherwise initialize ICE alone.
void MpmIceComponent::load_state(const StateArchive& archive) {
  if (!initialized_) initialize();
  mpm_->load_state(archive);
  ice_->load_state(archive);
  for (std::size_t k = 0; k < ice_->models().size(); ++k)
    if (auto* b = dynamic_cast<SolidBurnModel*>(ice_->models()[k].get()))
      b->load_arrays(archive, "mpmice.burn" + std::to_string(k) + ".");
}

}  // namespace tephra
