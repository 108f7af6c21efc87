#include "mpm/Transfers.h"

#include <cmath>

namespace tephra {

long compute_stencils(const Particles& p, const NodeGrid& g, std::vector<LinearStencil>& s) {
  s.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Range check in floating point first: a NaN or huge coordinate must not
    // reach the float -> int conversion of the cell index.
    for (int d = 0; d < 3; ++d) {
      const double xi = (p.x[i][d] - g.origin[d]) / g.h[d];
      if (!(xi >= 0.0 && xi < g.n[d] - 1)) return static_cast<long>(i);
    }
    linear_stencil(p.x[i], g.origin, g.h, s[i]);
    // Round-off guard: the support c..c+1 must be nodes 0..n-1.
    for (int d = 0; d < 3; ++d)
      if (s[i].cell[d] < 0 || s[i].cell[d] > g.n[d] - 2) return static_cast<long>(i);
  }
  return -1;
}

void particles_to_grid(const Particles& p, const std::vector<LinearStencil>& s, const Vec3& body_force,
                       NodeGrid& g) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 momentum = p.mass[i] * p.v[i];
    const Vec3 force = p.external_force[i] + p.mass[i] * body_force;
    const Mat3 vol_stress = p.volume[i] * p.stress[i];
    for (int n = 0; n < 8; ++n) {
      const std::size_t gi = g.index(s[i].cell + LinearStencil::offset(n));
      const double w = s[i].w[n];
      g.mass[gi] += p.mass[i] * w;
      g.volume[gi] += p.volume[i] * w;
      g.velocity[gi] += momentum * w;  // momentum until divided below
      g.external_force[gi] += force * w;
      g.stress[gi] += vol_stress * w;
    }
  }
  for (std::size_t gi = 0; gi < g.count(); ++gi) {
    if (g.mass[gi] > 0.0) g.velocity[gi] /= g.mass[gi];
    if (g.volume[gi] > 0.0) g.stress[gi] /= g.volume[gi];
  }
}

void compute_internal_force(const Particles& p, const std::vector<LinearStencil>& s, NodeGrid& g) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Mat3 vol_stress = p.volume[i] * p.stress[i];
    for (int n = 0; n < 8; ++n) {
      const std::size_t gi = g.index(s[i].cell + LinearStencil::offset(n));
      g.internal_force[gi] -= vol_stress * s[i].grad[n];
    }
  }
}

void integrate_grid_velocity(NodeGrid& g, double dt) {
  for (std::size_t gi = 0; gi < g.count(); ++gi) {
    if (g.mass[gi] > 0.0) {
      g.acceleration[gi] = (g.internal_force[gi] + g.external_force[gi]) / g.mass[gi];
      g.velocity_star[gi] = g.velocity[gi] + g.acceleration[gi] * dt;
    } else {
      g.acceleration[gi].setZero();
      g.velocity_star[gi].setZero();
    }
  }
}

void acceleration_from_velocities(NodeGrid& g, double dt) {
  for (std::size_t gi = 0; gi < g.count(); ++gi)
    g.acceleration[gi] = (g.velocity_star[gi] - g.velocity[gi]) / dt;
}

void velocity_gradients(const std::vector<LinearStencil>& s, const NodeGrid& g, std::vector<Mat3>& L) {
  L.resize(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    Mat3 l = Mat3::Zero();
    for (int n = 0; n < 8; ++n)
      l += g.velocity_star[g.index(s[i].cell + LinearStencil::offset(n))] * s[i].grad[n].transpose();
    L[i] = l;
  }
}

void grid_to_particles(const std::vector<LinearStencil>& s, const NodeGrid& g, double dt, Particles& p) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    Vec3 a = Vec3::Zero(), v = Vec3::Zero();
    for (int n = 0; n < 8; ++n) {
      const std::size_t gi = g.index(s[i].cell + LinearStencil::offset(n));
      a += g.acceleration[gi] * s[i].w[n];
      v += g.velocity_star[gi] * s[i].w[n];
    }
    p.v[i] += dt * a;
    p.x[i] += dt * v;
    p.displacement[i] += dt * v;
  }
}

}  // namespace tephra
