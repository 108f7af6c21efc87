#pragma once
// The work of the stresses over a step, for the AccStrainEnergy reduction
// (Vaango's accumulated strain energy: the sum over steps of the work
// increments, SerialMPM computeAccStrainEnergy). Tephra takes each step's
// increment on the reference configuration by the trapezoidal rule:
//   dW_n = sum_p V0_p (P_n + P_{n+1})/2 : (F_{n+1} - F_n),   P = J sigma F^{-T}
// (P the first Piola-Kirchhoff stress, so P : dF V0 = sigma : d V dt). For a
// hyperelastic model dW = P : dF exactly, and the trapezoidal sum converges to
// the stored energy sum W(F) V0 (StrainEnergy) at second order in the step;
// for a dissipative model it is the total work (stored + dissipated).
// Computed only when the deck saves AccStrainEnergy.
#include <vector>

#include "core/base/Types.h"
#include "mpm/Particles.h"

namespace tephra {

// sum_p V0_p P_p : (F_p - F_old_p), P_p = J sigma_p F_s^{-T}, J = det F_s, with the
// particles' current stress sigma_p taken at deformation F_s = F_stress_p.
double piola_work(const Particles& p, const std::vector<Mat3>& F_stress, const std::vector<Mat3>& F_old);

}  // namespace tephra
