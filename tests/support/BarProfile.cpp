#include "tests/support/BarProfile.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace tephra::test {

BarProfile bar_profile(const Particles& p, double v0) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return p.x[a][0] < p.x[b][0]; });
  BarProfile r;
  for (std::size_t k = order.size() - 1; k > 0; --k) {
    const std::size_t a = order[k - 1], b = order[k];
    if (p.v[a][0] >= 0.5 * v0 && p.v[b][0] < 0.5 * v0) {
      const double s = (0.5 * v0 - p.v[a][0]) / (p.v[b][0] - p.v[a][0]);
      r.front = p.x[a][0] + s * (p.x[b][0] - p.x[a][0]);
      break;
    }
  }
  double ss = 0, sv = 0;
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    r.min_stress = std::min(r.min_stress, p.stress[i](0, 0));
    if (p.x[i][0] > r.front - 0.15 && p.x[i][0] < r.front - 0.05) {
      ss += p.stress[i](0, 0);
      sv += p.v[i][0];
      ++n;
    }
  }
  r.mean_stress = n ? ss / n : 0.0;
  r.mean_velocity = n ? sv / n : 0.0;
  return r;
}

}  // namespace tephra::test
