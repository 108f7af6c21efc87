#pragma once
// CPDI shape functions, `<interpolator>cpdi` (Vaango theory manual §1.6.4,
// eqs. 1.94-1.100; Sadeghirad, Brannon & Burghardt 2011).
//
// The particle domain is the parallelepiped spanned by the edge vectors
// e_i = F_p E_i (E = Vaango's reference pSize in node-index units, columns =
// full edges; eq. 1.97 with the half-edge vectors r_i = e_i / 2). Its corners
// are x_a = x_p + s R[:,a], s = [r1 r2 r3], a = 1..8 with the sign matrix R of
// eq. 1.99. The linear hat S_g (ShapeLinear.h) is interpolated from the
// corners with the trilinear N_a of the parallelepiped (eq. 1.95-1.96), so
//   S_gp = (1/8) sum_a S_g(x_a),            (eq. 1.100, first part)
//   G_gp = (1/8) s^{-T} sum_a R[:,a] S_g(x_a)  (eq. 1.100, second part).
// Each corner contributes its 8 hat nodes: 64 entries, nodes repeated
// (duplicates add up in the transfers, as in Vaango's cpdiInterpolator).
//
// <cpdi_lcrit> (Vaango's d_lcrit, node-index units, default 1e10 = off): the
// four half-diagonals d = (+-r1 +- r2 + r3) that reach the upper corners are
// shortened to length lcrit when longer, and the edge vectors are rebuilt
// from them (r1 = (d++ + d+- - d-+ - d--)/4 ... with d_{ab} = a r1 + b r2 + r3),
// which limits the support of a stretched particle.
#include <cmath>

#include <Eigen/LU>

#include "core/base/Types.h"

namespace tephra {

// Sign matrix R of eq. 1.99: corner a has signs (R(0,a), R(1,a), R(2,a)).
inline double cpdi_sign(int d, int a) {
  static constexpr double R[3][8] = {{-1, 1, 1, -1, -1, 1, 1, -1},
                                     {-1, -1, 1, 1, -1, -1, 1, 1},
                                     {-1, -1, -1, -1, 1, 1, 1, 1}};
  return R[d][a];
}

// Applies the lcrit limit to the half-edge matrix s (columns r1, r2, r3).
inline Mat3 cpdi_limit_half_edges(const Mat3& s, double lcrit) {
  // Half-diagonals to the four upper corners: d(b1, b2) = b1 r1 + b2 r2 + r3.
  Vec3 d[2][2];
  bool scaled = false;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      d[a][b] = (a ? 1.0 : -1.0) * s.col(0) + (b ? 1.0 : -1.0) * s.col(1) + s.col(2);
      const double len = d[a][b].norm();
      if (len > lcrit) {
        d[a][b] *= lcrit / len;
        scaled = true;
      }
    }
  if (!scaled) return s;
  Mat3 out;
  out.col(0) = 0.25 * (d[1][1] + d[1][0] - d[0][1] - d[0][0]);
  out.col(1) = 0.25 * (d[1][1] - d[1][0] + d[0][1] - d[0][0]);
  out.col(2) = 0.25 * (d[1][1] + d[1][0] + d[0][1] + d[0][0]);
  return out;
}

// Fills the 64 entries for a particle at xi (index units) with current edge
// matrix e = F E (index units, columns = full edges) on a grid of spacing h.
// Returns false when the domain is degenerate (det s <= 0).
inline bool cpdi_stencil(const Vec3& xi, const Mat3& edges, double lcrit, const Vec3& h, IntVec3* node,
                         double* w, Vec3* grad) {
  const Mat3 s = cpdi_limit_half_edges(0.5 * edges, lcrit);
  const double det = s.determinant();
  if (!(det > 0.0)) return false;
  // Physical half-edge matrix s_x = diag(h) s, so s_x^{-T} = diag(1/h) s^{-T}.
  const Mat3 sinvT = s.inverse().transpose();
  int n = 0;
  for (int a = 0; a < 8; ++a) {
    const Vec3 sign(cpdi_sign(0, a), cpdi_sign(1, a), cpdi_sign(2, a));
    const Vec3 corner = xi + s * sign;
    // (1/8) s_x^{-T} R[:,a], in physical units.
    Vec3 g = 0.125 * (sinvT * sign);
    g = g.cwiseQuotient(h);
    IntVec3 c;
    double r[3];
    for (int d = 0; d < 3; ++d) {
      const double f = std::floor(corner[d]);
      c[d] = static_cast<int>(f);
      r[d] = corner[d] - f;
    }
    for (int k = 0; k < 8; ++k, ++n) {
      const int i = k & 1, j = (k >> 1) & 1, l = (k >> 2) & 1;
      const double hat = (i ? r[0] : 1.0 - r[0]) * (j ? r[1] : 1.0 - r[1]) * (l ? r[2] : 1.0 - r[2]);
      node[n] = c + IntVec3(i, j, l);
      w[n] = 0.125 * hat;
      grad[n] = hat * g;
    }
  }
  return true;
}

}  // namespace tephra
