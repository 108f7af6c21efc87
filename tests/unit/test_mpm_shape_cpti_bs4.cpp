// CPTI (mpm/shape/ShapeCpti.h) and the cubic B-spline 4thorderBS
// (mpm/shape/ShapeBsplineCubic.h): closed-form values, the identities of
// every interpolator (partition of unity, linear completeness
// sum S_g x_g = x_p, sum x_g (grad S_g)^T = I), CPTI = CPDI on affine fields,
// and where the boundary-modified cubic splines stop being linearly complete.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"
#include "mpm/shape/ShapeBsplineCubic.h"
#include "mpm/shape/ShapeCpdi.h"
#include "mpm/shape/ShapeCpti.h"

namespace tephra {
namespace {

// Sums of one particle's stencil entries.
struct Moments {
  double S = 0;
  Vec3 Sx = Vec3::Zero(), G = Vec3::Zero();
  Mat3 xG = Mat3::Zero();
};

Vec3 node_position(const NodeGrid& g, std::size_t gi) {
  const int i = int(gi % g.n[0]), j = int((gi / g.n[0]) % g.n[1]), k = int(gi / (std::size_t(g.n[0]) * g.n[1]));
  return g.position(i, j, k);
}

Moments moments(const Stencils& s, const NodeGrid& g, std::size_t p) {
  Moments m;
  for (std::size_t k = p * s.width; k < (p + 1) * s.width; ++k) {
    const Vec3 xg = node_position(g, s.node[k]);
    m.S += s.w[k];
    m.Sx += s.w[k] * xg;
    m.G += s.grad[k];
    m.xG += xg * s.grad[k].transpose();
  }
  return m;
}

// A non-cubic grid with one extra-cell layer, an offset origin, and particles
// with random sizes and deformation gradients, placed in [lo_margin,
// n - 1 - hi_margin] (node-index units).
struct Cloud {
  NodeGrid g;
  Particles p;
  Cloud(int count, double margin, bool deformed, unsigned seed = 7) {
    g.origin = Vec3(-0.3, 0.2, 1.0);
    g.h = Vec3(0.1, 0.25, 0.05);
    g.n = IntVec3(15, 14, 15);
    g.extra = IntVec3(1, 1, 1);
    g.reset();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < count; ++i) {
      Vec3 xi;
      for (int d = 0; d < 3; ++d) xi[d] = margin + (g.n[d] - 1 - 2 * margin) * u(rng);
      const Mat3 size = Vec3(0.2 + 0.8 * u(rng), 0.2 + 0.8 * u(rng), 0.2 + 0.8 * u(rng)).asDiagonal();
      p.add(g.origin + xi.cwiseProduct(g.h), Vec3::Zero(), 1.0, 1e-3, 300.0, 0.0, i, size);
      if (deformed) p.F.back() = Mat3::Identity() + 0.3 * Mat3::Random();
    }
  }
};

TEST(MpmShapeCpti, IdentitiesOnDeformedParticles) {
  Cloud c(500, 2.0, true);
  Stencils s;
  ASSERT_EQ(compute_stencils(c.p, c.g, {InterpolatorKind::Cpti, 1e10}, s), -1);
  ASSERT_EQ(s.width, 32);
  for (std::size_t i = 0; i < c.p.size(); ++i) {
    const Moments m = moments(s, c.g, i);
    ASSERT_NEAR(m.S, 1.0, 1e-13);
    ASSERT_NEAR((m.Sx - c.p.x[i]).norm(), 0.0, 1e-13);  // the tet's centroid is x_p
    ASSERT_NEAR(m.G.cwiseProduct(c.g.h).norm(), 0.0, 1e-12);
    ASSERT_NEAR((m.xG - Mat3::Identity()).norm(), 0.0, 1e-12);
  }
}

// For an affine field f(x) = a + b . x both CPTI and CPDI give the value at
// the particle, sum S_gp f_g = f(x_p), and the exact gradient, sum G_gp f_g = b.
TEST(MpmShapeCpti, EqualsCpdiOnAnAffineField) {
  Cloud c(200, 2.0, true, 11);
  const double a = 0.7;
  const Vec3 b(1.3, -2.1, 0.4);
  for (InterpolatorKind kind : {InterpolatorKind::Cpti, InterpolatorKind::Cpdi}) {
    Stencils s;
    ASSERT_EQ(compute_stencils(c.p, c.g, {kind, 1e10}, s), -1);
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      double f = 0;
      Vec3 grad = Vec3::Zero();
      for (std::size_t k = i * s.width; k < (i + 1) * s.width; ++k) {
        const double fg = a + b.dot(node_position(c.g, s.node[k]));
        f += s.w[k] * fg;
        grad += s.grad[k] * fg;
      }
      ASSERT_NEAR(f, a + b.dot(c.p.x[i]), 1e-12) << interpolator_name(kind);
      ASSERT_NEAR((grad - b).norm(), 0.0, 1e-10) << interpolator_name(kind);
    }
  }
}

