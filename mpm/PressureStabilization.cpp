#include "mpm/PressureStabilization.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace tephra {

void stabilize_pressure(const NodeGrid& g, Particles& p) {
  const IntVec3 cells = g.n - IntVec3::Ones();
  const std::size_t nc = std::size_t(cells[0]) * cells[1] * cells[2];
  std::vector<double> V0(nc, 0.0), V(nc, 0.0);
  std::vector<std::size_t> cell_of(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    IntVec3 c;
    for (int d = 0; d < 3; ++d)
      c[d] = std::clamp(int(std::floor((p.x[i][d] - g.origin[d]) / g.h[d])), 0, cells[d] - 1);
    const std::size_t ci = std::size_t(c[0]) + std::size_t(cells[0]) * (std::size_t(c[1]) + std::size_t(cells[1]) * c[2]);
    cell_of[i] = ci;
    V0[ci] += p.volume0[i];
    V[ci] += p.F[i].determinant() * p.volume0[i];
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double Jc = V[cell_of[i]] / V0[cell_of[i]];
    p.F[i] *= std::cbrt(Jc / p.F[i].determinant());
  }
}

}  // namespace tephra
