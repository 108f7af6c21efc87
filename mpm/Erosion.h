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
void erode_failed_particles(ErosionAlgorithm a, std::span<const double> localized, std::vector<Mat3>& stress);

}  // namespace tephra
