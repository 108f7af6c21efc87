#pragma once
// Linear (tri-linear) MPM shape functions on a uniform grid, as pure functions
// (Vaango theory manual §1.6, eqs. 1.86-1.89):
//   1-D hat  S(x) = 1 - |x - x_g|/h  for |x - x_g| < h,  dS/dx = -sign(x - x_g)/h
//   3-D      S_g(x) = S(x) S(y) S(z),  grad S_g = (S'(x)S(y)S(z), S(x)S'(y)S(z), S(x)S(y)S'(z))
// A point in cell c = floor((x - lower)/h) has the 8 nodes c + {0,1}^3 as its
// support. Identities (tested): sum S_g = 1, sum S_g x_g = x, sum grad S_g = 0,
// sum x_g (grad S_g)^T = I.
#include <cmath>

#include "core/base/Types.h"

namespace tephra {

struct LinearStencil {
  IntVec3 cell;      // lower node of the support (= the containing cell)
  double w[8];       // S_g, node n = cell + (n&1, (n>>1)&1, (n>>2)&1)
  Vec3 grad[8];      // grad S_g [1/m]
  static IntVec3 offset(int n) { return IntVec3(n & 1, (n >> 1) & 1, (n >> 2) & 1); }
};

// Fills the stencil of point x on the grid whose node 0 is at `origin` with
// spacing h. The cell index is not range checked (the caller checks it).
inline void linear_stencil(const Vec3& x, const Vec3& origin, const Vec3& h, LinearStencil& s) {
  double lo_w[3], hi_w[3], inv_h[3];
  for (int d = 0; d < 3; ++d) {
    const double xi = (x[d] - origin[d]) / h[d];  // position in cell units
    const double c = std::floor(xi);
    s.cell[d] = static_cast<int>(c);
    const double r = xi - c;  // local coordinate in [0,1)
    lo_w[d] = 1.0 - r;        // hat of the lower node
    hi_w[d] = r;              // hat of the upper node
    inv_h[d] = 1.0 / h[d];
  }
  for (int n = 0; n < 8; ++n) {
    const int a = n & 1, b = (n >> 1) & 1, c = (n >> 2) & 1;
    const double sx = a ? hi_w[0] : lo_w[0], sy = b ? hi_w[1] : lo_w[1], sz = c ? hi_w[2] : lo_w[2];
    const double dx = (a ? 1.0 : -1.0) * inv_h[0], dy = (b ? 1.0 : -1.0) * inv_h[1],
                 dz = (c ? 1.0 : -1.0) * inv_h[2];
    s.w[n] = sx * sy * sz;
    s.grad[n] = Vec3(dx * sy * sz, sx * dy * sz, sx * sy * dz);
  }
}

}  // namespace tephra
