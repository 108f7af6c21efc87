#include "mpm/DeformationGradient.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace tephra {

DeformationGradientAlgorithm deformation_gradient_algorithm(const std::string& name) {
  if (name == "first_order") return DeformationGradientAlgorithm::FirstOrder;
  if (name == "subcycling") return DeformationGradientAlgorithm::Subcycling;
  if (name == "taylor_series") return DeformationGradientAlgorithm::TaylorSeries;
  if (name == "cayley_hamilton") return DeformationGradientAlgorithm::CayleyHamilton;
  throw std::invalid_argument("unknown deformation_gradient algorithm '" + name + "'");
}

Mat3 deformation_gradient_increment(DeformationGradientAlgorithm alg, const Mat3& A, int terms) {
  const Mat3 I = Mat3::Identity();
  switch (alg) {
    case DeformationGradientAlgorithm::FirstOrder:
      return I + A;
    case DeformationGradientAlgorithm::Subcycling: {
      const int s = std::min(std::max(1, 2 * int(std::floor(A.norm()))), 1000);
      const Mat3 step = I + A / double(s);
      Mat3 inc = I;
      for (int k = 0; k < s; ++k) inc = step * inc;
      return inc;
    }
    case DeformationGradientAlgorithm::TaylorSeries: {
      // sum_{k=0}^{N} A^k / k!, term_k = term_{k-1} A / k.
      Mat3 inc = I, term = I;
      for (int k = 1; k <= terms; ++k) {
        term = term * A / double(k);
        inc += term;
      }
      return inc;
    }
    case DeformationGradientAlgorithm::CayleyHamilton: {
      // A^k = b0_k I + b1_k A + b2_k A^2; by Cayley-Hamilton
      // A^3 = I1 A^2 - I2 A + I3 I with I1 = tr A, I2 = (I1^2 - tr A^2)/2, I3 = det A,
      // so A^{k+1} = I3 b2 I + (b0 - I2 b2) A + (b1 + I1 b2) A^2.
      const Mat3 A2 = A * A;
      const double I1 = A.trace(), I2 = 0.5 * (I1 * I1 - A2.trace()), I3 = A.determinant();
      double a0 = 1.0, a1 = terms >= 1 ? 1.0 : 0.0, a2 = terms >= 2 ? 0.5 : 0.0;
      double b0 = 0.0, b1 = 0.0, b2 = 1.0, inv_factorial = 0.5;  // A^2 and 1/2!
      for (int k = 3; k <= terms; ++k) {
        const double n0 = I3 * b2, n1 = b0 - I2 * b2, n2 = b1 + I1 * b2;
        b0 = n0;
        b1 = n1;
        b2 = n2;
        inv_factorial /= double(k);
        a0 += b0 * inv_factorial;
        a1 += b1 * inv_factorial;
        a2 += b2 * inv_factorial;
      }
      return a0 * I + a1 * A + a2 * A2;
    }
  }
  return I + A;
}

void update_deformation_gradients(DeformationGradientAlgorithm alg, int terms, double dt,
                                  const std::vector<Mat3>& L, const std::vector<Mat3>& F_old,
                                  std::vector<Mat3>& F) {
  const long n = long(F_old.size());
  F.resize(F_old.size());
  // Eigen evaluates the product into a temporary, so F may alias F_old.
  if (alg == DeformationGradientAlgorithm::FirstOrder) {
#pragma omp parallel for schedule(static) if (n >= 4096)
    for (long i = 0; i < n; ++i) F[i] = (Mat3::Identity() + dt * L[i]) * F_old[i];
    return;
  }
#pragma omp parallel for schedule(static) if (n >= 4096)
  for (long i = 0; i < n; ++i) F[i] = deformation_gradient_increment(alg, dt * L[i], terms) * F_old[i];
}

void update_deformation_gradients(DeformationGradientAlgorithm alg, int terms, double dt,
                                  const std::vector<Mat3>& L, std::vector<Mat3>& F) {
  update_deformation_gradients(alg, terms, dt, L, F, F);
}

}  // namespace tephra
