#include "mpm/UpdatedGridVelocity.h"

namespace tephra {

void updated_particle_grid_velocity(const Particles& p, const Stencils& s, const NodeGrid& g, double dt,
                                    const std::vector<std::size_t>* canonical, std::vector<Vec3>& out) {
  const std::size_t nodes = g.mass.size();
  out.assign(nodes, Vec3::Zero());
  const int w = s.width;
  // Serial scatter: sum m_p S_gp v_p^{n+1} (the P2G kernel's order of summation per node).
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t base = i * std::size_t(w);
    Vec3 a = Vec3::Zero();
    for (int k = 0; k < w; ++k) a += s.w[base + k] * g.acceleration[s.node[base + k]];
    const Vec3 momentum = p.mass[i] * (p.v[i] + dt * a);
    for (int k = 0; k < w; ++k) out[s.node[base + k]] += s.w[base + k] * momentum;
  }
  if (canonical && !canonical->empty()) {
    std::vector<Vec3> sum(nodes, Vec3::Zero());
    for (std::size_t n = 0; n < nodes; ++n) sum[(*canonical)[n]] += out[n];
    for (std::size_t n = 0; n < nodes; ++n) out[n] = sum[(*canonical)[n]];
  }
  for (std::size_t n = 0; n < nodes; ++n) out[n] = g.mass[n] > 0.0 ? Vec3(out[n] / g.mass[n]) : Vec3::Zero();
}

}  // namespace tephra

namespace tephra {

void keep_stable_usl_nodes(const NodeGrid& g, double limit, double cell_volume, const std::vector<Vec3>& v_star,
                           std::vector<Vec3>& v) {
  for (std::size_t n = 0; n < v.size(); ++n)
    if (g.volume[n] >= limit * cell_volume) v[n] = v_star[n];
}

}  // namespace tephra