// h = 1, particle at (0.5, 0.5, 0.5), edges 0.5 e_i (F = I): tet corners
// c_0 = x_p - (0.125, 0.125, 0.125) = (0.375)^3 and c_i = c_0 + 0.5 e_i, all in
// cell 0. Node (0,0,0): hat(c_0) = 0.625^3, hat(c_i) = 0.125 0.625^2, so
//   S = (0.625^3 + 3 0.125 0.625^2)/4 = 0.09765625;
// grad N_i = (r_j x r_k)/det = 2 e_i, grad N_0 = -2 (1,1,1), so
//   G = 0.625^3 (-2,-2,-2) + 0.125 0.625^2 (2,2,2) = -0.390625 (1,1,1).
TEST(MpmShapeCpti, ClosedFormValues) {
  IntVec3 node[32];
  double w[32];
  Vec3 grad[32];
  ASSERT_TRUE(cpti_stencil(Vec3(0.5, 0.5, 0.5), 0.5 * Mat3::Identity(), 1e10, Vec3::Ones(), node, w, grad));
  double S = 0;
  Vec3 G = Vec3::Zero();
  for (int k = 0; k < 32; ++k)
    if (node[k] == IntVec3(0, 0, 0)) {
      S += w[k];
      G += grad[k];
    }
  EXPECT_NEAR(S, 0.09765625, 1e-15);
  EXPECT_NEAR((G - Vec3(-0.390625, -0.390625, -0.390625)).norm(), 0.0, 1e-15);
  // Physical units: h = (2, 1, 0.5) divides the index-unit gradient.
  ASSERT_TRUE(cpti_stencil(Vec3(0.5, 0.5, 0.5), 0.5 * Mat3::Identity(), 1e10, Vec3(2, 1, 0.5), node, w, grad));
  G.setZero();
  for (int k = 0; k < 32; ++k)
    if (node[k] == IntVec3(0, 0, 0)) G += grad[k];
  EXPECT_NEAR((G - Vec3(-0.1953125, -0.390625, -0.78125)).norm(), 0.0, 1e-15);
  // Inverted tetrahedron: degenerate.
  EXPECT_FALSE(cpti_stencil(Vec3(0.5, 0.5, 0.5), -0.5 * Mat3::Identity(), 1e10, Vec3::Ones(), node, w, grad));
}

TEST(MpmShapeCpti, LcritShortensTheCorners) {
  Mat3 e = Mat3::Zero();
  e(0, 0) = 3.0;  // stretched to 3 cells along x
  e(1, 1) = 0.5;
  e(2, 2) = 0.5;
  Vec3 c[4];
  Mat3 used;
  cpti_corners(e, 1e10, c, used);
  EXPECT_EQ(used, e);
  EXPECT_NEAR((c[1] - Vec3(2.25, -0.125, -0.125)).norm(), 0.0, 1e-15);  // c_0 = -(4, 0.5, 0.5)/4, + r_1
  cpti_corners(e, 1.0, c, used);
  // Edges rebuilt from the shortened corners, then re-centred on x_p.
  EXPECT_NEAR((c[0] + c[1] + c[2] + c[3]).norm(), 0.0, 1e-14);
  EXPECT_LT(used.col(0).norm(), 3.0);
  EXPECT_GT(used.determinant(), 0.0);
}

