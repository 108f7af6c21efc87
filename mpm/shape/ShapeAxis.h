#pragma once
// One-dimensional factors of tensor-product MPM shape functions, and their
// product into 3-D weights and gradients.
//
// Coordinates are in node-index units: xi = (x - origin)/h, so node i sits at
// xi = i. An axis holds `count` consecutive nodes first..first+count-1 with
// the factor S(xi) and its derivative dS/dxi (1/h is applied in the product).
//   3-D:  S_g = Sx Sy Sz,
//         grad S_g = (dSx Sy Sz / hx, Sx dSy Sz / hy, Sx Sy dSz / hz).
#include "core/base/Types.h"

namespace tephra {

struct ShapeAxis {
  int first = 0;       // lowest node index of the support
  int count = 0;       // nodes in the support (2 linear, 3 GIMP / quadratic B-spline)
  double S[4] = {};    // factor of node first + a
  double dS[4] = {};   // d factor / d xi  [per index unit]
};

// Writes the count_x count_y count_z entries (x fastest) of the tensor
// product; returns the number written. `node`, `w`, `grad` must hold 64.
inline int tensor_product(const ShapeAxis ax[3], const Vec3& h, IntVec3* node, double* w, Vec3* grad) {
  int n = 0;
  for (int c = 0; c < ax[2].count; ++c)
    for (int b = 0; b < ax[1].count; ++b)
      for (int a = 0; a < ax[0].count; ++a, ++n) {
        node[n] = IntVec3(ax[0].first + a, ax[1].first + b, ax[2].first + c);
        const double sx = ax[0].S[a], sy = ax[1].S[b], sz = ax[2].S[c];
        w[n] = sx * sy * sz;
        grad[n] = Vec3(ax[0].dS[a] * sy * sz / h[0], sx * ax[1].dS[b] * sz / h[1], sx * sy * ax[2].dS[c] / h[2]);
      }
  return n;
}

}  // namespace tephra
