// Volume of each piece by counting lattice points at spacing h, against the
// closed-form volume. Oracle (see counted_volume): the relative error is
// bounded by sqrt(3) A h / V (A the surface area, Steiner's formula), so it
// must fall at least like h as h halves, and at the finest h it must be below
// that bound. Booleans: shell, box intersection, inclusion-exclusion.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/geometry/Boolean.h"
#include "core/geometry/Primitives.h"
#include "test_geometry_support.h"

using namespace tephra;

namespace {

const double kPi = std::acos(-1.0);

// Counts at h0, h0/2, h0/4, h0/8, each with kShifts lattice shifts s
// (fixed pseudo-random). Checks at every level and shift the theory bound
// |V_h - V|/V <= sqrt(3) A h / V, and the observed convergence of the
// root-mean-square error over the shifts: it must drop by at least 4 over the
// three halvings (observed order >= 2/3; the bound alone gives 1, and for
// random shifts the RMS error of a lattice count decays like h^2 for smooth
// surfaces, so this is far from flaky yet fails for a wrong inside test).
constexpr int kShifts = 6;

void check_volume(const GeometryPiece& p, double exact_volume, double area, double h0) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Vec3> shifts;
  for (int k = 0; k < kShifts; ++k) shifts.emplace_back(u01(rng), u01(rng), u01(rng));
  double first_rms = 0, rms = 0, h = h0;
  for (int level = 0; level < 4; ++level, h /= 2) {
    const double bound = std::sqrt(3.0) * area * h / exact_volume;
    double sum2 = 0, worst = 0;
    for (const Vec3& s : shifts) {
      const double err = std::abs(test::counted_volume(p, h, s) - exact_volume) / exact_volume;
      EXPECT_LE(err, bound) << p.type() << " at h=" << h;
      sum2 += err * err;
      worst = std::max(worst, err);
    }
    rms = std::sqrt(sum2 / kShifts);
    std::printf("  %-14s h=%-10.4g rms.err=%-10.3e max.err=%-10.3e bound=%.3e\n", p.type().c_str(),
                h, rms, worst, bound);
    if (level == 0) first_rms = rms;
  }
  EXPECT_LT(rms, first_rms / 4) << p.type() << ": no convergence";
}

}  // namespace

TEST(GeometryVolume, Box) {
  // Sides incommensurate with h (a lattice count of a box whose sides are
  // multiples of h is exact).
  const double a = 1.03, b = 1.97, c = 0.51;
  BoxPiece box(Vec3(0, 0, 0), Vec3(a, b, c));
  // V = abc, A = 2(ab + bc + ca)
  check_volume(box, a * b * c, 2 * (a * b + b * c + c * a), 0.1);
}

TEST(GeometryVolume, Sphere) {
  const double r = 0.7;
  SpherePiece s(Vec3(0.1, 0.2, 0.3), r);
  check_volume(s, 4.0 / 3.0 * kPi * r * r * r, 4 * kPi * r * r, 2 * r / 10);
}

TEST(GeometryVolume, ObliqueCylinder) {
  const double r = 0.4, L = 2.0;
  const Vec3 b(0, 0, 0), a = Vec3(2, 1, 2) / 3.0;
  auto c = make_cylinder(b, b + L * a, r);
  // V = pi r^2 L, A = 2 pi r L + 2 pi r^2
  check_volume(*c, kPi * r * r * L, 2 * kPi * r * L + 2 * kPi * r * r, 0.08);
}

TEST(GeometryVolume, ObliqueConeFrustum) {
  const double R = 0.6, r = 0.2, L = 1.2;
  const Vec3 b(0, 0, 0), a = Vec3(1, -2, 2) / 3.0;
  auto c = make_cone(b, R, b + L * a, r);
  // V = pi L (R^2 + R r + r^2) / 3; A = pi (R + r) sqrt((R - r)^2 + L^2) + pi (R^2 + r^2)
  const double area = kPi * (R + r) * std::sqrt((R - r) * (R - r) + L * L) + kPi * (R * R + r * r);
  check_volume(*c, kPi * L * (R * R + R * r + r * r) / 3, area, 0.08);
}

TEST(GeometryVolume, RotatedEllipsoid) {
  const Vec3 r(0.8, 0.5, 0.3);
  const Mat3 U = Eigen::AngleAxisd(0.9, Vec3(1, -1, 2).normalized()).toRotationMatrix();
  EllipsoidPiece e(Vec3(0, 0, 0), r, U);
  // V = 4/3 pi r1 r2 r3; the area has no closed form: bounded above by the
  // sphere of radius max r_k, 4 pi max(r)^2, which only loosens the bound.
  check_volume(e, 4.0 / 3.0 * kPi * r.prod(), 4 * kPi * 0.8 * 0.8, 0.08);
}

