#include "mpm/PressureStabilization.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace tephra {

namespace {

// The cell of the node grid holding x, as the node index of its lower corner.
std::size_t cell_node(const NodeGrid& g, const Vec3& x) {
  const IntVec3 cells = g.n - IntVec3::Ones();
  IntVec3 c;
  for (int d = 0; d < 3; ++d) c[d] = std::clamp(int(std::floor((x[d] - g.origin[d]) / g.h[d])), 0, cells[d] - 1);
  return g.index(c[0], c[1], c[2]);
}

}  // namespace

std::vector<double> cell_volume_sums(const NodeGrid& g, const Particles& p) {
  std::vector<double> sums(2 * g.count(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t ci = cell_node(g, p.x[i]);
    sums[2 * ci] += p.volume0[i];
    sums[2 * ci + 1] += p.F[i].determinant() * p.volume0[i];
  }
  return sums;
}

void apply_cell_dilatation(const NodeGrid& g, const std::vector<double>& sums, Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t ci = cell_node(g, p.x[i]);
    const double Jc = sums[2 * ci + 1] / sums[2 * ci];
    p.F[i] *= std::cbrt(Jc / p.F[i].determinant());
  }
}

void stabilize_pressure(const NodeGrid& g, Particles& p) { apply_cell_dilatation(g, cell_volume_sums(g, p), p); }

}  // namespace tephra
