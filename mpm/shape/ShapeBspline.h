#pragma once
// Quadratic B-spline shape functions, `<interpolator>3rdorderBS` (third order
// = degree 2; Vaango's TOBSplineInterpolator, 27 nodes in 3-D). Vaango uses
// the uniform quadratic B-spline at every node, including the nodes of the
// extra cells (its boundary-modified splines are defined but not called), so
// a particle within h/2 of the domain face weights an extra-cell node.
// In node-index units, d = xi - i:
//   S(d) = 3/4 - d^2                 |d| <= 1/2
//          (3/2 - |d|)^2 / 2         1/2 < |d| < 3/2
//          0                         otherwise
//   dS/dd = -2 d,  -sign(d) (3/2 - |d|),  0
// Support: the nodes N - 1, N, N + 1 with N = round(xi). C1 continuous;
// reproduces linear functions (sum S_i i = xi), so the identities of
// ShapeLinear.h hold.
#include <cmath>

#include "mpm/shape/FloorIndex.h"
#include "mpm/shape/ShapeAxis.h"

namespace tephra {

inline void quadratic_bspline_1d(double d, double& S, double& dS) {
  const double a = std::abs(d);
  if (a <= 0.5) {
    S = 0.75 - d * d;
    dS = -2.0 * d;
  } else if (a < 1.5) {
    S = 0.5 * (1.5 - a) * (1.5 - a);
    dS = (d > 0 ? -1.0 : 1.0) * (1.5 - a);
  } else {
    S = 0.0;
    dS = 0.0;
  }
}

inline ShapeAxis quadratic_bspline_axis(double xi) {
  ShapeAxis a;
  a.first = floor_index(xi + 0.5) - 1;  // = (int)std::floor(xi + 0.5) - 1 (FloorIndex.h)
  a.count = 3;
  for (int k = 0; k < 3; ++k) quadratic_bspline_1d(xi - (a.first + k), a.S[k], a.dS[k]);
  return a;
}

}  // namespace tephra
