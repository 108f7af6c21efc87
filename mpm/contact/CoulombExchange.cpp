#include "mpm/contact/CoulombExchange.h"

#include <algorithm>
#include <cmath>

namespace tephra {

double boundary_volume_factor(const NodeGrid& g, std::size_t node) {
  std::size_t rest = node;
  double f = 1.0;
  for (int d = 0; d < 3; ++d) {
    const std::size_t i = rest % std::size_t(g.n[d]);
    rest /= std::size_t(g.n[d]);
    if (i == 0 || i + 1 == std::size_t(g.n[d])) f *= 2.0;
  }
  return f;
}

Vec3 coulomb_exchange(const ContactPair& p, double mu, const Vec3& h, double dt) {
  const Vec3 dv = p.relative();
  const double dvn = dv.dot(p.n);
  const Vec3 tangential = dv - dvn * p.n;
  const double dvt = tangential.norm();
  Vec3 dva;  // Delta v_a
  if (dvt <= 1e-15 * dv.norm()) {
    dva = -dvn * p.n;  // approach along the normal: no slip to resolve
  } else if (dvn == 0.0) {
    return Vec3::Zero();  // no normal impulse, hence no friction
  } else {
    const double ratio = std::min(mu, dvt / std::abs(dvn));  // eq. 1.115
    dva = -dvn * p.n - ratio * std::abs(dvn) * (tangential / dvt);
  }
  // Vaango's limiter on the imposed strain (see the header).
  double eps = 0.0;
  for (int d = 0; d < 3; ++d) eps = std::max(eps, std::abs(dva[d]) * dt / h[d]);
  if (eps > 0.0) {
    eps *= std::max(1.0, p.ma / p.mb);
    dva *= std::min(eps, 0.5) / eps;
  }
  return p.ma * dva;
}

double friction_work(const ContactPair& p, const Vec3& dp) {
  const Vec3 slip = (p.va + dp / p.ma) - (p.vb - dp / p.mb);  // v'_a - v'_b
  const Vec3 slip_t = slip - slip.dot(p.n) * p.n;
  const Vec3 impulse_t = dp - dp.dot(p.n) * p.n;
  return std::max(0.0, -impulse_t.dot(slip_t));  // >= 0 but for round-off
}

void record_friction_work(ContactNodes& nodes, std::size_t node, int a, const std::vector<int>& lump,
                          const ContactPair& p, const Vec3& dp) {
  if (nodes.friction_work.empty()) return;
  const double q = friction_work(p, dp);
  if (q == 0.0) return;
  const double total = p.ma + p.mb;
  nodes.friction_work[a][node] += q * (p.mb / total);
  for (int b : lump)
    if (b != a) nodes.friction_work[b][node] += q * (p.ma / total) * (nodes.grid[b]->mass[node] / p.mb);
}

}  // namespace tephra
