#pragma once
// The wave front and the state behind it in a 1-D bar of particles struck at
// x-: used by the bar-wave tests (velocity and pressure loading).
#include "mpm/Particles.h"

namespace tephra::test {

struct BarProfile {
  double front = 0;          // x where v_x crosses v0/2, scanning from the undisturbed end
  double mean_stress = 0;    // mean sigma_xx over [front - 0.15, front - 0.05]
  double mean_velocity = 0;  // mean v_x over the same window
  double min_stress = 0;     // most compressive sigma_xx anywhere
};

BarProfile bar_profile(const Particles& p, double v0);

}  // namespace tephra::test
