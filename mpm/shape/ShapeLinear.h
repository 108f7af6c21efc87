#pragma once
// Linear (tri-linear) MPM shape functions, `<interpolator>linear` (Vaango
// theory manual §1.6.1, eqs. 1.86-1.89), in node-index units (ShapeAxis.h):
//   1-D hat  S(xi) = 1 - |xi - i|  for |xi - i| < 1,  dS/dxi = -sign(xi - i)
// A point in cell c = floor(xi) has the nodes c, c+1 per direction (8 in 3-D).
// Identities (tested): sum S_g = 1, sum S_g x_g = x, sum grad S_g = 0,
// sum x_g (grad S_g)^T = I.
#include <cmath>

#include "mpm/shape/FloorIndex.h"
#include "mpm/shape/ShapeAxis.h"

namespace tephra {

inline ShapeAxis linear_axis(double xi) {
  ShapeAxis a;
  a.first = floor_index(xi);
  const double c = floor_value(xi, a.first);  // std::floor(xi), the same bits (FloorIndex.h)
  const double r = xi - c;  // local coordinate in [0,1)
  a.count = 2;
  a.S[0] = 1.0 - r;
  a.S[1] = r;
  a.dS[0] = -1.0;
  a.dS[1] = 1.0;
  return a;
}

}  // namespace tephra
