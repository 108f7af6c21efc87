#pragma once
// Grid damping, <MPM><artificial_damping_coeff> alpha [1/s]: the theory
// manual's m_g dv_g/dt = f_ext - f_int + f_body - alpha_d v_g (eq. 1.65),
// with alpha_d = alpha m_g (a mass-proportional coefficient, so that alpha is
// a rate independent of the node's mass), integrated with the explicit step:
//   a_g -= alpha v_g,   v*_g = v_g + a_g dt.
// A body translating freely with v_0 keeps a uniform v_g, and P2G/G2P pass a
// uniform field exactly, so v_n = (1 - alpha dt)^n v_0 -> v_0 exp(-alpha t)
// (first order in dt).
#include "mpm/NodeGrid.h"

namespace tephra {

inline void apply_grid_damping(NodeGrid& g, double alpha, double dt) {
  for (std::size_t gi = 0; gi < g.count(); ++gi)
    if (g.mass[gi] > 0.0) {
      g.acceleration[gi] -= alpha * g.velocity[gi];
      g.velocity_star[gi] = g.velocity[gi] + g.acceleration[gi] * dt;
    }
}

}  // namespace tephra
