#pragma once
// The particles' CFL step size of explicit MPM (Vaango's rule, used by
// MpmComponent::material_stable_timestep):
//   dt = min_{p,d} h_d / (c_p + |v_p,d|)
// c_p the dilatational wave speed of the last stress update, v_p the particle
// velocity, h_d the cell size. +inf with no particles.
#include "core/base/Types.h"
#include "mpm/Particles.h"

namespace tephra {

// Evaluated as min_d fl(h_d / max_p s_p,d), s = c + |v_d|: one division per
// direction instead of three per particle, with the bits of the quotient-by-
// quotient minimum (StableTimestep.cpp). Threaded; the same value for any
// thread count.
double particle_stable_timestep(const Particles& p, const Vec3& h);

// The quotient-by-quotient minimum itself (std::min over p, then d), serial:
// the definition, for the tests and for a negative s.
double particle_stable_timestep_by_quotients(const Particles& p, const Vec3& h);

}  // namespace tephra
