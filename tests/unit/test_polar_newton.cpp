// Newton polar decomposition (models/solid/PolarNewton.h) against its
// definition and against the eigen-solve polar_decomposition (Kinematics.h):
//   R^T R = I, det R = +1, U = U^T positive definite, R U = F (to round-off),
//   and R, U equal to the eigen-solve factors (the polar decomposition of an
//   invertible F is unique).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tephra
