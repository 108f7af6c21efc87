#pragma once
// Polar decomposition F = R U by Newton's iteration for the orthogonal factor
// (Higham 1986, "Computing the polar decomposition - with applications",
// SIAM J. Sci. Stat. Comput. 7(4), eqs. 3.1 and 3.5 with the determinant
// scaling of §3.2):
//   X_0 = F,  X_{k+1} = (zeta_k X_k + (zeta_k X_k)^{-T}) / 2,  zeta_k = |det X_k|^{-1/3},
// converging quadratically to R; then U = sym(R^T F). Same result as
// polar_decomposition (Kinematics.h, eigen-decomposition of F^T F) to
// round-off, at a fraction of the cost (a few 3x3 inverses instead of a
// symmetric eigen-solve): the hot path of hypo_elastic. Precondition: det F > 0;
// falls back to polar_decomposition if the iteration has not converged in 40 steps.
#include <Eigen/Core>

#include "models/solid/Kinematics.h"

namespace tephra {

PolarDecomposition polar_decomposition_newton(const Eigen::Matrix3d& F);

}  // namespace tephra
