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

// The PlasticWork reduction (a Tephra label; Vaango has no such reduction): the
// dissipation of the step, sum_p V0_p w_p, with w_p the model's plastic work of
// the step per reference volume (SolidUpdateOutput::plastic_work, e.g.
// elastic_plastic_hp: J sigma : d_eps^p). Summed over the steps it is the
// plastic work W_p of the energy balance KE + StrainEnergy + W_p = KE_0 + work
// of the external forces (docs/models/taylor-impact.md). Summed only when the
// deck saves PlasticWork (MpmSetup::accumulate_plastic_work). plastic_work has
// one entry per particle.
double plastic_work_of_step(const Particles& p, const std::vector<double>& plastic_work);

}  // namespace tephra
