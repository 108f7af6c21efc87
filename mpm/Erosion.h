#pragma once
// Erosion of failed particles, <MPM><erosion algorithm="..."/> (theory manual
// ch. 16; Vaango applies it inside the damage-capable constitutive models to
// the particles their damage model flagged as localized, p.localized != 0):
//   none            no change
//   ZeroStress      sigma = 0
//   AllowNoTension  p = tr(sigma)/3 (tension positive): sigma = 0 if p > 0, else p I
//   AllowNoShear    sigma = p I (the failed particle keeps its pressure only)
//   KeepStress      no change (the particle stays flagged)
// Tephra applies it once, after the model's update, to every material whose
// model declares a history column named "localized" (nonzero = failed). A model
// without that column never flags a particle, so its particles never erode
// (as in Vaango, where models without damage never set p.localized).
// RemoveMass, BrittleDamage and FailureCriterion are not implemented.
#include <span>
#include <string>
#include <vector>

#include "core/base/Types.h"

namespace tephra {

enum class ErosionAlgorithm { None, ZeroStress, AllowNoTension, AllowNoShear, KeepStress };

// The algorithm of a Vaango name; false for a name that is not implemented.
bool erosion_algorithm_from_name(const std::string& name, ErosionAlgorithm& out);

// The name of the history column that flags a failed particle.
inline const char* localized_history_name() { return "localized"; }

// Applies `a` to the stress of every particle i with localized[i] != 0.
// ZeroStress also bounds the particle's wave speed by `reference_wave_speed`,
// the material's dilatational wave speed at rest, sqrt((K0 + 4 G0/3)/rho0):
// the particle carries no stress whatever its deformation, so the tangent
// stiffness of its (crushed) state must not set the time step. Measured
// (docs/validation/cookoff.md "Session 27"): a failed steel particle at the
// cookoff container's inner corner, crushed to J = 0.48 near the
// Mie-Grueneisen limit 1 - 1/s, reported c = 9.3e6 m/s and cut the step from
// 2e-8 to 1.4e-10 s. (Uintah's older damage models reset a failed particle
// to its reference state, F = I, V = m/rho0, and take c from the reference
// moduli: the same bound.)
void erode_failed_particles(ErosionAlgorithm a, std::span<const double> localized, std::vector<Mat3>& stress,
                            std::vector<double>& wave_speed, double reference_wave_speed);

}  // namespace tephra