TEST(GeometryVolume, Parallelepiped) {
  const Vec3 p1(0, 0, 0), e1(1, 0.21, 0), e2(0.33, 0.8, 0.12), e3(-0.2, 0.11, 0.63);
  ParallelepipedPiece p(p1, p1 + e1, p1 + e2, p1 + e3);
  Mat3 E;
  E << e1, e2, e3;
  // V = |det E|, A = 2 (|e1 x e2| + |e2 x e3| + |e3 x e1|)
  const double area = 2 * (e1.cross(e2).norm() + e2.cross(e3).norm() + e3.cross(e1).norm());
  check_volume(p, std::abs(E.determinant()), area, 0.1);
}

TEST(GeometryVolume, ObliqueTorus) {
  const double R = 0.7, r = 0.25;
  TorusPiece t(Vec3(0, 0, 0), Vec3(1, 2, -1), R, r);
  // Pappus: V = 2 pi^2 R r^2, A = 4 pi^2 R r
  check_volume(t, 2 * kPi * kPi * R * r * r, 4 * kPi * kPi * R * r, 0.1);
}

TEST(GeometryVolume, DifferenceOfConcentricSpheresIsAShell) {
  const double R = 1.0, r = 0.6;
  const Vec3 o(0.2, -0.1, 0.05);
  DifferencePiece shell({std::make_shared<SpherePiece>(o, R), std::make_shared<SpherePiece>(o, r)});
  // V = 4/3 pi (R^3 - r^3), A = 4 pi (R^2 + r^2)
  check_volume(shell, 4.0 / 3.0 * kPi * (R * R * R - r * r * r), 4 * kPi * (R * R + r * r), 0.2);
  EXPECT_FALSE(shell.inside(o));
  EXPECT_TRUE(shell.inside(o + Vec3(0.8, 0, 0)));
}

TEST(GeometryVolume, IntersectionOfTwoBoxesIsTheirOverlap) {
  IntersectionPiece both({std::make_shared<BoxPiece>(Vec3(0, 0, 0), Vec3(2, 2, 2)),
                          std::make_shared<BoxPiece>(Vec3(1.01, 0.53, -1), Vec3(3, 2.5, 1.47))});
  // [0,2]^3 and [1.01,3]x[0.53,2.5]x[-1,1.47] overlap in
  // [1.01,2]x[0.53,2]x[0,1.47]: V = 0.99 * 1.47 * 1.47, A = 2 (ab + bc + ca)
  const BoundingBox b = both.bounding_box();
  EXPECT_EQ(b.lo, Vec3(1.01, 0.53, 0));
  EXPECT_EQ(b.hi, Vec3(2, 2, 1.47));
  for (const Vec3& x : {Vec3(1.5, 1, 1), Vec3(1.01, 0.53, 0), Vec3(2, 2, 1.47)}) EXPECT_TRUE(both.inside(x));
  for (const Vec3& x : {Vec3(0.5, 1, 1), Vec3(1.5, 2.2, 1), Vec3(1.5, 1, 1.6)}) EXPECT_FALSE(both.inside(x));
  check_volume(both, 0.99 * 1.47 * 1.47, 2 * (0.99 * 1.47 + 1.47 * 1.47 + 1.47 * 0.99), 0.1);
}

TEST(GeometryVolume, UnionOfOverlappingSpheresByInclusionExclusion) {
  const double r = 0.5, d = 0.6;
  UnionPiece two({std::make_shared<SpherePiece>(Vec3(0, 0, 0), r),
                  std::make_shared<SpherePiece>(Vec3(d, 0, 0), r)});
  // V = 2 (4/3 pi r^3) - V_lens, lens of two spheres of radius r at distance
  // d: V_lens = pi (4r + d)(2r - d)^2 / 12. A <= 2 * 4 pi r^2.
  const double lens = kPi * (4 * r + d) * (2 * r - d) * (2 * r - d) / 12;
  check_volume(two, 2 * 4.0 / 3.0 * kPi * r * r * r - lens, 8 * kPi * r * r, 0.1);
}

// Identity: a parallelepiped whose edge vectors are vectors of the lattice hZ^3
// is a fundamental domain of a sublattice, so (for a generic shift) it holds
// exactly |det E| / h^3 lattice points.
TEST(GeometryVolume, LatticeParallelepipedHoldsExactlyDetOverH3Points) {
  const double h = 0.125;
  const Vec3 p1(0, 0, 0), e1 = h * Vec3(8, 2, 0), e2 = h * Vec3(3, 6, 1), e3 = h * Vec3(-2, 1, 5);
  ParallelepipedPiece p(p1, p1 + e1, p1 + e2, p1 + e3);
  Mat3 E;
  E << e1, e2, e3;
  EXPECT_DOUBLE_EQ(test::counted_volume(p, h), std::abs(E.determinant()));
}
