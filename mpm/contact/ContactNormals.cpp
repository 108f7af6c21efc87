#include "mpm/contact/ContactNormals.h"

namespace tephra {

void mass_gradient(const Particles& p, const std::vector<LinearStencil>& s, const NodeGrid& g,
                   std::vector<Vec3>& out) {
  out.assign(g.count(), Vec3::Zero());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int n = 0; n < 8; ++n) out[g.index(s[i].cell + LinearStencil::offset(n))] += p.mass[i] * s[i].grad[n];
}

void mass_weighted_position(const Particles& p, const std::vector<LinearStencil>& s, const NodeGrid& g,
                            std::vector<Vec3>& out) {
  out.assign(g.count(), Vec3::Zero());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int n = 0; n < 8; ++n)
      out[g.index(s[i].cell + LinearStencil::offset(n))] += p.mass[i] * s[i].w[n] * p.x[i];
  for (std::size_t gi = 0; gi < g.count(); ++gi)
    if (g.mass[gi] > 0.0) out[gi] /= g.mass[gi];
}

}  // namespace tephra
