// MPM shape functions (mpm/shape/): linear, GIMP, CPDI, quadratic B-spline.
// Identities every interpolator must satisfy at any point (Vaango theory
// manual §1.6): partition of unity sum S = 1, linear completeness
// sum S_g x_g = x, sum grad S_g = 0, sum x_g (grad S_g)^T = I; gradients equal
// the derivative of the weights (central differences); and the values of the
// inventory (seed-inventory-vaango-theory.md, Chapter 1 oracles).
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/Transfers.h"
#include "mpm/shape/Interpolator.h"
#include "mpm/shape/ShapeBspline.h"
#include "mpm/shape/ShapeCpdi.h"
#include "mpm/shape/ShapeGimp.h"
#include "mpm/shape/ShapeLinear.h"

namespace tephra {
namespace {

const InterpolatorKind kAll[] = {InterpolatorKind::Linear, InterpolatorKind::Gimp, InterpolatorKind::Cpdi,
                                 InterpolatorKind::QuadraticBspline, InterpolatorKind::Cpti};

// A non-cubic grid with an offset origin, particles in its interior (two node
// layers from the edge) with random sizes and deformation gradients.
struct Cloud {
  NodeGrid g;
  Particles p;
  explicit Cloud(int count, bool deformed) {
    g.origin = Vec3(-0.3, 0.2, 1.0);
    g.h = Vec3(0.1, 0.25, 0.05);
    g.n = IntVec3(10, 8, 7);
    g.reset();
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < count; ++i) {
      Vec3 xi;
      for (int d = 0; d < 3; ++d) xi[d] = 2.0 + (g.n[d] - 5.0) * u(rng);
      const Vec3 x = g.origin + xi.cwiseProduct(g.h);
      const Mat3 size = Vec3(0.2 + 0.8 * u(rng), 0.2 + 0.8 * u(rng), 0.2 + 0.8 * u(rng)).asDiagonal();
      p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3, 300.0, 0.0, i, size);
      if (deformed) p.F.back() = Mat3::Identity() + 0.3 * Mat3::Random();
    }
  }
  Vec3 node_position(std::size_t gi) const {
    const int i = int(gi % g.n[0]), j = int((gi / g.n[0]) % g.n[1]), k = int(gi / (std::size_t(g.n[0]) * g.n[1]));
    return g.position(i, j, k);
  }
};

TEST(MpmShape, IdentitiesForEveryInterpolator) {
  for (InterpolatorKind kind : kAll) {
    SCOPED_TRACE(interpolator_name(kind));
    Cloud c(500, true);
    Stencils s;
    ASSERT_EQ(compute_stencils(c.p, c.g, InterpolatorSpec{kind, 1e10}, s), -1);
    ASSERT_EQ(s.width, stencil_width(kind));
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      double sum = 0;
      Vec3 sum_x = Vec3::Zero(), sum_grad = Vec3::Zero();
      Mat3 sum_x_grad = Mat3::Zero();
      for (std::size_t k = i * s.width; k < (i + 1) * s.width; ++k) {
        EXPECT_GE(s.w[k], -1e-15);
        const Vec3 xg = c.node_position(s.node[k]);
        sum += s.w[k];
        sum_x += s.w[k] * xg;
        sum_grad += s.grad[k];
        sum_x_grad += xg * s.grad[k].transpose();
      }
      ASSERT_NEAR(sum, 1.0, 1e-13);
      ASSERT_NEAR((sum_x - c.p.x[i]).norm(), 0.0, 1e-13);
      ASSERT_NEAR(sum_grad.cwiseProduct(c.g.h).norm(), 0.0, 1e-12);  // grad ~ 1/h
      ASSERT_NEAR((sum_x_grad - Mat3::Identity()).norm(), 0.0, 1e-12);
    }
  }
}

// grad S_gp is the derivative of S_gp with respect to x_p (central differences,
// step 1e-6 h; truncation O(1e-12 / h)) for the tensor-product functions.
// Not for CPDI: its G_gp is the domain average of the gradient of the
// trilinear interpolant of the corner values (eq. 1.100), which differs from
// d/dx_p of the corner average once the corners span a node.
TEST(MpmShape, GradientsAreDerivativesOfTheWeights) {
  for (InterpolatorKind kind : {InterpolatorKind::Linear, InterpolatorKind::Gimp, InterpolatorKind::QuadraticBspline}) {
    SCOPED_TRACE(interpolator_name(kind));
    Cloud c(100, true);
    Stencils s0, sp, sm;
    ASSERT_EQ(compute_stencils(c.p, c.g, {kind, 1e10}, s0), -1);
    for (int d = 0; d < 3; ++d) {
      const double eps = 1e-6 * c.g.h[d];
      Cloud cp = c, cm = c;
      for (std::size_t i = 0; i < c.p.size(); ++i) {
        cp.p.x[i][d] += eps;
        cm.p.x[i][d] -= eps;
      }
      ASSERT_EQ(compute_stencils(cp.p, cp.g, {kind, 1e10}, sp), -1);
      ASSERT_EQ(compute_stencils(cm.p, cm.g, {kind, 1e10}, sm), -1);
      for (std::size_t i = 0; i < c.p.size(); ++i) {
        // Accumulate per node (entries may repeat nodes or change order).
        std::map<std::size_t, double> fd, an;
        for (std::size_t k = i * s0.width; k < (i + 1) * s0.width; ++k) {
          an[s0.node[k]] += s0.grad[k][d];
          fd[sp.node[k]] += sp.w[k] / (2 * eps);
          fd[sm.node[k]] -= sm.w[k] / (2 * eps);
        }
        for (auto [node, g] : an) EXPECT_NEAR(fd[node], g, 1e-5 / c.g.h[d]) << "particle " << i << " dir " << d;
      }
    }
  }
}

