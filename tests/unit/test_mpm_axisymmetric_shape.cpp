// Axisymmetric stencils of every interpolator (mpm/shape/ShapeAxisymmetric.h,
// mpm/Axisymmetric.cpp): the identities that make a uniform radial
// expansion and a rigid axial translation exact, and the closed-form radial
// factors of Vaango's AxiGIMPInterpolator.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpm/Axisymmetric.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/ShapeAxisymmetric.h"
#include "mpm/shape/ShapeBspline.h"
#include "mpm/shape/ShapeBsplineCubic.h"

namespace tephra {
namespace {

// A grid with the axis at node 1 (one extra layer at r = -h), one hoop cell,
// particles with random sizes (and, for CPDI, random in-plane F), some of
// them touching the axis.
struct AxiCloud {
  NodeGrid g;
  Particles p;
  explicit AxiCloud(int count) {
    g.h = Vec3(0.1, 0.25, 0.05);
    g.origin = Vec3(-0.1, -0.25, -0.05);
    g.n = IntVec3(12, 10, 3);
    g.extra = IntVec3(1, 1, 1);
    g.reset();
    std::mt19937 rng(777);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
      // r from 0.01 (inside the first cell: the domain may cross the axis) to 0.8, z inside.
      const Vec3 x(0.01 + 0.79 * u(rng), 0.5 + 1.0 * u(rng), 0.025);
      const double sr = 0.2 + 0.8 * u(rng), sz = 0.2 + 0.8 * u(rng);
      p.add(x, Vec3::Zero(), 1.0, 1e-3, 300.0, 0.0, i, Vec3(sr, sz, 1.0).asDiagonal());
      Mat3 F = Mat3::Identity();
      F(0, 0) += 0.3 * (u(rng) - 0.5);
      F(1, 1) += 0.3 * (u(rng) - 0.5);
      F(0, 1) = 0.2 * (u(rng) - 0.5);
      F(1, 0) = 0.2 * (u(rng) - 0.5);
      F(2, 2) = 1.1;
      p.F.back() = F;
    }
  }
  Vec3 node_position(std::size_t n) const {
    const std::size_t nx = g.n[0], ny = g.n[1];
    const int i = int(n % nx), j = int((n / nx) % ny), k = int(n / (nx * ny));
    return g.origin + Vec3(i * g.h[0], j * g.h[1], k * g.h[2]);
  }
};

class AxisymmetricStencils : public ::testing::TestWithParam<InterpolatorKind> {};

// For every particle: sum S = 1; sum grad_r = sum grad_z = 0; sum r_i grad_r = 1,
// sum z_i grad_z = 1, sum z_i grad_r = sum r_i grad_z = 0 (linear fields have
// their exact in-plane gradient); sum r_i T = 1 (v_r = a r gives v_r / r = a);
// sum z_i S = z_p (the axial direction is Cartesian).
TEST_P(AxisymmetricStencils, PartitionOfUnityAndLinearGradients) {
  AxiCloud c(400);
  Stencils s;
  ASSERT_EQ(compute_axisymmetric_stencils(c.p, c.g, GetParam(), s), -1);
  const int W = s.width;
  ASSERT_EQ(W, axisymmetric_stencil_width(GetParam()));
  double worst = 0;
  int checked = 0;
  for (std::size_t i = 0; i < c.p.size(); ++i) {
    double S = 0, gr = 0, gz = 0, rgr = 0, zgz = 0, zgr = 0, rgz = 0, rT = 0, zS = 0;
    for (int e = 0; e < W; ++e) {
      const std::size_t k = i * W + e;
      const Vec3 x = c.node_position(s.node[k]);
      S += s.w[k];
      gr += s.grad[k][0];
      gz += s.grad[k][1];
      rgr += x[0] * s.grad[k][0];
      zgz += x[1] * s.grad[k][1];
      zgr += x[1] * s.grad[k][0];
      rgz += x[0] * s.grad[k][1];
      rT += x[0] * s.grad[k][2];
      zS += x[1] * s.w[k];
    }
    // 4thorderBS: Vaango's boundary-modified splines reproduce a linear
    // field only where every support node is of type 1 (three nodes from
    // each face, ShapeBsplineCubic.h); elsewhere only the partition of unity
    // (sum S = 1, sum grad S = 0) holds.
    const double xi_r = (c.p.x[i][0] - c.g.origin[0]) / c.g.h[0], xi_z = (c.p.x[i][1] - c.g.origin[1]) / c.g.h[1];
    const bool linear_complete = GetParam() != InterpolatorKind::CubicBspline ||
                                 (xi_r >= c.g.extra[0] + 3 && xi_r <= c.g.n[0] - 1 - c.g.extra[0] - 3 &&
                                  xi_z >= c.g.extra[1] + 3 && xi_z <= c.g.n[1] - 1 - c.g.extra[1] - 3);
    if (linear_complete) {
      ++checked;
      for (double err : {S - 1, gr, gz, rgr - 1, zgz - 1, zgr, rgz, rT - 1, zS - c.p.x[i][1]})
        worst = std::max(worst, std::abs(err));
    } else {
      for (double err : {S - 1, gr, gz}) worst = std::max(worst, std::abs(err));
    }
  }
  std::printf("%s axisymmetric stencils: worst identity error %.3e over %zu particles (%d with the linear ones)\n",
              interpolator_name(GetParam()).c_str(), worst, c.p.size(), checked);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GE(checked, GetParam() == InterpolatorKind::CubicBspline ? 20 : 400);
}

INSTANTIATE_TEST_SUITE_P(AllInterpolators, AxisymmetricStencils,
                         ::testing::Values(InterpolatorKind::Linear, InterpolatorKind::Gimp, InterpolatorKind::Cpdi,
                                           InterpolatorKind::Cpti, InterpolatorKind::QuadraticBspline,
                                           InterpolatorKind::CubicBspline, InterpolatorKind::CpGimp));

// The planar-weight forms (3rdorderBS, 4thorderBS, cpgimp; cpti = axiCpdi):
// the hoop factor is T = S / r_p for every entry, and for the B-splines each
// in-plane weight is the planar one halved over the two hoop planes,
// S = N(xi_r - i) N(xi_z - j) / 2 with the 1-D splines of ShapeBspline.h
// (uniform quadratic) and ShapeBsplineCubic.h (boundary-modified cubic).
TEST(AxisymmetricPlanarForms, HalfPlanarWeightsAndHoopFactor) {
  AxiCloud c(50);
  for (InterpolatorKind kind : {InterpolatorKind::QuadraticBspline, InterpolatorKind::CubicBspline,
                                InterpolatorKind::CpGimp, InterpolatorKind::Cpti}) {
    Stencils s;
    ASSERT_EQ(compute_axisymmetric_stencils(c.p, c.g, kind, s), -1);
    double worst_T = 0, worst_S = 0;
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      const double xr = (c.p.x[i][0] - c.g.origin[0]) / c.g.h[0], xz = (c.p.x[i][1] - c.g.origin[1]) / c.g.h[1];
      for (int e = 0; e < s.width; ++e) {
        const std::size_t k = i * s.width + e;
        worst_T = std::max(worst_T, std::abs(s.grad[k][2] - s.w[k] / c.p.x[i][0]));
        if (s.w[k] == 0.0) continue;
        const int ni = int(s.node[k] % c.g.n[0]), nj = int((s.node[k] / c.g.n[0]) % c.g.n[1]);
        double Sr = 0, Sz = 0, d;
        if (kind == InterpolatorKind::QuadraticBspline) {
          quadratic_bspline_1d(xr - ni, Sr, d);
          quadratic_bspline_1d(xz - nj, Sz, d);
        } else if (kind == InterpolatorKind::CubicBspline) {
          cubic_bspline_node(xr, ni, c.g.extra[0], c.g.n[0] - 1 - c.g.extra[0], Sr, d);
          cubic_bspline_node(xz, nj, c.g.extra[1], c.g.n[1] - 1 - c.g.extra[1], Sz, d);
        } else {
          continue;
        }
        worst_S = std::max(worst_S, std::abs(s.w[k] - 0.5 * Sr * Sz));
      }
    }
    EXPECT_LT(worst_T, 1e-12) << interpolator_name(kind);
    EXPECT_LT(worst_S, 1e-15) << interpolator_name(kind);
  }
}

