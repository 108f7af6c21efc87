#include "mpm/Transfers.h"

#include <cmath>

namespace tephra {

void particles_to_grid(const Particles& p, const Stencils& s, const Vec3& body_force, NodeGrid& g) {
  const std::size_t W = s.width;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 momentum = p.mass[i] * p.v[i];
    const Vec3 force = p.external_force[i] + p.mass[i] * body_force;
    const Mat3 vol_stress = p.volume[i] * p.stress[i];
    for (std::size_t k = i * W; k < (i + 1) * W; ++k) {
      const std::size_t gi = s.node[k];
      const double w = s.w[k];
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

void compute_internal_force(const Particles& p, const Stencils& s, NodeGrid& g) {
  const std::size_t W = s.width;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Mat3 vol_stress = p.volume[i] * p.stress[i];
    for (std::size_t k = i * W; k < (i + 1) * W; ++k) g.internal_force[s.node[k]] -= vol_stress * s.grad[k];
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

void velocity_gradients(const Stencils& s, const NodeGrid& g, std::vector<Mat3>& L) {
  const std::size_t W = s.width, np = s.particles();
  L.resize(np);
  for (std::size_t i = 0; i < np; ++i) {
    Mat3 l = Mat3::Zero();
    for (std::size_t k = i * W; k < (i + 1) * W; ++k) l += g.velocity_star[s.node[k]] * s.grad[k].transpose();
    L[i] = l;
  }
}

void grid_to_particles(const Stencils& s, const NodeGrid& g, double dt, Particles& p) {
  const std::size_t W = s.width, np = s.particles();
  for (std::size_t i = 0; i < np; ++i) {
    Vec3 a = Vec3::Zero(), v = Vec3::Zero();
    for (std::size_t k = i * W; k < (i + 1) * W; ++k) {
      a += g.acceleration[s.node[k]] * s.w[k];
      v += g.velocity_star[s.node[k]] * s.w[k];
    }
    p.v[i] += dt * a;
    p.x[i] += dt * v;
    p.displacement[i] += dt * v;
  }
}

}  // namespace tephra
