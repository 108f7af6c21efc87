// GIMP convolution for any half-length (mpm/shape/ShapeGimp.h gimp_axis_any)
// and the cpGIMP stencils (InterpolatorKind::CpGimp, l_d = l0_d F_dd).
// Oracles: for l <= 1/2 the closed form of eqs. 1.91-1.92 (gimp_1d);
// for any l in (0, 1]: partition of unity sum S = 1, linear completeness
// sum S_i i = xi, sum dS_i = 0, sum dS_i i = 1 (the convolution of the hat,
// which reproduces linear functions, with a normalised box reproduces them
// too), and dS = d S / d xi (central differences).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"
#include "mpm/shape/ShapeBspline.h"
#include "mpm/shape/ShapeGimp.h"

namespace tephra {
namespace {

TEST(MpmShapeCpGimp, AnyLengthEqualsTheClosedFormUpToHalf) {
  for (double l : {0.1, 0.25, 0.4, 0.5})
    for (double xi = 3.0; xi < 4.0; xi += 0.0137) {
      const ShapeAxis a = gimp_axis_any(xi, l);
      for (int k = 0; k < a.count; ++k) {
        double S, dS;
        gimp_1d(xi - (a.first + k), l, S, dS);
        ASSERT_NEAR(a.S[k], S, 1e-14) << "l " << l << " xi " << xi;
        ASSERT_NEAR(a.dS[k], dS, 1e-14) << "l " << l << " xi " << xi;
      }
    }
}

TEST(MpmShapeCpGimp, IdentitiesAndDerivativesForLongDomains) {
  for (double l : {0.3, 0.5, 0.58, 0.75, 1.0})
    for (double xi = 3.0; xi < 4.0; xi += 0.0173) {
      const ShapeAxis a = gimp_axis_any(xi, l);
      ASSERT_LE(a.count, 4);
      double sum = 0, sum_i = 0, sum_d = 0, sum_di = 0;
      for (int k = 0; k < a.count; ++k) {
        const int i = a.first + k;
        EXPECT_GE(a.S[k], 0.0);
        sum += a.S[k];
        sum_i += a.S[k] * i;
        sum_d += a.dS[k];
        sum_di += a.dS[k] * i;
      }
      ASSERT_NEAR(sum, 1.0, 1e-14);
      ASSERT_NEAR(sum_i, xi, 1e-13);
      ASSERT_NEAR(sum_d, 0.0, 1e-14);
      ASSERT_NEAR(sum_di, 1.0, 1e-13);
      // Every node outside the listed ones has |xi - i| >= 1 + l (zero weight).
      EXPECT_GE(xi - (a.first - 1), 1.0 + l - 1e-12);
      EXPECT_GE((a.first + a.count) - xi, 1.0 + l - 1e-12);
      // dS = dS/dxi, central differences. S is C1 with |S''| <= 1/l (S'' =
      // (hat'(d+l) - hat'(d-l))/(2l) jumps where d +- l hits a node), so the
      // difference is within eps/l of dS (O(eps^2) away from those points).
      const double eps = 1e-6;
      const ShapeAxis p = gimp_axis_any(xi + eps, l), m = gimp_axis_any(xi - eps, l);
      for (int k = 0; k < a.count; ++k) {
        const int i = a.first + k;
        auto S_at = [&](const ShapeAxis& b) {
          const int kk = i - b.first;
          return kk >= 0 && kk < b.count ? b.S[kk] : 0.0;
        };
        ASSERT_NEAR((S_at(p) - S_at(m)) / (2 * eps), a.dS[k], eps / l) << "l " << l << " xi " << xi;
      }
    }
}

// Three-dimensional cpGIMP stencils on a grid: the identities of every
// interpolator (as test_mpm_shape.cpp) with stretched and sheared F (the
// circumscribed half-lengths l_d = sum_j |(F size)_dj| / 2 span about 0.1 ..
// 0.85 cells), and a rejected particle whose domain exceeds one cell (l > 1)
// or is inverted (det F < 0).
TEST(MpmShapeCpGimp, StencilIdentitiesWithStretchedDomains) {
  NodeGrid g;
  g.origin = Vec3(-0.3, 0.2, 1.0);
  g.h = Vec3(0.1, 0.25, 0.05);
  g.n = IntVec3(10, 8, 7);
  g.reset();
  Particles p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 300; ++n) {
    Vec3 xi;
    for (int d = 0; d < 3; ++d) xi[d] = 2.5 + (g.n[d] - 6.0) * u(rng);
    const Mat3 size = Vec3(0.2 + 0.8 * u(rng), 0.2 + 0.8 * u(rng), 0.2 + 0.8 * u(rng)).asDiagonal();
    p.add(g.origin + xi.cwiseProduct(g.h), Vec3::Zero(), 1.0, 1e-3, 300.0, 0.0, n, size);
    Mat3 F = Vec3(0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng)).asDiagonal();
    if (n % 2) F += 0.1 * Mat3::Random();
    p.F.back() = F;
  }
  Stencils s;
  ASSERT_EQ(compute_stencils(p, g, {InterpolatorKind::CpGimp, 1e10}, s), -1);
  ASSERT_EQ(s.width, 64);
  for (std::size_t i = 0; i < p.size(); ++i) {
    double sum = 0;
    Vec3 sum_x = Vec3::Zero();
    Mat3 sum_x_grad = Mat3::Zero();
    for (std::size_t k = i * s.width; k < (i + 1) * s.width; ++k) {
      const std::size_t gi = s.node[k];
      const int a = int(gi % g.n[0]), b = int((gi / g.n[0]) % g.n[1]), c = int(gi / (std::size_t(g.n[0]) * g.n[1]));
      const Vec3 xg = g.position(a, b, c);
      sum += s.w[k];
      sum_x += s.w[k] * xg;
      sum_x_grad += xg * s.grad[k].transpose();
    }
    ASSERT_NEAR(sum, 1.0, 1e-13);
    ASSERT_NEAR((sum_x - p.x[i]).norm(), 0.0, 1e-13);
    ASSERT_NEAR((sum_x_grad - Mat3::Identity()).norm(), 0.0, 1e-12);
  }
  p.F[5] = Mat3::Identity();
  p.F[5](1, 1) = 2.5 / p.psize[5](1, 1);  // l = 1.25 cells
  EXPECT_EQ(compute_stencils(p, g, {InterpolatorKind::CpGimp, 1e10}, s), 5);
  p.F[5](1, 1) = -0.1;
  EXPECT_EQ(compute_stencils(p, g, {InterpolatorKind::CpGimp, 1e10}, s), 5);
}