// Inventory table (eqs. 1.91-1.92, h = 1, l_p = 0.25, d = x_p - x_g).
TEST(MpmShape, GimpOneDimensionalValuesOfTheInventory) {
  const double l = 0.25;
  struct Row { double d, S, G; };
  const Row rows[] = {{0.0, 0.875, 0.0}, {0.1, 0.855, -0.4}, {0.25, 0.75, -1.0}, {0.5, 0.5, -1.0},
                      {0.75, 0.25, -1.0}, {0.9, 0.1225, -0.7}, {1.0, 0.0625, -0.5}, {1.25, 0.0, 0.0},
                      {1.5, 0.0, 0.0}};
  for (const Row& r : rows) {
    double S, G;
    gimp_1d(r.d, l, S, G);
    EXPECT_NEAR(S, r.S, 1e-14) << "d = " << r.d;
    EXPECT_NEAR(G, r.G, 1e-14) << "d = " << r.d;
    gimp_1d(-r.d, l, S, G);  // S even, G odd
    EXPECT_NEAR(S, r.S, 1e-14) << "d = " << -r.d;
    EXPECT_NEAR(G, -r.G, 1e-14) << "d = " << -r.d;
  }
  // Particle at x_p = 0.1 with nodes -1, 0, 1: weights 0.0225, 0.855, 0.1225;
  // gradients -0.3, -0.4, +0.7 (inventory; G_gp is d S_gp / d x_p).
  const ShapeAxis a = gimp_axis(0.1, l);
  ASSERT_EQ(a.first, -1);
  EXPECT_NEAR(a.S[0], 0.0225, 1e-15);
  EXPECT_NEAR(a.S[1], 0.855, 1e-15);
  EXPECT_NEAR(a.S[2], 0.1225, 1e-15);
  EXPECT_NEAR(a.dS[0], -0.3, 1e-15);
  EXPECT_NEAR(a.dS[1], -0.4, 1e-15);
  EXPECT_NEAR(a.dS[2], 0.7, 1e-15);
}

// Inventory (eq. 1.100): h = 1, half-edges 0.25, x_p = (0.3, 0.3, 0.3).
double cpdi_weight(const Vec3& xp, const Mat3& F, const IntVec3& node, Vec3& grad) {
  IntVec3 nodes[64];
  double w[64];
  Vec3 g[64];
  EXPECT_TRUE(cpdi_stencil(xp, F * (0.5 * Mat3::Identity()), 1e10, Vec3::Ones(), nodes, w, g));
  double S = 0;
  grad.setZero();
  for (int k = 0; k < 64; ++k)
    if (nodes[k] == node) {
      S += w[k];
      grad += g[k];
    }
  return S;
}

