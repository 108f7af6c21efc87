#pragma once
// Particle deletion at the end of a step (Vaango's
// interpolateToParticlesAndUpdate, theory manual Alg. 14 "DELETEROGUEPARTICLES";
// the seed gives no criteria, these are Vaango's):
//   * m_p <= <minimum_particle_mass> (default 3e-15 kg) or T_p < 0: deleted;
//   * |v_p| > <maximum_particle_velocity> (default 3e105 m/s): deleted with
//     <delete_rogue_particles>true; otherwise, if the speed grew during the
//     step (|v_{n+1}| >= |v_n|), the velocity is scaled back to 0.9 times the
//     limit, keeping its direction.
//   * a particle outside the interior domain (in a non-periodic direction)
//     after its position update: deleted. This is Uintah's and Vaango's
//     relocation rule (Schedulers/Relocate.cc: a particle found in no patch of
//     the level is neither kept nor sent, so material leaving through a face,
//     e.g. the copper of JWLppCuRS2d at its x+ face, leaves the run). A
//     particle more than one cell beyond the face cannot have got there within
//     the CFL limit: the step stops with a NumericalFailure before this rule.
// A deleted particle leaves every column of the SoA (positions, state, the
// model's history); its mass, momentum and energy leave the sums with it.
#include <cstddef>
#include <string>
#include <vector>

#include "core/grid/Grid.h"
#include "mpm/Particles.h"

namespace tephra {

struct ParticleLimits {
  double minimum_mass = 3e-15;       // <minimum_particle_mass> [kg]
  double maximum_speed = 3e105;      // <maximum_particle_velocity> [m/s]
  bool delete_rogue = false;         // <delete_rogue_particles>
  const Grid* domain = nullptr;      // when set: delete particles outside its interior box (non-periodic d)
};

// True when x lies outside the interior box [lower, upper] of `domain` in a
// non-periodic direction (a particle on a face is inside); d_out is that direction.
bool outside_domain(const Grid& domain, const Vec3& x, int* d_out = nullptr);

// One deleted particle, for the run's log.
struct DeletedParticle {
  long long id = 0;
  double mass = 0.0;
  std::string reason;
};

// Removes the rows i with keep[i] == 0 from every column of p (order of the
// kept rows preserved) and from the per-particle scratch columns given in
// `extra_doubles` / `extra_mats` (each either empty or of length p.size()).
void remove_particles(Particles& p, const std::vector<char>& keep,
                      std::vector<std::vector<double>*> extra_doubles = {},
                      std::vector<std::vector<Mat3>*> extra_mats = {});

// Applies the limits to the particles after G2P: clamps rogue velocities
// (v_old: the velocities at the start of the step) and returns the rows to keep
// (keep[i] = 0 for a particle to delete), appending each deletion to `deleted`.
std::vector<char> apply_particle_limits(const ParticleLimits& limits, const std::vector<Vec3>& v_old,
                                        Particles& p, std::vector<DeletedParticle>& deleted);

}  // namespace tephra
