// Inside/outside of the primitive pieces against their analytic definitions,
// including boundary points (closed sets) and rotated axes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "core/geometry/Primitives.h"
#include "test_geometry_support.h"

using namespace tephra;

namespace {
constexpr double kIn = 1.0 - 1e-9, kOut = 1.0 + 1e-9;  // just inside / just outside factors
}

TEST(GeometryPrimitives, BoxIsClosedAndExact) {
  BoxPiece box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  EXPECT_TRUE(box.inside(Vec3(0.5, 1, 1.5)));
  EXPECT_TRUE(box.inside(Vec3(0, 0, 0)));      // corner
  EXPECT_TRUE(box.inside(Vec3(1, 2, 3)));      // corner
  EXPECT_TRUE(box.inside(Vec3(1, 1, 1.5)));    // face
  EXPECT_FALSE(box.inside(Vec3(std::nextafter(1.0, 2.0), 1, 1)));
  EXPECT_FALSE(box.inside(Vec3(0.5, -1e-300, 1)));
  EXPECT_FALSE(box.inside(Vec3(0.5, 1, 3.5)));
  EXPECT_DOUBLE_EQ(box.volume(), 6.0);
  EXPECT_THROW(BoxPiece(Vec3(0, 0, 0), Vec3(1, 0, 1)), std::invalid_argument);
}

TEST(GeometryPrimitives, SphereAgainstDistance) {
  const Vec3 o(1, 2, 3);
  const double r = 2;
  SpherePiece s(o, r);
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  for (int n = 0; n < 200; ++n) {
    const Vec3 u = Vec3(g(rng), g(rng), g(rng)).normalized();
    EXPECT_TRUE(s.inside(o + r * u)) << "boundary point";
    EXPECT_TRUE(s.inside(o + kIn * r * u));
    EXPECT_FALSE(s.inside(o + kOut * r * u));
  }
  EXPECT_TRUE(s.inside(o));
  const BoundingBox b = s.bounding_box();
  EXPECT_TRUE(b.lo.isApprox(Vec3(-1, 0, 1)) && b.hi.isApprox(Vec3(3, 4, 5)));
}

// Frustum on an oblique axis: x = b + s a + rho (cos phi n1 + sin phi n2) is
// inside iff 0 <= s <= L and rho <= r_b + (r_t - r_b) s / L.
static void check_frustum(const GeometryPiece& p, const Vec3& b, const Vec3& a, double L,
                          double rb, double rt) {
  Vec3 n1, n2;
  test::frame(a, n1, n2);
  for (double sf : {0.0, 0.3, 0.5, 1.0})
    for (double phi : {0.0, 1.0, 2.5, 4.0}) {
      const double s = sf * L, rs = rb + (rt - rb) * sf;
      const Vec3 e = std::cos(phi) * n1 + std::sin(phi) * n2;
      EXPECT_TRUE(p.inside(b + s * a + rs * e)) << "side boundary s=" << s;
      EXPECT_TRUE(p.inside(b + s * a + kIn * rs * e));
      EXPECT_FALSE(p.inside(b + s * a + (kOut * rs + 1e-9) * e));
      EXPECT_TRUE(p.inside(b + s * a));  // on the axis
    }
  EXPECT_FALSE(p.inside(b - 1e-9 * L * a));
  EXPECT_FALSE(p.inside(b + (1 + 1e-9) * L * a));
  // The bounding box holds every boundary circle point.
  const BoundingBox bb = p.bounding_box();
  for (double phi = 0; phi < 6.28; phi += 0.1)
    for (double sf : {0.0, 1.0}) {
      const Vec3 x = b + sf * L * a + (rb + (rt - rb) * sf) * (std::cos(phi) * n1 + std::sin(phi) * n2);
      EXPECT_TRUE(((x.array() >= bb.lo.array() - 1e-12) && (x.array() <= bb.hi.array() + 1e-12)).all());
    }
}

TEST(GeometryPrimitives, CylinderOnObliqueAxis) {
  const Vec3 b(1, 1, 1), a = Vec3(1, 2, 2) / 3.0;
  const double L = 3, r = 0.5;
  auto c = make_cylinder(b, b + L * a, r);
  EXPECT_EQ(c->type(), "cylinder");
  check_frustum(*c, b, a, L, r, r);
}

