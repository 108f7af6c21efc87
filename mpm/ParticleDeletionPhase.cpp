// MpmComponent: the end-of-step particle limits and deletion (mpm/ParticleDeletion.h).
#include <algorithm>
#include <sstream>

#include "core/base/Log.h"
#include "mpm/MpmComponent.h"
#include "mpm/ParticleDeletion.h"

namespace tephra {

// After G2P: clamps or deletes rogue particles, deletes light and negative-
// temperature ones and those that left the domain through a face, and reports each deletion (a warning naming the particle,
// the material, the step and the reason; the deleted mass is summed in
// deleted_mass()).
void MpmComponent::delete_particles(MpmMaterial& m, const std::vector<Vec3>& v_old, int step) {
  const MpmFlags& f = setup_.flags;
  const ParticleLimits limits{f.minimum_particle_mass, f.maximum_particle_velocity, f.delete_rogue_particles,
                              &setup_.grid};
  std::vector<DeletedParticle> deleted;
  std::vector<char> keep = apply_particle_limits(limits, v_old, m.particles, deleted);
  if (deleted.empty()) return;
  for (const DeletedParticle& d : deleted) {
    deleted_mass_ += d.mass;
    std::ostringstream s;
    s.precision(17);
    s << "MPM step " << step << ": deleted particle id " << d.id << " of material " << m.index << " (mass "
      << d.mass << " kg): " << d.reason;
    log::warning(s.str());
  }
  remove_particles(m.particles, keep, {&m.plastic_work, &m.heating}, {&m.L, &m.F_old});
}

// <test_for_neg_temps_mpm> (default true): the lowest-index particle whose
// temperature is below 0 K (or not a number) after the step's temperature
// update stops the run with a NumericalFailure naming it, its material and
// the step. Without the check the deletion above removes such particles.
void MpmComponent::check_temperatures(const MpmMaterial& m, int step) const {
  const std::vector<double>& T = m.particles.temperature;
  // Threaded screen for the lowest failing particle (a minimum: order-free), then its message.
  const long np = long(T.size());
  long first = np;
#pragma omp parallel for schedule(static) reduction(min : first) if (np >= 4096)
  for (long i = 0; i < np; ++i)
    if (!(T[i] >= 0.0)) first = std::min(first, i);
  for (std::size_t i = std::size_t(first); i < T.size(); ++i)
    if (!(T[i] >= 0.0)) {
      std::ostringstream s;
      s.precision(17);
      s << "negative temperature T = " << T[i] << " K (<test_for_neg_temps_mpm>; false deletes the particle instead)";
      fail_particle(m, i, step, "update particle temperatures", s.str());
    }
}

}  // namespace tephra
