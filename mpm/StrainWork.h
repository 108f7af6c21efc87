#pragma once
// Vaango's AccStrainEnergy: the work of the stress over the run,
//   W += sum_p (sigma_n + sigma_{n+1})/2 : d_p (V_n + V_{n+1})/2 dt,
// d = sym(l) the step's rate of deformation (trapezoid in time, as Vaango's
// hypo models sum their per-step StrainEnergy). half_stress_power(p, L, dt)
// returns sum_p sigma_p : sym(L_p) V_p dt / 2 for the particles' current
// stress and volume; the driver calls it before and after the stress update.
// (With the midpoint volumes the cross terms differ from Vaango's product of
// averages by O(dt^2).)
#include <vector>

#include "core/base/Types.h"
#include "mpm/Particles.h"

namespace tephra {

inline double half_stress_power(const Particles& p, const std::vector<Mat3>& L, double dt) {
  double w = 0.0;
  for (std::size_t i = 0; i < p.size() && i < L.size(); ++i)
    w += (p.stress[i].cwiseProduct(0.5 * (L[i] + L[i].transpose()))).sum() * p.volume[i];
  return 0.5 * dt * w;
}

}  // namespace tephra