TEST(GeometryPrimitives, ConeAndPointedConeOnObliqueAxis) {
  const Vec3 b(-1, 0.5, 2), a = Vec3(2, -1, 2) / 3.0;
  const double L = 1.5;
  auto frustum = make_cone(b, 1.0, b + L * a, 0.25);
  EXPECT_EQ(frustum->type(), "cone");
  check_frustum(*frustum, b, a, L, 1.0, 0.25);
  auto pointed = make_cone(b, 0.0, b + L * a, 0.8);
  check_frustum(*pointed, b, a, L, 0.0, 0.8);
  EXPECT_TRUE(pointed->inside(b));  // apex
}

TEST(GeometryPrimitives, RotatedEllipsoid) {
  const Vec3 o(0.5, -1, 2), r(3, 1, 0.5);
  const Mat3 U = Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized()).toRotationMatrix();
  EllipsoidPiece e(o, r, U);
  std::mt19937 rng(2);
  std::normal_distribution<double> g;
  for (int n = 0; n < 200; ++n) {
    // x = o + U diag(r) c with |c| = 1 lies on the surface.
    const Vec3 c = Vec3(g(rng), g(rng), g(rng)).normalized();
    const Vec3 d = U * r.cwiseProduct(c);
    EXPECT_TRUE(e.inside(o + d));
    EXPECT_TRUE(e.inside(o + kIn * d));
    EXPECT_FALSE(e.inside(o + kOut * d));
  }
  // Bounding box: support function sqrt(sum_k r_k^2 U_ik^2), touched by the surface.
  const BoundingBox b = e.bounding_box();
  for (int i = 0; i < 3; ++i) {
    double s = 0;
    for (int k = 0; k < 3; ++k) s += r[k] * r[k] * U(i, k) * U(i, k);
    EXPECT_NEAR(b.hi[i] - o[i], std::sqrt(s), 1e-14);
    EXPECT_NEAR(o[i] - b.lo[i], std::sqrt(s), 1e-14);
  }
}

TEST(GeometryPrimitives, ParallelepipedInUnitCubeCoordinates) {
  const Vec3 p1(1, 0, -1), e1(2, 0.5, 0), e2(-0.5, 1, 0.3), e3(0.2, -0.4, 1.5);
  ParallelepipedPiece p(p1, p1 + e1, p1 + e2, p1 + e3);
  ParallelepipedPiece swapped(p1, p1 + e3, p1 + e1, p1 + e2);  // order of p2..p4 irrelevant
  Mat3 E;
  E << e1, e2, e3;
  for (double c0 : {-1e-9, 0.0, 0.5, 1.0, 1 + 1e-9})
    for (double c1 : {-1e-9, 0.0, 0.3, 1.0, 1 + 1e-9})
      for (double c2 : {-1e-9, 0.0, 0.7, 1.0, 1 + 1e-9}) {
        const Vec3 c(c0, c1, c2);
        const bool expect = (c.array() >= 0).all() && (c.array() <= 1).all();
        const Vec3 x = p1 + E * c;
        EXPECT_EQ(p.inside(x), expect) << c.transpose();
        EXPECT_EQ(swapped.inside(x), expect) << c.transpose();
      }
  EXPECT_THROW(ParallelepipedPiece(p1, p1 + e1, p1 + e2, p1 + e1 + e2), std::invalid_argument);
}

TEST(GeometryPrimitives, TorusOnObliqueAxis) {
  const Vec3 c(0, 1, -1), a = Vec3(1, 1, 1).normalized();
  const double R = 2, r = 0.5;
  TorusPiece t(c, a, R, r);
  Vec3 n1, n2;
  test::frame(a, n1, n2);
  // x = c + (R + q cos psi) e(phi) + q sin psi a: inside iff q <= r.
  for (double phi : {0.0, 1.3, 3.0, 5.0})
    for (double psi : {0.0, 0.8, 2.0, 3.14159, 4.5}) {
      const Vec3 e = std::cos(phi) * n1 + std::sin(phi) * n2;
      auto at = [&](double q) { return c + (R + q * std::cos(psi)) * e + q * std::sin(psi) * a; };
      EXPECT_TRUE(t.inside(at(r)));
      EXPECT_TRUE(t.inside(at(kIn * r)));
      EXPECT_FALSE(t.inside(at(kOut * r)));
    }
  EXPECT_FALSE(t.inside(c));  // the hole
}
