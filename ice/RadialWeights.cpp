// Radial face-area weights of axisymmetric ICE (the math: RadialWeights.h).
#include "ice/RadialWeights.h"

namespace tephra {

RadialWeights make_radial_weights(const Grid& g) {
  RadialWeights w;
  w.i_first = -g.extra_cells[0];
  const int n = g.cells[0] + 2 * g.extra_cells[0];
  w.lo.assign(std::size_t(n), 1.0);
  w.hi.assign(std::size_t(n), 1.0);
  w.r.assign(std::size_t(n), 0.0);
  const double dr = g.dx[0];
  for (int c = 0; c < n; ++c) {
    const int i = w.i_first + c;
    const double r_lo = g.lower[0] + i * dr, r_hi = g.lower[0] + (i + 1) * dr;
    const double r_c = g.lower[0] + (i + 0.5) * dr;
    w.r[std::size_t(c)] = r_c;
    if (r_c <= 0.0) continue;
    w.lo[std::size_t(c)] = r_lo / r_c;
    w.hi[std::size_t(c)] = r_hi / r_c;
  }
  return w;
}

}  // namespace tephra
