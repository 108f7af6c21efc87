#pragma once
// CPTI shape functions, `<interpolator>cpti`: convected particle domain
// interpolation with a tetrahedral particle domain (Leavy et al. 2019,
// Comput. Mech. 64, theory manual ref. [10]; Sadeghirad, Brannon & Guilkey
// 2013 "CPDI2" for the tetrahedron form). Facts checked in Vaango's
// CPTIInterpolator.cc (not copied):
//
// * One tetrahedron per particle, spanned by the current edge vectors
//   r_i = F_p E_i (columns of F p.size, full edges in node-index units, the
//   same vectors that span the CPDI parallelepiped). Its corners, relative
//   to the particle, are
//     c_0 = -(r_1 + r_2 + r_3)/4,   c_i = c_0 + r_i  (i = 1, 2, 3),
//   so the tetrahedron's centroid sum_a c_a / 4 is the particle position.
//   Its volume is det[r_1 r_2 r_3]/6 (Vaango keeps the particle volume
//   J V0 separately; the tetrahedron only sets the support).
// * The linear hat S_g (ShapeLinear.h) is interpolated from the corners with
//   the barycentric functions N_a of the tetrahedron:
//     S_gp = (1/4) sum_a S_g(x_a)              (domain average of sum N_a S_g(x_a))
//     G_gp = sum_a S_g(x_a) grad N_a           (grad N_a constant on the tet)
//   with grad N_1 = (r_2 x r_3)/det, grad N_2 = (r_3 x r_1)/det,
//   grad N_3 = (r_1 x r_2)/det, grad N_0 = -(grad N_1 + grad N_2 + grad N_3),
//   det = r_1 . (r_2 x r_3) (the rows of [r_1 r_2 r_3]^{-1}).
//   Each corner contributes its 8 hat nodes: 32 entries, nodes repeated.
// * Identities: sum_g S_gp = 1; sum_g S_gp x_g = sum_a x_a / 4 = x_p;
//   sum_g x_g G_gp^T = sum_a x_a grad N_a^T = I (barycentric identity), so
//   an affine field is reproduced exactly, as by CPDI.
// * <cpdi_lcrit> (Vaango's d_lcrit, node-index units): a corner vector c_a
//   longer than lcrit is shortened to lcrit and the edges rebuilt from the
//   shortened corners, r_i = c_i - c_0, then the tetrahedron is re-centred.
//   (Vaango's rebuild writes all three edges into the first column of its
//   size matrix, which leaves r_2, r_3 unchanged and r_1 = c_3 - c_0; Tephra
//   rebuilds each edge from its own corner.)
#include <cmath>

#include <Eigen/Geometry>  // cross
#include <Eigen/LU>        // determinant

#include "core/base/Types.h"

namespace tephra {

// Corner vectors c_0..c_3 (relative to the particle, index units) of the
// tetrahedron spanned by the edge matrix e (columns r_1, r_2, r_3), with the
// lcrit limit applied; writes the edges actually used to `used`.
inline void cpti_corners(const Mat3& e, double lcrit, Vec3 c[4], Mat3& used) {
  used = e;
  c[0] = -0.25 * (e.col(0) + e.col(1) + e.col(2));
  for (int i = 1; i < 4; ++i) c[i] = c[0] + e.col(i - 1);
  bool frozen = false;
  for (int a = 0; a < 4; ++a) {
    const double len = c[a].norm();
    if (len > lcrit) {
      c[a] *= lcrit / len;
      frozen = true;
    }
  }
  if (!frozen) return;
  for (int i = 0; i < 3; ++i) used.col(i) = c[i + 1] - c[0];
  c[0] = -0.25 * (used.col(0) + used.col(1) + used.col(2));
  for (int i = 1; i < 4; ++i) c[i] = c[0] + used.col(i - 1);
}

// Fills the 32 entries for a particle at xi (index units) with current edge
// matrix `edges` = F size (index units, columns = full edges) on a grid of
// spacing h. Returns false when the tetrahedron is degenerate (det <= 0).
inline bool cpti_stencil(const Vec3& xi, const Mat3& edges, double lcrit, const Vec3& h, IntVec3* node,
                         double* w, Vec3* grad) {
  Vec3 c[4];
  Mat3 r;
  cpti_corners(edges, lcrit, c, r);
  const double det = r.determinant();
  if (!(det > 0.0)) return false;
  // Barycentric gradients in index units; physical = diag(1/h) (index).
  Vec3 gN[4];
  gN[1] = r.col(1).cross(r.col(2)) / det;
  gN[2] = r.col(2).cross(r.col(0)) / det;
  gN[3] = r.col(0).cross(r.col(1)) / det;
  gN[0] = -(gN[1] + gN[2] + gN[3]);
  int n = 0;
  for (int a = 0; a < 4; ++a) {
    const Vec3 corner = xi + c[a];
    const Vec3 g = gN[a].cwiseQuotient(h);
    IntVec3 base;
    double f[3];
    for (int d = 0; d < 3; ++d) {
      const double fl = std::floor(corner[d]);
      base[d] = static_cast<int>(fl);
      f[d] = corner[d] - fl;
    }
    for (int k = 0; k < 8; ++k, ++n) {
      const int i = k & 1, j = (k >> 1) & 1, l = (k >> 2) & 1;
      const double hat = (i ? f[0] : 1.0 - f[0]) * (j ? f[1] : 1.0 - f[1]) * (l ? f[2] : 1.0 - f[2]);
      node[n] = base + IntVec3(i, j, l);
      w[n] = 0.25 * hat;
      grad[n] = hat * g;
    }
  }
  return true;
}

}  // namespace tephra