// Uniform cubic B-spline: N(0) = 2/3, N(+-1) = 1/6, N(+-1/2) = 23/48,
// N(+-3/2) = 1/48; N'(1) = -1/2, N'(1/2) = -5/8.
TEST(MpmShapeCubicBspline, InteriorValues) {
  double S, dS;
  cubic_bspline_1d(0.0, S, dS);
  EXPECT_NEAR(S, 2.0 / 3.0, 1e-15);
  EXPECT_EQ(dS, 0.0);
  cubic_bspline_1d(1.0, S, dS);
  EXPECT_NEAR(S, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(dS, -0.5, 1e-15);
  cubic_bspline_1d(-0.5, S, dS);
  EXPECT_NEAR(S, 23.0 / 48.0, 1e-15);
  EXPECT_NEAR(dS, 0.625, 1e-15);
  cubic_bspline_1d(1.5, S, dS);
  EXPECT_NEAR(S, 1.0 / 48.0, 1e-15);
  cubic_bspline_1d(2.0, S, dS);
  EXPECT_EQ(S, 0.0);
  // Four nodes around xi = 5.5 on a long axis: 1/48, 23/48, 23/48, 1/48.
  const ShapeAxis a = cubic_bspline_axis(5.5, 0, 20);
  ASSERT_EQ(a.first, 4);
  ASSERT_EQ(a.count, 4);
  EXPECT_NEAR(a.S[0], 1.0 / 48.0, 1e-15);
  EXPECT_NEAR(a.S[1], 23.0 / 48.0, 1e-15);
  EXPECT_NEAR(a.S[2], 23.0 / 48.0, 1e-15);
  EXPECT_NEAR(a.S[3], 1.0 / 48.0, 1e-15);
}

// Face modification (Vaango's type 2 and 3 splines), lo = 1, xi = lo + 1/2:
// N3(1/2) = 1 - 3/8 + 3/32 = 23/32, N2(-1/2) = 11/96 - 5/16 - 1/8 + 7/12 = 25/96,
// N(3/2... from node lo + 2) = 1/48: sum 1. The first moment
// sum S_i (i - lo) = 25/96 + 2/48 = 29/96, not 1/2: the modified basis is not
// linearly complete next to a face. The upper face is the mirror image.
TEST(MpmShapeCubicBspline, FaceValuesAndTheirMirror) {
  const int lo = 1, top = 11;
  const ShapeAxis a = cubic_bspline_axis(lo + 0.5, lo, top);
  ASSERT_EQ(a.first, lo);
  ASSERT_EQ(a.count, 3);
  EXPECT_NEAR(a.S[0], 23.0 / 32.0, 1e-15);
  EXPECT_NEAR(a.S[1], 25.0 / 96.0, 1e-15);
  EXPECT_NEAR(a.S[2], 1.0 / 48.0, 1e-15);
  EXPECT_NEAR(a.S[1] + 2 * a.S[2], 29.0 / 96.0, 1e-15);
  EXPECT_NEAR(a.dS[0], 0.5 * (2.25 * 0.5 - 3.0), 1e-15);  // N3'(d) = d (9/4 d - 3)
  const ShapeAxis b = cubic_bspline_axis(top - 0.5, lo, top);
  ASSERT_EQ(b.first, top - 2);
  ASSERT_EQ(b.count, 3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(b.S[k], a.S[2 - k], 1e-15);
    EXPECT_NEAR(b.dS[k], -a.dS[2 - k], 1e-15);
  }
  // At the face node itself: weight 1, zero slope.
  const ShapeAxis f = cubic_bspline_axis(lo, lo, top);
  EXPECT_NEAR(f.S[0], 1.0, 1e-15);
  EXPECT_EQ(f.dS[0], 0.0);
}

// Along a whole axis: partition of unity, sum dS = 0, dS = d S / d xi
// (central differences), continuity of every node's weight across the knots,
// and linear completeness sum S_i i = xi wherever the support holds only
// type-1 nodes (xi in [lo + 3, top - 3]).
TEST(MpmShapeCubicBspline, AxisIdentities) {
  const int lo = 1, top = 13;
  auto weight = [&](double xi, int node) {
    double S, dS;
    cubic_bspline_node(xi, node, lo, top, S, dS);
    return S;
  };
  for (int step = 0; step <= 1200; ++step) {
    const double xi = lo + (top - lo) * step / 1200.0;
    const ShapeAxis a = cubic_bspline_axis(xi, lo, top);
    double sum = 0, sum_d = 0, moment = 0;
    for (int k = 0; k < a.count; ++k) {
      sum += a.S[k];
      sum_d += a.dS[k];
      moment += a.S[k] * (a.first + k);
      EXPECT_GE(a.S[k], 0.0);
      const int node = a.first + k;
      const double eps = 1e-6;
      if (xi - eps >= lo && xi + eps <= top)
        EXPECT_NEAR((weight(xi + eps, node) - weight(xi - eps, node)) / (2 * eps), a.dS[k], 1e-8)
            << "xi " << xi << " node " << node;
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << xi;
    EXPECT_NEAR(sum_d, 0.0, 1e-13) << xi;
    if (xi >= lo + 3 && xi <= top - 3) EXPECT_NEAR(moment, xi, 1e-13) << xi;
  }
  // Continuity at every inner knot for every node (the weights are defined in [lo, top] only).
  for (int knot = lo + 1; knot < top; ++knot)
    for (int node = lo; node <= top; ++node)
      EXPECT_NEAR(weight(knot - 1e-12, node), weight(knot + 1e-12, node), 1e-11) << knot << " " << node;
}

// 3-D stencils on a grid with one extra-cell layer: no extra-cell node gets
// a weight, partition of unity everywhere in the domain, and the linear
// identities for particles 3 cells or more inside every face.
TEST(MpmShapeCubicBspline, ThreeDimensionalStencils) {
  Cloud c(400, 1.0, false, 5);  // the whole domain [extra, n - 1 - extra]
  Stencils s;
  ASSERT_EQ(compute_stencils(c.p, c.g, {InterpolatorKind::CubicBspline, 1e10}, s), -1);
  ASSERT_EQ(s.width, 64);
  int interior = 0;
  for (std::size_t i = 0; i < c.p.size(); ++i) {
    const Moments m = moments(s, c.g, i);
    ASSERT_NEAR(m.S, 1.0, 1e-13);
    ASSERT_NEAR(m.G.cwiseProduct(c.g.h).norm(), 0.0, 1e-12);
    for (std::size_t k = i * s.width; k < (i + 1) * s.width; ++k) {
      if (s.w[k] == 0.0 && s.grad[k] == Vec3::Zero()) continue;
      const std::size_t gi = s.node[k];
      const IntVec3 ijk(int(gi % c.g.n[0]), int((gi / c.g.n[0]) % c.g.n[1]), int(gi / (std::size_t(c.g.n[0]) * c.g.n[1])));
      ASSERT_TRUE((ijk.array() >= c.g.extra.array()).all() && (ijk.array() <= (c.g.n - c.g.extra).array() - 1).all());
    }
    const Vec3 xi = (c.p.x[i] - c.g.origin).cwiseQuotient(c.g.h);
    bool inside = true;
    for (int d = 0; d < 3; ++d) inside = inside && xi[d] >= 1 + 3 && xi[d] <= c.g.n[d] - 2 - 3;
    if (!inside) continue;
    ++interior;
    ASSERT_NEAR((m.Sx - c.p.x[i]).norm(), 0.0, 1e-13);
    ASSERT_NEAR((m.xG - Mat3::Identity()).norm(), 0.0, 1e-12);
  }
  EXPECT_GT(interior, 20);
  // A particle in an extra cell has no support: reported.
  c.p.x[7] = c.g.position(0, 4, 4) + Vec3(0.5 * c.g.h[0], 0, 0);
  EXPECT_EQ(compute_stencils(c.p, c.g, {InterpolatorKind::CubicBspline, 1e10}, s), 7);
}

// 4thorderBS needs no extra cells (its support never leaves the domain's
// nodes), so a deck without them runs; gimp still requires them.
std::unique_ptr<MpmComponent> one_block(const std::string& interpolator, int extra) {
  const std::string e = std::to_string(extra);
  const std::string xml =
      "<Uintah_specification><MPM><interpolator>" + interpolator +
      "</interpolator></MPM><MaterialProperties><MPM><material><density>1000</density>"
      "<constitutive_model type='comp_neo_hook'><bulk_modulus>1e7</bulk_modulus><shear_modulus>5e6</shear_modulus>"
      "</constitutive_model><thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
      "<geom_object><box><min>[0.2,0.2,0.2]</min><max>[0.8,0.8,0.8]</max></box><res>[2,2,2]</res>"
      "<velocity>[1,0,0]</velocity><temperature>300</temperature></geom_object></material></MPM>"
      "</MaterialProperties><Grid><BoundaryConditions></BoundaryConditions><Level><Box><lower>[0,0,0]</lower>"
      "<upper>[1,1,1]</upper><resolution>[8,8,8]</resolution><extraCells>[" + e + "," + e + "," + e +
      "]</extraCells><patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(xml, "bs4.ups", ".");
  return make_mpm_component(*deck);
}

TEST(MpmShapeCubicBspline, RunsWithoutExtraCells) {
  auto c = one_block("4thorderBS", 0);
  c->initialize();
  c->advance(0.0, 0.2 * c->stable_timestep(), 1);
  const Particles& p = c->materials()[0].particles;
  Vec3 momentum = Vec3::Zero();
  double mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i) momentum += p.mass[i] * p.v[i], mass += p.mass[i];
  EXPECT_NEAR((momentum / mass - Vec3(1, 0, 0)).norm(), 0.0, 1e-12);  // free body, uniform motion
  EXPECT_THROW(one_block("gimp", 0), DeckError);
}

}  // namespace
}  // namespace tephra