// The positions of the AA runs at 1 particle per cell (cell centres, xi =
// k + 1/2) and of particles on nodes (xi = k), where the quadratic B-spline
// and uGIMP (l = 1/2, the same function) switch pieces: the gradient still
// reproduces a linear field exactly, sum dS_i i = 1 and sum dS_i = 0, and
// the values are the closed forms (B-spline at d = 0: 3/4, +-1: 1/8, slopes
// 0 and -+1/2; at d = +-1/2: 1/2 each, slopes -+1).
TEST(MpmShapeCpGimp, GradientCompletenessOnNodesAndCellCentres) {
  for (double xi : {3.0, 3.5, 3.0 + 1e-14, 3.5 - 1e-14}) {
    const ShapeAxis b = quadratic_bspline_axis(xi), g = gimp_axis(xi, 0.5);
    for (const ShapeAxis& a : {b, g}) {
      double sum_d = 0, sum_di = 0;
      for (int k = 0; k < a.count; ++k) {
        sum_d += a.dS[k];
        sum_di += a.dS[k] * (a.first + k);
      }
      EXPECT_NEAR(sum_d, 0.0, 1e-13) << xi;
      EXPECT_NEAR(sum_di, 1.0, 1e-13) << xi;
    }
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(b.S[k], g.S[k], 1e-14);
      EXPECT_NEAR(b.dS[k], g.dS[k], 1e-13);
    }
  }
  const ShapeAxis on = quadratic_bspline_axis(3.0);
  EXPECT_EQ(on.first, 2);
  EXPECT_DOUBLE_EQ(on.S[0], 0.125);
  EXPECT_DOUBLE_EQ(on.S[1], 0.75);
  EXPECT_DOUBLE_EQ(on.S[2], 0.125);
  EXPECT_DOUBLE_EQ(on.dS[0], -0.5);
  EXPECT_DOUBLE_EQ(on.dS[1], 0.0);
  EXPECT_DOUBLE_EQ(on.dS[2], 0.5);
}

}  // namespace
}  // namespace tephra
