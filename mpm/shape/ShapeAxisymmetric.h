#pragma once
// Radial and in-plane factors of the axisymmetric GIMP and CPDI
// interpolators (x = r, y = z, per-radian volumes; mpm/Axisymmetric.h).
//
// Axisymmetric GIMP (Vaango's AxiGIMPInterpolator, checked against its
// formulas): the GIMP averages of theory manual eq. 1.90 taken with the
// axisymmetric volume element dV = r dr dz over the particle's rectangle
// [r_p - l_r, r_p + l_r] x [z_p - l_z, z_p + l_z], clipped at the axis r >= 0
// (Vaango's "r -> 0 treatment" is this clipped integral):
//   S_ip      = (1/V_p) int N_i dV      = SR_i SZ_i,   SR_i = int N_i r dr / W
//   dS_ip/dr  = (1/V_p) int dN_i/dr dV  = GR_i SZ_i,   GR_i = int N_i' r dr / W
//   dS_ip/dz  = SR_i dSZ_i/dz                          (SZ: Cartesian uGIMP, ShapeGimp.h)
//   T_ip      = (1/V_p) int N_i / r dV  = TR_i SZ_i,   TR_i = int N_i dr / W
// with W = int r dr = (b^2 - a^2)/2 over the clipped radial interval [a, b].
// T is the hoop factor: l_thth = sum_i v_r,i T_ip and the hoop stress term of
// the internal force, sigma_thth T_ip (Axisymmetric.h).
// Identities (the tests): sum_i SR_i = 1, sum_i GR_i = 0, sum_i r_i GR_i = 1
// (a radial velocity a r has dv_r/dr = a), sum_i r_i TR_i = 1 (v_r = a r has
// v_r / r = a), sum_i r_i SR_i = int r^2 dr / W (the r-weighted centroid).
//
// Axisymmetric CPDI (Vaango's axiCpdiInterpolator): the planar CPDI of the
// parallelogram spanned by the in-plane edges F_2x2 size_2x2 (4 corners
// x_c = x_p + s R_c, s = the half-edge matrix, R_c = (+-1, +-1)):
//   S_ip = (1/4) sum_c N_i(x_c),  grad S_ip = (1/4) s^{-T} sum_c R_c N_i(x_c),
//   T_ip = S_ip / r_p
// (sum_i r_i T_ip = mean of the corners' r / r_p = 1 for a parallelogram).
//
// Each in-plane weight is split equally between the two hoop node planes
// (factor 1/2), as the linear axisymmetric interpolator does.
#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "core/base/Types.h"

namespace tephra {

struct AxiRadialFactor {
  double S = 0.0;  // SR_i
  double G = 0.0;  // GR_i  [1/m]
  double T = 0.0;  // TR_i  [1/m]
};

// The radial factors of the hat of node r_i (support [r_i - h, r_i + h]) over
// [a, b] (0 <= a < b), exact: on each linear piece of the hat the integrands
// N, N r, N' r are polynomials of degree <= 2, integrated by Simpson's rule.
inline AxiRadialFactor axi_gimp_radial(double r_i, double h, double a, double b) {
  double I0 = 0.0, I1 = 0.0, D1 = 0.0;
  for (int piece = 0; piece < 2; ++piece) {
    const double lo = piece == 0 ? r_i - h : r_i, hi = piece == 0 ? r_i : r_i + h;
    const double c = std::max(lo, a), d = std::min(hi, b);
    if (!(d > c)) continue;
    // N on this piece: rising (r - (r_i - h))/h, falling (r_i + h - r)/h.
    const double slope = piece == 0 ? 1.0 / h : -1.0 / h;
    auto N = [&](double r) { return piece == 0 ? (r - lo) / h : (hi - r) / h; };
    const double m = 0.5 * (c + d);
    I0 += (d - c) * 0.5 * (N(c) + N(d));
    I1 += (d - c) / 6.0 * (N(c) * c + 4.0 * N(m) * m + N(d) * d);
    D1 += slope * 0.5 * (d * d - c * c);
  }
  const double W = 0.5 * (b * b - a * a);
  return {I1 / W, D1 / W, I0 / W};
}

// The clipped radial interval of a GIMP particle at r_p with half-length l.
inline void axi_gimp_interval(double r_p, double l, double& a, double& b) {
  a = std::max(0.0, r_p - l);
  b = r_p + l;
}

// Planar CPDI corners of the parallelogram with in-plane full edges e (index
// units, columns = edges) around xi (index units). Returns false when the
// domain is degenerate (det <= 0). corner[c] in index units, gfac[c] the
// physical-unit gradient factor (1/4) s_x^{-T} R_c.
inline bool axi_cpdi_corners(const Vec3& xi, const Eigen::Matrix2d& e, const Vec3& h, Vec3 corner[4],
                             Eigen::Vector2d gfac[4]) {
  const Eigen::Matrix2d s = 0.5 * e;
  const double det = s.determinant();
  if (!(det > 0.0)) return false;
  const Eigen::Matrix2d sinvT = s.inverse().transpose();
  static constexpr double R[2][4] = {{-1, 1, 1, -1}, {-1, -1, 1, 1}};
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d sign(R[0][c], R[1][c]);
    const Eigen::Vector2d off = s * sign;
    corner[c] = Vec3(xi[0] + off[0], xi[1] + off[1], xi[2]);
    const Eigen::Vector2d g = 0.25 * (sinvT * sign);
    gfac[c] = Eigen::Vector2d(g[0] / h[0], g[1] / h[1]);
  }
  return true;
}

}  // namespace tephra
