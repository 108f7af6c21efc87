#include "models/solid/PolarNewton.h"

#include <cmath>

#include <Eigen/LU>

namespace tephra {

PolarDecomposition polar_decomposition_newton(const Eigen::Matrix3d& F) {
  Eigen::Matrix3d X = F;
  bool scale = true;
  for (int k = 0; k < 40; ++k) {
    const double det = X.determinant();
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) break;
    // Scaling speeds up the first steps only; near convergence zeta -> 1.
    // zeta ~ 1 when |det X| ~ 1 (the mean stretch is 1): no cube root then.
    const double zeta = scale && std::abs(std::abs(det) - 1.0) > 1e-3 ? std::cbrt(1.0 / std::abs(det)) : 1.0;
    // zeta X formed once, and not at all when zeta = 1 (1 x = x exactly for
    // every double): the coefficients Eigen's expression formed, so the same bits.
    Eigen::Matrix3d next;
    if (zeta == 1.0) {
      next = 0.5 * (X + X.inverse().transpose());
    } else {
      const Eigen::Matrix3d Z = zeta * X;
      next = 0.5 * (Z + Z.inverse().transpose());
    }
    const double change = (next - X).lpNorm<1>();  // sum |.|, ||X|| ~ 3 near convergence
    X = next;
    if (change < 1e-3) scale = false;
    // Quadratic convergence: the error after this step is O(change^2),
    // below round-off once change < 1e-9.
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

}  // namespace tephra
