#include "mpm/UpdatedGridVelocity.h"

#include <algorithm>

#include "mpm/shape/AxisStencils.h"

namespace tephra {

void updated_particle_grid_velocity(const Particles& p, const Stencils& s, const NodeGrid& g, double dt,
                                    const std::vector<std::size_t>* canonical, std::vector<Vec3>& out) {
  const std::size_t nodes = g.mass.size();
  out.assign(nodes, Vec3::Zero());
  // sum m_p S_gp v_p^{n+1}, in the scatter order of P2G (ScatterOrder.h: the
  // same bits for any thread count).
  Vec3* o = out.data();
  const Vec3* acc = g.acceleration.data();
  visit_stencils(s, [&](const auto& view) {
    for_each_scatter_particle(s.order, p.size(), [&](std::size_t i) {
      Vec3 a = Vec3::Zero();
      view.weights(i, [&](std::size_t gi, double wk) { a += wk * acc[gi]; });
      const Vec3 momentum = p.mass[i] * (p.v[i] + dt * a);
      view.weights(i, [&](std::size_t gi, double wk) { o[gi] += wk * momentum; });
    });
  });
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

namespace tephra {

std::size_t usl_needed_nodes(const NodeGrid& g, double limit, double cell_volume, std::vector<unsigned char>& needed) {
  const std::size_t nodes = g.count();
  needed.assign(nodes, 0);
  std::size_t weak = 0;
  for (std::size_t n = 0; n < nodes; ++n)
    if (!(g.volume[n] >= limit * cell_volume)) needed[n] = 1, ++weak;  // the negation of keep_stable_usl_nodes' test
  if (weak == 0) return 0;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const IntVec3 c(i, j, k);
        bool layer = false;
        for (int d = 0; d < 3; ++d) layer = layer || c[d] <= 2 * g.extra[d] || c[d] >= g.n[d] - 1 - 2 * g.extra[d];
        if (layer) needed[g.index(c)] = 1;
      }
  return weak;
}

void updated_particle_grid_velocity_at(const Particles& p, const Stencils& s, const NodeGrid& g, double dt,
                                       const std::vector<unsigned char>& needed, std::vector<Vec3>& out) {
  const std::size_t nodes = g.mass.size();
  out.assign(nodes, Vec3::Zero());
  if (std::find(needed.begin(), needed.end(), 1) == needed.end()) return;
  // The scatter order of P2G (ScatterOrder.h), threaded; the particles whose
  // stencil reaches no needed node are skipped.
  Vec3* o = out.data();
  const Vec3* acc = g.acceleration.data();
  const unsigned char* need = needed.data();
  visit_stencils(s, [&](const auto& view) {
    for_each_scatter_particle(s.order, p.size(), [&](std::size_t i) {
      bool reaches = false;
      view.weights(i, [&](std::size_t gi, double) { reaches = reaches || need[gi]; });
      if (!reaches) return;
      Vec3 a = Vec3::Zero();
      view.weights(i, [&](std::size_t gi, double wk) { a += wk * acc[gi]; });
      const Vec3 momentum = p.mass[i] * (p.v[i] + dt * a);
      view.weights(i, [&](std::size_t gi, double wk) { o[gi] += wk * momentum; });
    });
  });
#pragma omp parallel for schedule(static) if (nodes >= 4096)
  for (std::size_t n = 0; n < nodes; ++n)
    if (need[n]) o[n] = g.mass[n] > 0.0 ? Vec3(o[n] / g.mass[n]) : Vec3::Zero();
}

}  // namespace tephra
