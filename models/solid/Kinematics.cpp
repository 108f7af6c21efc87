#include "models/solid/Kinematics.h"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace tephra {

PolarDecomposition polar_decomposition(const Eigen::Matrix3d& F) {
  // C = F^T F = Q diag(l^2) Q^T  =>  U = Q diag(l) Q^T, U^{-1} = Q diag(1/l) Q^T.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(F.transpose() * F);
  const Eigen::Vector3d l = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  const Eigen::Matrix3d& Q = eig.eigenvectors();
  PolarDecomposition pd;
  pd.U = Q * l.asDiagonal() * Q.transpose();
  pd.R = F * (Q * l.cwiseInverse().asDiagonal() * Q.transpose());
  return pd;
}

Eigen::Vector3d principal_stretches(const Eigen::Matrix3d& F) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(F * F.transpose(), Eigen::EigenvaluesOnly);
  return eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace tephra