// GIMP: sum r_i S_i is the r-weighted centroid of the (clipped) domain,
// int r^2 dr / int r dr = (2/3)(b^3 - a^3)/(b^2 - a^2), which lies outside r_p
// by l^2 / (3 r_p) when the domain does not touch the axis.
TEST(AxisymmetricGimp, WeightsHaveTheVolumeCentroid) {
  const double h = 0.1;
  for (double rp : {0.013, 0.05, 0.137, 0.42}) {
    const double l = 0.03;
    double a, b;
    axi_gimp_interval(rp, l, a, b);
    double rS = 0;
    for (int i = -1; i < 8; ++i) rS += i * h * axi_gimp_radial(i * h, h, a, b).S;
    const double centroid = 2.0 / 3.0 * (b * b * b - a * a * a) / (b * b - a * a);
    EXPECT_NEAR(rS, centroid, 1e-14) << rp;
    if (rp > l) EXPECT_NEAR(centroid, rp + l * l / (3 * rp), 1e-14);
  }
}

// Closed forms of Vaango's AxiGIMPInterpolator (natural coordinate
// xi = 2 (r - r_i)/h of the particle from its left node i, nr = r_i / h,
// lp = 2 l / h):
//  - particle domain inside [r_i, r_i + h]:   S_i = (2 - xi)/2 - lp^2 / (6 (2 nr + xi)),
//                                             T_i = ((2 - xi)/2) / r_p  (the Cartesian weight / r_p);
//  - domain clipped at the axis (r_i = 0):    S_0 = (3 - lp - xi)/3, S_1 = (lp + xi)/3,
//                                             T_0 = (4/(lp + xi) - 1)/h, T_1 = 1/h, dS_0/dr = -1/h.
TEST(AxisymmetricGimp, RadialFactorsMatchVaangosClosedForms) {
  const double h = 0.1, l = 0.025, lp = 2 * l / h;
  {
    const double ri = 0.3, rp = 0.345, xi = 2 * (rp - ri) / h, nr = ri / h;
    double a, b;
    axi_gimp_interval(rp, l, a, b);
    const AxiRadialFactor f = axi_gimp_radial(ri, h, a, b);
    EXPECT_NEAR(f.S, (2 - xi) / 2 - lp * lp / (6 * (2 * nr + xi)), 1e-14);
    EXPECT_NEAR(f.T, ((2 - xi) / 2) / rp, 1e-13);
    EXPECT_NEAR(f.G, -1 / h, 1e-12);
  }
  {
    const double rp = 0.01, xi = 2 * rp / h;  // l > r_p: the domain [0, r_p + l]
    double a, b;
    axi_gimp_interval(rp, l, a, b);
    ASSERT_EQ(a, 0.0);
    const AxiRadialFactor f0 = axi_gimp_radial(0.0, h, a, b), f1 = axi_gimp_radial(h, h, a, b);
    EXPECT_NEAR(f0.S, (3 - lp - xi) / 3, 1e-14);
    EXPECT_NEAR(f1.S, (lp + xi) / 3, 1e-14);
    EXPECT_NEAR(f0.T, (4 / (lp + xi) - 1) / h, 1e-11);
    EXPECT_NEAR(f1.T, 1 / h, 1e-12);
    EXPECT_NEAR(f0.G, -1 / h, 1e-12);
    EXPECT_EQ(axi_gimp_radial(-h, h, a, b).S, 0.0);  // the node beyond the axis has no weight
  }
}

}  // namespace
}  // namespace tephra
