// MpmComponent: two body-load phases of the step.
//  * the rotating-frame body force (theory manual Alg. 3,
//    mpm/loads/RotatingFrame.h), at the start of a step after the
//    <PhysicalBC> loads and before P2G;
//  * the heat-flux load (mpm/loads/ParticleLoads.h), after the stress update
//    and before G2P.
#include <algorithm>
#include <sstream>

#include "core/base/Errors.h"
#include "core/base/PhaseTimers.h"
#include "mpm/MpmComponent.h"

namespace tephra {

// f_ext,p = (the <PhysicalBC> loads of apply_loads(), or 0 without loads)
//         + m_p (-omega x (omega x r_p) - 2 omega x v_p), at x_n, v_n.
void MpmComponent::apply_rotating_frame() {
  PhaseTimers::Scope timer(phase_timers(), "MPM: apply external loads");
  for (MpmMaterial& m : setup_.materials) {
    Particles& p = m.particles;
    // Without loads nothing resets f_ext,p between steps (apply_loads returns early).
    if (setup_.loads.empty()) std::fill(p.external_force.begin(), p.external_force.end(), Vec3::Zero());
    add_rotating_frame_forces(*setup_.rotating_frame, p);
  }
}

// <PhysicalBC><MPM><heat_flux> (mpm/loads/ParticleLoads.h): each of the N_k
// particles on heat-flux surface k (counted over all materials, flags from
// the reference position X = x - u) gets the heat rate Q = q_k(t_n) A_k / N_k
// [W] as the heating rate Q / (m_p c_v) [K/s], added to the step's model
// heating before G2P (T_p += dt hdot_p). Sum over the particles of
// m_p c_v dT_p = q A dt: the energy in is exact. Vaango spreads the same
// particle rate through the grid (gExternalHeatRate); the total is the same.
void MpmComponent::add_heat_flux_heating(double t, int step) {
  PhaseTimers::Scope timer(phase_timers(), "MPM: apply external loads");
  const auto& surfaces = setup_.loads.heat_flux;
  std::vector<Particles*> all;
  for (MpmMaterial& m : setup_.materials) all.push_back(&m.particles);
  const std::vector<long> count = particles_per_surface(surfaces, setup_.grid.dx, all, load_totals());  // N over the ranks
  for (MpmMaterial& m : setup_.materials) {
    Particles& p = m.particles;
    m.heating.resize(p.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 X = p.x[i] - p.displacement[i];
      const Vec3 dxpp(p.psize[i].col(0).norm() * setup_.grid.dx[0], p.psize[i].col(1).norm() * setup_.grid.dx[1],
                      p.psize[i].col(2).norm() * setup_.grid.dx[2]);
      for (std::size_t k = 0; k < surfaces.size(); ++k) {
        if (!surfaces[k].on_surface(X, dxpp)) continue;
        const double Q = surfaces[k].curve.at(t) * surfaces[k].area / double(count[k]);
        if (!(m.specific_heat > 0.0)) {
          std::ostringstream s;
          s << "a <heat_flux> load heats particle id " << p.id[i] << " of material " << m.index
            << ", whose specific_heat is " << m.specific_heat << " (must be > 0)";
          fail_particle(m, i, step, "apply heat flux", s.str());
        }
        m.heating[i] += Q / (p.mass[i] * m.specific_heat);
      }
    }
  }
}

}  // namespace tephra
