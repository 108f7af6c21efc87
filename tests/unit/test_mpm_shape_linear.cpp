// Linear MPM shape functions (mpm/ShapeLinear.h; Vaango theory manual eqs. 1.86-1.89).
#include <gtest/gtest.h>

#include <random>

#include "mpm/ShapeLinear.h"

namespace tephra {
namespace {

// Random points on a non-cubic grid with an offset origin.
struct Fixture {
  Vec3 origin{-0.3, 0.2, 1.0};
  Vec3 h{0.1, 0.25, 0.05};
  std::mt19937 rng{12345};
  Vec3 random_point() {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return origin + Vec3(7 * h[0] * u(rng), 5 * h[1] * u(rng), 3 * h[2] * u(rng));
  }
  Vec3 node(const LinearStencil& s, int n) const {
    const IntVec3 c = s.cell + LinearStencil::offset(n);
    return origin + Vec3(c[0] * h[0], c[1] * h[1], c[2] * h[2]);
  }
};

TEST(MpmShapeLinear, OneDimensionalHatValues) {
  // S(x) = 1 - |x - x_g|/h: a point 0.3 h above node 2 (x direction) has weights
  // 0.7 (node 2) and 0.3 (node 3); gradients -1/h and +1/h (times the y, z hats).
  LinearStencil s;
  const Vec3 h(2.0, 1.0, 1.0);
  linear_stencil(Vec3(2.3 * 2.0, 0.0, 0.0), Vec3::Zero(), h, s);
  EXPECT_EQ(s.cell, IntVec3(2, 0, 0));
  EXPECT_NEAR(s.w[0], 0.7, 1e-15);
  EXPECT_NEAR(s.w[1], 0.3, 1e-15);
  EXPECT_NEAR(s.grad[0][0], -0.5, 1e-15);
  EXPECT_NEAR(s.grad[1][0], 0.5, 1e-15);
  for (int n = 2; n < 8; ++n) EXPECT_EQ(s.w[n], 0.0);  // y = z = 0 on the lower node plane
}

TEST(MpmShapeLinear, PartitionOfUnityAndLinearCompleteness) {
  Fixture f;
  for (int trial = 0; trial < 1000; ++trial) {
    const Vec3 x = f.random_point();
    LinearStencil s;
    linear_stencil(x, f.origin, f.h, s);
    double sum = 0;
    Vec3 sum_x = Vec3::Zero(), sum_grad = Vec3::Zero();
    Mat3 sum_x_grad = Mat3::Zero();
    for (int n = 0; n < 8; ++n) {
      EXPECT_GE(s.w[n], 0.0);
      sum += s.w[n];
      sum_x += s.w[n] * f.node(s, n);
      sum_grad += s.grad[n];
      sum_x_grad += f.node(s, n) * s.grad[n].transpose();
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);                                    // sum S_g = 1
    EXPECT_NEAR((sum_x - x).norm(), 0.0, 1e-14);                     // sum S_g x_g = x
    EXPECT_NEAR(sum_grad.cwiseProduct(f.h).norm(), 0.0, 1e-13);      // sum grad S_g = 0 (scaled by h)
    EXPECT_NEAR((sum_x_grad - Mat3::Identity()).norm(), 0.0, 1e-12); // sum x_g grad S_g^T = I
  }
}

TEST(MpmShapeLinear, GradientMatchesFiniteDifference) {
  // grad S_g is the derivative of S_g inside a cell; central differences of a
  // tri-linear function are exact up to round-off (the function is linear in each
  // coordinate), so the tolerance is round-off of (S(x+e) - S(x-e)) / 2e.
  Fixture f;
  for (int trial = 0; trial < 100; ++trial) {
    LinearStencil s;
    const Vec3 x = f.random_point();
    linear_stencil(x, f.origin, f.h, s);
    for (int d = 0; d < 3; ++d) {
      const double e = 1e-6 * f.h[d];
      // Stay in the same cell: skip points too close to a cell face.
      const double r = (x[d] - f.origin[d]) / f.h[d] - s.cell[d];
      if (r < 1e-5 || r > 1 - 1e-5) continue;
      Vec3 xp = x, xm = x;
      xp[d] += e;
      xm[d] -= e;
      LinearStencil sp, sm;
      linear_stencil(xp, f.origin, f.h, sp);
      linear_stencil(xm, f.origin, f.h, sm);
      for (int n = 0; n < 8; ++n)
        EXPECT_NEAR((sp.w[n] - sm.w[n]) / (2 * e), s.grad[n][d], 1e-8 / f.h[d]);
    }
  }
}

}  // namespace
}  // namespace tephra
