// The start of an MPM step for a redo (MpmComponent::StepStart; MPMICE's
// step redo, core/sim/StepRedo.h). Copy-assignment of the particle columns
// into the caller's buffers (std::vector keeps its storage when the sizes
// agree: no allocation after the first step). Unlike save_state it copies
// this process's particles as they are (no gather over MPI ranks, no
// flattening) and no node arrays (P2G resets them every step).
#include "mpm/MpmComponent.h"

namespace tephra {

void MpmComponent::save_step_start(StepStart& s) const {
  s.particles.resize(setup_.materials.size());
  for (std::size_t m = 0; m < setup_.materials.size(); ++m) s.particles[m] = setup_.materials[m].particles;
  s.time = time_;
  s.acc_strain_energy = acc_strain_energy_;
  s.plastic_work = plastic_work_;
  s.deleted_mass = deleted_mass_;
  s.ledger = ledger_;
  s.boundary_force = boundary_force_;
  s.boundary_area = boundary_area_;
}

void MpmComponent::restore_step_start(const StepStart& s) {
  for (std::size_t m = 0; m < setup_.materials.size(); ++m) setup_.materials[m].particles = s.particles[m];
  time_ = s.time;
  acc_strain_energy_ = s.acc_strain_energy;
  plastic_work_ = s.plastic_work;
  deleted_mass_ = s.deleted_mass;
  ledger_ = s.ledger;
  boundary_force_ = s.boundary_force;
  boundary_area_ = s.boundary_area;
}

}  // namespace tephra