TEST(MpmShape, CpdiValuesOfTheInventory) {
  const Vec3 xp(0.3, 0.3, 0.3);
  Vec3 g;
  // F = I: the corner average of a hat is the hat (it is linear between the
  // corners inside one cell): 0.7^3 = 0.343, grad = -(0.7^2)(1,1,1).
  EXPECT_NEAR(cpdi_weight(xp, Mat3::Identity(), IntVec3(0, 0, 0), g), 0.343, 1e-15);
  EXPECT_NEAR((g - Vec3(-0.49, -0.49, -0.49)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(cpdi_weight(xp, Mat3::Identity(), IntVec3(1, 1, 1), g), 0.027, 1e-15);
  EXPECT_NEAR((g - Vec3(0.09, 0.09, 0.09)).norm(), 0.0, 1e-15);
  // Simple shear F = I + 0.2 e1 e2: node (0,0,0) S = 0.35175, grad = (-0.49, -0.49, -0.5025).
  Mat3 F = Mat3::Identity();
  F(0, 1) = 0.2;
  EXPECT_NEAR(cpdi_weight(xp, F, IntVec3(0, 0, 0), g), 0.35175, 1e-15);
  EXPECT_NEAR((g - Vec3(-0.49, -0.49, -0.5025)).norm(), 0.0, 1e-14);
}

// CPDI with F = I and GIMP agree when the particle does not straddle a node
// (both then equal the hat at x_p, by linearity between the corners), and
// differ when it does (GIMP integrates the kink of the hat, CPDI interpolates
// it linearly between the corners).
TEST(MpmShape, CpdiAtIdentityEqualsGimpAwayFromNodes) {
  Vec3 g;
  const double cp = cpdi_weight(Vec3(0.3, 0.3, 0.3), Mat3::Identity(), IntVec3(0, 0, 0), g);
  double S, dS;
  gimp_1d(0.3, 0.25, S, dS);
  EXPECT_NEAR(cp, S * S * S, 1e-15);
  const double cp_node = cpdi_weight(Vec3(0.1, 0.1, 0.1), Mat3::Identity(), IntVec3(0, 0, 0), g);
  gimp_1d(0.1, 0.25, S, dS);
  EXPECT_GT(std::abs(cp_node - S * S * S), 1e-3);
}

TEST(MpmShape, CpdiLcritLimitsTheDomain) {
  // A particle stretched to 3 cells along x: half-diagonals longer than
  // lcrit = 0.75 are shortened, the edge vectors rebuilt from them.
  Mat3 s = Mat3::Zero();
  s(0, 0) = 1.5;
  s(1, 1) = 0.25;
  s(2, 2) = 0.25;
  const Mat3 limited = cpdi_limit_half_edges(s, 0.75);
  for (int a = -1; a <= 1; a += 2)
    for (int b = -1; b <= 1; b += 2)
      EXPECT_NEAR((a * limited.col(0) + b * limited.col(1) + limited.col(2)).norm(), 0.75, 1e-14);
  EXPECT_EQ(cpdi_limit_half_edges(s, 10.0), s);  // no-op under the limit
}

// Quadratic B-spline: S(0) = 3/4, S(+-1) = 1/8 at a node; S(1/2) = 1/2 on a
// cell face (nodes 0, 1 at 1/2 each, the third at 0).
TEST(MpmShape, QuadraticBsplineValues) {
  const ShapeAxis a = quadratic_bspline_axis(3.0);
  EXPECT_EQ(a.first, 2);
  EXPECT_NEAR(a.S[0], 0.125, 1e-15);
  EXPECT_NEAR(a.S[1], 0.75, 1e-15);
  EXPECT_NEAR(a.S[2], 0.125, 1e-15);
  // dS/dxi of node i at d = xi - i: the lower node loses weight as xi grows.
  EXPECT_NEAR(a.dS[0], -0.5, 1e-15);
  EXPECT_NEAR(a.dS[1], 0.0, 1e-15);
  EXPECT_NEAR(a.dS[2], 0.5, 1e-15);
  const ShapeAxis b = quadratic_bspline_axis(3.4999999999);
  EXPECT_NEAR(b.S[1], 0.5, 1e-9);
  EXPECT_NEAR(b.S[2], 0.5, 1e-9);
  EXPECT_NEAR(b.S[0], 0.0, 1e-9);
}

TEST(MpmShape, LinearHatValues) {
  // S(x) = 1 - |x - x_g|/h: a point 0.3 h above node 2 weights 0.7 and 0.3,
  // gradients -1/h and +1/h (eqs. 1.86, 1.89).
  const ShapeAxis a = linear_axis(2.3);
  EXPECT_EQ(a.first, 2);
  EXPECT_NEAR(a.S[0], 0.7, 1e-15);
  EXPECT_NEAR(a.S[1], 0.3, 1e-15);
  EXPECT_EQ(a.dS[0], -1.0);
  EXPECT_EQ(a.dS[1], 1.0);
}

// P2G conserves mass and momentum for every interpolator (partition of unity).
TEST(MpmShape, ParticleToGridConservesMassAndMomentum) {
  for (InterpolatorKind kind : kAll) {
    SCOPED_TRACE(interpolator_name(kind));
    Cloud c(300, true);
    Stencils s;
    ASSERT_EQ(compute_stencils(c.p, c.g, {kind, 1e10}, s), -1);
    particles_to_grid(c.p, s, Vec3::Zero(), c.g);
    double mp = 0, mg = 0;
    Vec3 pp = Vec3::Zero(), pg = Vec3::Zero();
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      mp += c.p.mass[i];
      pp += c.p.mass[i] * c.p.v[i];
    }
    for (std::size_t gi = 0; gi < c.g.count(); ++gi) {
      mg += c.g.mass[gi];
      pg += c.g.mass[gi] * c.g.velocity[gi];
    }
    EXPECT_NEAR(mg, mp, 1e-13 * mp);
    EXPECT_NEAR((pg - pp).norm(), 0.0, 1e-12 * mp);
  }
}

TEST(MpmShape, RejectsSupportsLeavingTheGrid) {
  for (InterpolatorKind kind : {InterpolatorKind::Gimp, InterpolatorKind::QuadraticBspline}) {
    Cloud c(10, false);
    Stencils s;
    c.p.x[3] = c.g.position(0, 3, 3) + Vec3(0.2 * c.g.h[0], 0, 0);  // node -1 would carry weight
    EXPECT_EQ(compute_stencils(c.p, c.g, {kind, 1e10}, s), 3) << interpolator_name(kind);
  }
}

}  // namespace
}  // namespace tephra
