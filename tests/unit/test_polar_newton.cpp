// Newton polar decomposition (models/solid/PolarNewton.h) against its
// definition and against the eigen-solve polar_decomposition (Kinematics.h):
//   R^T R = I, det R = +1, U = U^T positive definite, R U = F (to round-off),
//   and R, U equal to the eigen-solve factors (the polar decomposition of an
//   invertible F is unique).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "models/solid/PolarNewton.h"

namespace tephra {
namespace {

TEST(PolarNewton, MatchesDefinitionAndEigenSolve) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (int trial = 0; trial < 2000; ++trial) {
    // F = Q V with Q a rotation and V symmetric positive definite; the
    // strain size from 1e-8 (near a pure rotation) to O(1).
    const double size = std::pow(10.0, -8.0 + 8.0 * (trial % 9) / 8.0);
    Eigen::Matrix3d A;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) A(a, b) = size * u(rng);
    const Eigen::Matrix3d V = (I + 0.5 * (A + A.transpose())).eval();
    if (V.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff() < 0.2) continue;
    const Eigen::Matrix3d Q =
        Eigen::AngleAxisd(3.0 * u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    const Eigen::Matrix3d F = Q * V;
    const PolarDecomposition n = polar_decomposition_newton(F), e = polar_decomposition(F);
    EXPECT_LE((n.R.transpose() * n.R - I).norm(), 1e-14);
    EXPECT_NEAR(n.R.determinant(), 1.0, 1e-14);
    EXPECT_EQ(n.U, n.U.transpose());
    EXPECT_LE((n.R * n.U - F).norm(), 1e-14 * F.norm());
    EXPECT_LE((n.R - Q).norm(), 1e-12);
    EXPECT_LE((n.U - V).norm(), 1e-12);
    EXPECT_LE((n.R - e.R).norm(), 1e-13);
    EXPECT_LE((n.U - e.U).norm(), 1e-13 * e.U.norm());
  }
}

TEST(PolarNewton, RotationAndIdentityExactly) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const PolarDecomposition a = polar_decomposition_newton(I);
  EXPECT_EQ(a.R, I);
  EXPECT_EQ(a.U, I);
  // A large stretch with shear (12:1 principal stretch ratio).
  Eigen::Matrix3d F;
  F << 3.0, 1.0, 0.0, 0.0, 0.25, 0.0, 0.0, 0.5, 1.0;
  const PolarDecomposition b = polar_decomposition_newton(F), e = polar_decomposition(F);
  EXPECT_LE((b.R * b.U - F).norm(), 1e-14 * F.norm());
  EXPECT_LE((b.R - e.R).norm(), 1e-13);
  EXPECT_LE((b.U - e.U).norm(), 1e-13 * e.U.norm());
}

// The iteration as written before session 23 (zeta X formed inside the
// expression, also when zeta = 1): the reference for the bits.
PolarDecomposition newton_before_session23(const Eigen::Matrix3d& F) {
  Eigen::Matrix3d X = F;
  bool scale = true;
  for (int k = 0; k < 40; ++k) {
    const double det = X.determinant();
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) break;
    const double zeta = scale && std::abs(std::abs(det) - 1.0) > 1e-3 ? std::cbrt(1.0 / std::abs(det)) : 1.0;
    const Eigen::Matrix3d next = 0.5 * (zeta * X + (zeta * X).inverse().transpose());
    const double change = (next - X).lpNorm<1>();
    X = next;
    if (change < 1e-3) scale = false;
    if (change < 1e-9) {
      PolarDecomposition pd;
      pd.R = X;
      const Eigen::Matrix3d RtF = X.transpose() * F;
      pd.U = 0.5 * (RtF + RtF.transpose());
      return pd;
    }
  }
  return polar_decomposition(F);
}

// Session 23 forms zeta X once and skips it when zeta = 1 (1 x = x exactly):
// R and U bit for bit those of the earlier loop, for F from near-rotations to
// large stretches (scaled and unscaled iterations) and for a few exact cases.
TEST(PolarNewton, SameBitsAsTheLoopBeforeSession23) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int scaled = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double size = std::pow(10.0, -10.0 + 10.0 * (trial % 11) / 10.0);
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) F(a, b) += size * u(rng);
    if (trial % 3 == 0) F *= 1.0 + 0.5 * u(rng);  // |det F| away from 1: scaled first steps
    if (!(F.determinant() > 0.0)) continue;
    scaled += std::abs(std::abs(F.determinant()) - 1.0) > 1e-3;
    const PolarDecomposition a = polar_decomposition_newton(F), b = newton_before_session23(F);
    ASSERT_EQ(a.R, b.R) << F;
    ASSERT_EQ(a.U, b.U) << F;
  }
  EXPECT_GT(scaled, 1000);  // both branches of zeta were taken
  Eigen::Matrix3d F;
  F << 3.0, 1.0, 0.0, 0.0, 0.25, 0.0, 0.0, 0.5, 1.0;
  for (const Eigen::Matrix3d& G : {Eigen::Matrix3d(Eigen::Matrix3d::Identity()), F, Eigen::Matrix3d(2.0 * F)}) {
    const PolarDecomposition a = polar_decomposition_newton(G), b = newton_before_session23(G);
    EXPECT_EQ(a.R, b.R);
    EXPECT_EQ(a.U, b.U);
  }
}

}  // namespace
}  // namespace tephra
