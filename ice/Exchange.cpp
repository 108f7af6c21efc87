#include "ice/Exchange.h"

#include <Eigen/Dense>
#include <cassert>

namespace tephra {

namespace {

using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxExchangeMaterials,
                                  kMaxExchangeMaterials>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxExchangeMaterials, 1>;

SmallMatrix exchange_matrix(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                            std::span<const double> scale, std::span<const double> coeff) {
  const int n = static_cast<int>(theta.size());
  assert(n <= kMaxExchangeMaterials);
  SmallMatrix a(n, n);
  for (int m = 0; m < n; ++m) {
    a(m, m) = 1.0;
    for (int k = 0; k < n; ++k) {
      if (k == m) continue;
      const double beta = dt * theta[k] * coeff[m * n + k] * sp_vol[m] * (scale.empty() ? 1.0 : scale[m]);
      a(m, k) = -beta;
      a(m, m) += beta;
    }
  }
  return a;
}

}  // namespace

void solve_exchange(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                    std::span<const double> scale, std::span<const double> coeff, std::span<double> x) {
  const int n = static_cast<int>(theta.size());
  const SmallMatrix a = exchange_matrix(dt, theta, sp_vol, scale, coeff);
  SmallVector b(n);
  for (int m = 0; m < n; ++m) b[m] = x[m];
  const SmallVector r = a.partialPivLu().solve(b);
  for (int m = 0; m < n; ++m) x[m] = r[m];
}

void solve_exchange3(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                     std::span<const double> coeff, std::span<double> ux, std::span<double> uy,
                     std::span<double> uz) {
  const int n = static_cast<int>(theta.size());
  const SmallMatrix a = exchange_matrix(dt, theta, sp_vol, {}, coeff);
  const Eigen::PartialPivLU<SmallMatrix> lu(a);
  for (std::span<double> x : {ux, uy, uz}) {
    SmallVector b(n);
    for (int m = 0; m < n; ++m) b[m] = x[m];
    const SmallVector r = lu.solve(b);
    for (int m = 0; m < n; ++m) x[m] = r[m];
  }
}

}  // namespace tephra
