#pragma once
// Finite-deformation kinematics shared by the solid models (Eigen only).
#include <Eigen/Core>

namespace tephra {

// Polar decomposition F = R U (VT eq. 4.1 ff., 17.1): U = sqrt(F^T F) the right
// stretch tensor (symmetric positive definite), R = F U^{-1} the rotation.
// Precondition: det F > 0. U comes from the eigen-decomposition of C = F^T F.
struct PolarDecomposition {
  Eigen::Matrix3d R;
  Eigen::Matrix3d U;
};
PolarDecomposition polar_decomposition(const Eigen::Matrix3d& F);

// Principal stretches lambda_i = sqrt(eig(F F^T)), ascending.
Eigen::Vector3d principal_stretches(const Eigen::Matrix3d& F);

}  // namespace tephra
