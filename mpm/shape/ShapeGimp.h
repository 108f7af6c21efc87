#pragma once
// uGIMP shape functions, `<interpolator>gimp` (Vaango theory manual §1.6.2,
// eqs. 1.90-1.92): the linear hat convolved with the particle's top-hat
// characteristic function of half-length l_p, per direction (tensor product).
// In node-index units (h = 1), d = xi - i, l = l_p / h:
//   S(d) = (1 + l + d)^2 / (4 l)        -1 - l < d <= -1 + l
//          1 + d                        -1 + l < d <= -l
//          1 - (d^2 + l^2) / (2 l)      -l     < d <=  l
//          1 - d                         l     < d <=  1 - l
//          (1 + l - d)^2 / (4 l)         1 - l < d <=  1 + l
//          0                            otherwise
//   dS/dd = (1 + l + d)/(2 l), 1, -d/l, -1, -(1 + l - d)/(2 l), 0   (eq. 1.92)
// Valid for 0 < l <= 1/2 (Vaango's particles have l = 1/(2 res) <= 1/2);
// the support of node i is |d| < 1 + l, so the three nodes nearest to the
// particle (N - 1, N, N + 1 with N = round(xi)) hold every non-zero weight.
// "u"GIMP: l_p is the particle's size at creation (Vaango keeps pSize fixed
// unless the interpolator is cpdi), not the deformed size.
#include <algorithm>
#include <cmath>

#include "mpm/shape/FloorIndex.h"
#include "mpm/shape/ShapeAxis.h"

namespace tephra {

// S and dS/dd of eqs. 1.91-1.92 at d = xi - x_g (index units), half-length l.
inline void gimp_1d(double d, double l, double& S, double& dS) {
  if (d <= -1.0 - l || d > 1.0 + l) {
    S = 0.0;
    dS = 0.0;
  } else if (d <= -1.0 + l) {
    S = (1.0 + l + d) * (1.0 + l + d) / (4.0 * l);
    dS = (1.0 + l + d) / (2.0 * l);
  } else if (d <= -l) {
    S = 1.0 + d;
    dS = 1.0;
  } else if (d <= l) {
    S = 1.0 - (d * d + l * l) / (2.0 * l);
    dS = -d / l;
  } else if (d <= 1.0 - l) {
    S = 1.0 - d;
    dS = -1.0;
  } else {
    S = (1.0 + l - d) * (1.0 + l - d) / (4.0 * l);
    dS = -(1.0 + l - d) / (2.0 * l);
  }
}

// The three nodes around xi; l = half-length in index units, 0 < l <= 1/2.
inline ShapeAxis gimp_axis(double xi, double l) {
  ShapeAxis a;
  a.first = floor_index(xi + 0.5) - 1;  // = (int)std::floor(xi + 0.5) - 1 (FloorIndex.h)
  a.count = 3;
  for (int k = 0; k < 3; ++k) gimp_1d(xi - (a.first + k), l, a.S[k], a.dS[k]);
  return a;
}

// The same convolution for any half-length 0 < l <= 1 (index units), as the
// exact integral S(d) = (1/2l) int_{d-l}^{d+l} hat(s) ds = (H(d+l) - H(d-l))/(2l)
// with H the antiderivative of the hat, H(s) = 0 (s < -1), (1+s)^2/2 (s < 0),
// 1 - (1-s)^2/2 (s < 1), 1; dS/dd = (hat(d+l) - hat(d-l))/(2l). For l <= 1/2
// it is eqs. 1.91-1.92; for l > 1/2 (a deformed domain, l = l0 F_dd) the
// support |d| < 1 + l holds up to four nodes. Used by cpGIMP
// (InterpolatorKind::CpGimp, Bardenhagen & Kober 2004), whose domains follow
// the stretch so that they keep tiling the body.
inline double hat_integral(double s) {
  if (s <= -1.0) return 0.0;
  if (s <= 0.0) return 0.5 * (1.0 + s) * (1.0 + s);
  if (s <= 1.0) return 1.0 - 0.5 * (1.0 - s) * (1.0 - s);
  return 1.0;
}
inline double hat_1d(double s) { return std::max(0.0, 1.0 - std::abs(s)); }

inline ShapeAxis gimp_axis_any(double xi, double l) {
  ShapeAxis a;
  // Nodes i with |xi - i| < 1 + l: floor(xi - l) .. floor(xi + l) + 1 (<= 4 for l <= 1).
  a.first = floor_index(xi - l);  // (int)std::floor (FloorIndex.h)
  a.count = 0;
  const int last = floor_index(xi + l) + 1;
  for (int i = a.first; i <= last && a.count < 4; ++i) {
    const double d = xi - i;
    a.S[a.count] = (hat_integral(d + l) - hat_integral(d - l)) / (2.0 * l);
    a.dS[a.count] = (hat_1d(d + l) - hat_1d(d - l)) / (2.0 * l);
    ++a.count;
  }
  return a;
}

}  // namespace tephra
