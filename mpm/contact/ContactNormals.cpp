#include "mpm/contact/ContactNormals.h"

namespace tephra {

void mass_gradient(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out) {
  out.assign(g.count(), Vec3::Zero());
  const std::size_t W = std::size_t(s.width);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t e = i * W; e < (i + 1) * W; ++e) out[s.node[e]] += p.mass[i] * s.grad[e];
}

void mass_weighted_position(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out) {
  out.assign(g.count(), Vec3::Zero());
  const std::size_t W = std::size_t(s.width);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t e = i * W; e < (i + 1) * W; ++e) out[s.node[e]] += p.mass[i] * s.w[e] * p.x[i];
  for (std::size_t gi = 0; gi < g.count(); ++gi)
    if (g.mass[gi] > 0.0) out[gi] /= g.mass[gi];
}

}  // namespace tephra
