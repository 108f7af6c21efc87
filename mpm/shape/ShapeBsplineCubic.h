#pragma once
// Cubic B-spline shape functions, `<interpolator>4thorderBS` (fourth order =
// degree 3; Vaango's BSplineInterpolator, 64 nodes in 3-D), with Vaango's
// boundary-modified splines on the two node layers at each face of the
// domain, so that no extra-cell node is used. Facts checked in Vaango's
// BSplineInterpolator.cc (evalType1/2/3BSpline, findNodeComponents; not
// copied). Node-index units, lo and top = the first and last interior node
// (the domain faces), d = xi - i:
//
// type 1, interior nodes (the uniform cubic B-spline):
//   N(d) = 2/3 - d^2 + |d|^3/2          |d| < 1
//          (2 - |d|)^3 / 6              1 <= |d| < 2
// type 2, node lo + 1 (d in [-1, 2)):
//   N2(d) = -11/12 d^3 - 5/4 d^2 + d/4 + 7/12      -1 <= d < 0
//            7/12 d^3 - 5/4 d^2 + d/4 + 7/12        0 <= d < 1
//           (2 - d)^3 / 6                           1 <= d < 2
// type 3, the face node lo (d in [0, 2)):
//   N3(d) = 1 - 3/2 d^2 + 3/4 d^3                    0 <= d < 1
//           (2 - d)^3 / 4                           1 <= d < 2
// and the mirror images at the upper face: node top uses N3(top - xi), node
// top - 1 uses N2(top - 1 - xi) (derivatives change sign).
//
// Properties (tests/unit/test_mpm_shape_cpti_bs4.cpp): C2 in the interior;
// partition of unity everywhere in [lo, top]; linear completeness
// sum S_i i = xi only where every node of the support is of type 1
// (xi >= lo + 3 and xi <= top - 3): N3 has zero slope at the face, so near
// a face the modified basis does not reproduce a linear field (for example
// at xi = lo + 1/2: sum S_i (i - lo) = 0.3021, not 0.5).
//
// Vaango difference: its findNodeComponents adds node ix + 2 whenever
// ix + 1 is below its exclusive upper bound, so a particle in the last
// interior cell also weights the extra-cell node top + 1 with N(d - 2) and
// its weights sum to 1 + (xi - ix)^3/6; Tephra keeps the support inside
// [lo, top], mirroring the lower face (partition of unity holds).
#include <cmath>

#include "mpm/shape/ShapeAxis.h"

namespace tephra {

inline void cubic_bspline_1d(double d, double& S, double& dS) {
  const double a = std::abs(d);
  if (a < 1.0) {
    S = 2.0 / 3.0 - d * d + 0.5 * a * a * a;
    dS = -2.0 * d + 1.5 * d * a;
  } else if (a < 2.0) {
    const double b = 2.0 - a;
    S = b * b * b / 6.0;
    dS = (d > 0 ? -0.5 : 0.5) * b * b;
  } else {
    S = 0.0;
    dS = 0.0;
  }
}

// Node lo + 1, d = xi - node in [-1, 2).
inline void cubic_bspline_type2(double d, double& S, double& dS) {
  if (d < -1.0 || d >= 2.0) {
    S = 0.0;
    dS = 0.0;
  } else if (d < 0.0) {
    S = ((-11.0 / 12.0 * d - 1.25) * d + 0.25) * d + 7.0 / 12.0;
    dS = (-11.0 / 4.0 * d - 2.5) * d + 0.25;
  } else if (d < 1.0) {
    S = ((7.0 / 12.0 * d - 1.25) * d + 0.25) * d + 7.0 / 12.0;
    dS = (7.0 / 4.0 * d - 2.5) * d + 0.25;
  } else {
    const double b = 2.0 - d;
    S = b * b * b / 6.0;
    dS = -0.5 * b * b;
  }
}

// Face node lo, d = xi - lo in [0, 2).
inline void cubic_bspline_type3(double d, double& S, double& dS) {
  if (d < 0.0 || d >= 2.0) {
    S = 0.0;
    dS = 0.0;
  } else if (d < 1.0) {
    S = 1.0 + d * d * (0.75 * d - 1.5);
    dS = d * (2.25 * d - 3.0);
  } else {
    const double b = 2.0 - d;
    S = 0.25 * b * b * b;
    dS = -0.75 * b * b;
  }
}

// Weight and d/dxi of node i for a particle at xi, interior nodes lo..top.
inline void cubic_bspline_node(double xi, int i, int lo, int top, double& S, double& dS) {
  if (i == lo) {
    cubic_bspline_type3(xi - i, S, dS);
  } else if (i == top) {
    cubic_bspline_type3(i - xi, S, dS);
    dS = -dS;
  } else if (i == lo + 1) {
    cubic_bspline_type2(xi - i, S, dS);
  } else if (i == top - 1) {
    cubic_bspline_type2(i - xi, S, dS);
    dS = -dS;
  } else {
    cubic_bspline_1d(xi - i, S, dS);
  }
}

// The nodes floor(xi) - 1 .. floor(xi) + 2 that lie in [lo, top] (2 to 4).
// Requires lo <= xi <= top and top - lo >= 3.
inline ShapeAxis cubic_bspline_axis(double xi, int lo, int top) {
  ShapeAxis a;
  const int ix = static_cast<int>(std::floor(xi));
  a.first = ix - 1 < lo ? lo : ix - 1;
  const int last = ix + 2 > top ? top : ix + 2;
  a.count = last - a.first + 1;
  for (int k = 0; k < a.count; ++k) cubic_bspline_node(xi, a.first + k, lo, top, a.S[k], a.dS[k]);
  return a;
}

}  // namespace tephra
