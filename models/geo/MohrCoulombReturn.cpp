#include "models/geo/MohrCoulombReturn.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

namespace tephra {

namespace {
using V3 = Eigen::Vector3d;

// Gradient of f_ij (angle phi) or of g_ij (angle psi) in principal space.
V3 plane_vector(int i, int j, double sin_angle) {
  V3 v = V3::Zero();
  v(i) = 1.0 + sin_angle;
  v(j) = -(1.0 - sin_angle);
  return v;
}

double f_ij(const MohrCoulombParams& m, const V3& s, int i, int j) {
  return (s(i) - s(j)) + (s(i) + s(j)) * std::sin(m.phi) - 2.0 * m.c * std::cos(m.phi);
}

Eigen::Matrix3d elastic_matrix(const MohrCoulombParams& m) {
  return (m.K - 2.0 * m.G / 3.0) * Eigen::Matrix3d::Ones() + 2.0 * m.G * Eigen::Matrix3d::Identity();
}

bool ordered(const V3& s, double tol) { return s(0) >= s(1) - tol && s(1) >= s(2) - tol; }
}  // namespace

double mohr_coulomb_f13(const MohrCoulombParams& m, const V3& s) { return f_ij(m, s, 0, 2); }

double mohr_coulomb_yield_invariants(const MohrCoulombParams& m, const Eigen::Matrix3d& sig) {
  const double p = sig.trace() / 3.0;
  const Eigen::Matrix3d s = sig - p * Eigen::Matrix3d::Identity();
  const double J2 = 0.5 * s.squaredNorm(), J3 = s.determinant();
  const double q = std::sqrt(3.0 * J2);
  double c3 = J2 > 0.0 ? 1.5 * std::sqrt(3.0) * J3 / std::pow(J2, 1.5) : 1.0;
  c3 = std::max(-1.0, std::min(1.0, c3));
  const double theta = std::acos(c3) / 3.0;  // in [0, pi/3]
  const double R = std::sin(theta + M_PI / 3.0) / std::sqrt(3.0) - std::sin(m.phi) * std::cos(theta + M_PI / 3.0) / 3.0;
  return R * q - p * std::sin(m.phi) - m.c * std::cos(m.phi);
}

MohrCoulombReturnResult mohr_coulomb_return(const MohrCoulombParams& m, const V3& s_tr) {
  MohrCoulombReturnResult r;
  r.s = s_tr;
  const double scale = std::abs(s_tr(0)) + std::abs(s_tr(2)) + m.c + 1e-300;
  const double tol = 1e-13 * scale;
  if (!(mohr_coulomb_f13(m, s_tr) > tol)) return r;  // elastic
  const Eigen::Matrix3d D = elastic_matrix(m);
  const double sphi = std::sin(m.phi), spsi = std::sin(m.psi);
  // 1. main plane
  {
    const V3 a = plane_vector(0, 2, sphi), Dn = D * plane_vector(0, 2, spsi);
    const double dg = mohr_coulomb_f13(m, s_tr) / a.dot(Dn);
    const V3 s = s_tr - dg * Dn;
    if (ordered(s, tol)) {
      r.s = s;
      r.region = MohrCoulombRegion::main_plane;
      r.dgamma[0] = dg;
      return r;
    }
    // 2. an edge: s1 = s2 when the main return pushed s2 above s1, else s2 = s3
    const bool compression_edge = s(1) > s(0);
    const int i2 = compression_edge ? 1 : 0, j2 = compression_edge ? 2 : 1;
    const V3 b = plane_vector(i2, j2, sphi), Dm = D * plane_vector(i2, j2, spsi);
    Eigen::Matrix2d A;
    A << a.dot(Dn), a.dot(Dm), b.dot(Dn), b.dot(Dm);
    const Eigen::Vector2d rhs(mohr_coulomb_f13(m, s_tr), f_ij(m, s_tr, i2, j2));
    const Eigen::Vector2d g = A.fullPivLu().solve(rhs);
    const V3 se = s_tr - g(0) * Dn - g(1) * Dm;
    if (g(0) >= 0.0 && g(1) >= 0.0 && ordered(se, tol)) {
      r.s = se;
      if (compression_edge) r.s(0) = r.s(1) = 0.5 * (se(0) + se(1));  // exact equality on the edge
      else r.s(1) = r.s(2) = 0.5 * (se(1) + se(2));
      r.region = compression_edge ? MohrCoulombRegion::edge_compression : MohrCoulombRegion::edge_extension;
      r.dgamma[0] = g(0);
      r.dgamma[1] = g(1);
      return r;
    }
  }
  // 3. apex (tension positive: p = c cot(phi))
  r.region = MohrCoulombRegion::apex;
  r.s = V3::Constant(sphi > 0.0 ? m.c * std::cos(m.phi) / sphi : std::numeric_limits<double>::quiet_NaN());
  return r;
}

}  // namespace tephra
