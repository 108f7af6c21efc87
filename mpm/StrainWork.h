#pragma once
// The stress power of a material's particles, for the AccStrainEnergy
// reduction (Vaango's accumulated strain energy: the sum over steps of the
// work increments, SerialMPM computeAccStrainEnergy). Tephra takes each
// step's increment by the trapezoidal rule in time,
//   dW_n = dt/2 [ P(sigma_n, V_n) + P(sigma_{n+1}, V_{n+1}) ],
//   P(sigma, V) = sum_p V_p sigma_p : d_p,   d_p = sym(l_p) of the step,
// so AccStrainEnergy = integral of the stress power over the run (work done
// on the particles by their stresses) to O(dt^2). For a hyperelastic model it
// converges to the stored energy sum W(F) V0 (StrainEnergy) at second order;
// for a dissipative one it is the total work (stored + dissipated).
// Computed only when the deck saves AccStrainEnergy.
#include <vector>

#include "core/base/Types.h"
#include "mpm/Particles.h"

namespace tephra {

// sum_p V_p sigma_p : sym(L_p), with the particles' current volume and stress.
double stress_power(const Particles& p, const std::vector<Mat3>& L);

}  // namespace tephra
