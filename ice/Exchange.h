#pragma once
// Point-implicit momentum and heat exchange among the materials of one cell
// or face (Vaango theory manual eq. 26.11-26.12 in the conservative form of
// the inventory's erratum 3, which is what Uintah's ICE solves):
//
//   x_m^new - x_m = sum_n beta_mn (x_n^new - x_m^new),
//   beta_mn = dt * theta_n * C_mn * v_m * s_m,
//
// with v_m the specific volume (1/rho_micro), C the symmetric coefficient
// matrix (K for momentum, s_m = 1; H for heat, s_m = 1/cv_m). Multiplying by
// the mass M_m = V theta_m / v_m (and cv_m for heat) shows the change
// dt V theta_m theta_n C_mn (x_n - x_m) is antisymmetric in (m, n): total
// momentum sum M_m u_m and energy sum M_m cv_m T_m are conserved.
//
// The N x N system (I + diag(sum_n beta_mn) - beta) x^new = x is solved per
// call by Gaussian elimination without pivoting (the matrix is strictly
// diagonally dominant by rows); N <= kMaxExchangeMaterials; N = 2 by its
// closed form (TwoByTwo).
#include <algorithm>
#include <cassert>
#include <span>

namespace tephra {

constexpr int kMaxExchangeMaterials = 16;

// x: in = values before exchange, out = after. theta, sp_vol, scale: per
// material. coeff: n x n row-major, symmetric. x is scalar per material; call
// once per velocity component.
// solve_exchange3: the same for three components at once (one matrix factorisation).
// Defined inline here: they run once per cell and face of multi-material
// steps, where the call and the generic n cost more than the n <= 4 solve.
namespace exchange_detail {

// a = I + diag(sum_k beta_mk) - beta (row-major, n x n), beta_mk as above.
inline void exchange_matrix(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                     std::span<const double> scale, std::span<const double> coeff, double* a) {
  const int n = static_cast<int>(theta.size());
  assert(n <= kMaxExchangeMaterials);
  for (int m = 0; m < n; ++m) {
    double diag = 1.0;
    for (int k = 0; k < n; ++k) {
      if (k == m) continue;
      const double beta = dt * theta[k] * coeff[m * n + k] * sp_vol[m] * (scale.empty() ? 1.0 : scale[m]);
      a[m * n + k] = -beta;
      diag += beta;
    }
    a[m * n + m] = diag;
  }
}

// Gaussian elimination without pivoting on the n x n system a x = b for
// nrhs right-hand sides (overwritten with the solutions). The exchange matrix
// is strictly diagonally dominant by rows (a_mm = 1 + sum_k |a_mk| for
// non-negative coefficients, volume fractions and specific volumes), a
// property elimination keeps, so no pivot is needed and none is small
// (Golub & Van Loan, Matrix Computations, sec. 3.4.10).
inline void solve_dominant(int n, double* a, std::span<double>* b, int nrhs) {
  for (int p = 0; p < n; ++p) {
    const double inv = 1.0 / a[p * n + p];
    for (int r = p + 1; r < n; ++r) {
      const double f = a[r * n + p] * inv;
      if (f == 0.0) continue;
      for (int c = p + 1; c < n; ++c) a[r * n + c] -= f * a[p * n + c];
      for (int q = 0; q < nrhs; ++q) b[q][r] -= f * b[q][p];
    }
  }
  for (int p = n - 1; p >= 0; --p) {
    const double inv = 1.0 / a[p * n + p];
    for (int q = 0; q < nrhs; ++q) {
      double s = b[q][p];
      for (int c = p + 1; c < n; ++c) s -= a[p * n + c] * b[q][c];
      b[q][p] = s * inv;
    }
  }
}

// Two materials (the common case), closed form of the 2 x 2 system
//   (1 + b12) x1' - b12 x2' = x1,   -b21 x1' + (1 + b21) x2' = x2,
// det = 1 + b12 + b21 (Cramer's rule):
//   x1' = ((1 + b21) x1 + b12 x2)/det,   x2' = (b21 x1 + (1 + b12) x2)/det.
// One division instead of the elimination's three.
struct TwoByTwo {
  double b12, b21, inv_det;
  TwoByTwo(double dt, std::span<const double> theta, std::span<const double> sp_vol, std::span<const double> scale,
           std::span<const double> coeff) {
    b12 = dt * theta[1] * coeff[1] * sp_vol[0] * (scale.empty() ? 1.0 : scale[0]);
    b21 = dt * theta[0] * coeff[2] * sp_vol[1] * (scale.empty() ? 1.0 : scale[1]);
    inv_det = 1.0 / (1.0 + b12 + b21);
  }
  void solve(std::span<double> x) const {
    const double x1 = x[0], x2 = x[1];
    x[0] = ((1.0 + b21) * x1 + b12 * x2) * inv_det;
    x[1] = (b21 * x1 + (1.0 + b12) * x2) * inv_det;
  }
};

}  // namespace exchange_detail

inline void solve_exchange(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                    std::span<const double> scale, std::span<const double> coeff, std::span<double> x) {
  if (theta.size() == 2) {
    exchange_detail::TwoByTwo(dt, theta, sp_vol, scale, coeff).solve(x);
    return;
  }
  double a[kMaxExchangeMaterials * kMaxExchangeMaterials];
  exchange_detail::exchange_matrix(dt, theta, sp_vol, scale, coeff, a);
  exchange_detail::solve_dominant(static_cast<int>(theta.size()), a, &x, 1);
}

inline void solve_exchange3(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                     std::span<const double> coeff, std::span<double> ux, std::span<double> uy,
                     std::span<double> uz) {
  if (theta.size() == 2) {
    const exchange_detail::TwoByTwo s(dt, theta, sp_vol, {}, coeff);
    s.solve(ux);
    s.solve(uy);
    s.solve(uz);
    return;
  }
  double a[kMaxExchangeMaterials * kMaxExchangeMaterials];
  exchange_detail::exchange_matrix(dt, theta, sp_vol, {}, coeff, a);
  std::span<double> b[3] = {ux, uy, uz};
  exchange_detail::solve_dominant(static_cast<int>(theta.size()), a, b, 3);
}

// <exchange_properties><heatExchangeCoeff> variable (Uintah's
// ExchangeCoefficients::getVariableExchangeCoeff; the momentum coefficients
// stay the deck's): per cell, for every pair of materials, with the ratio of
// their Lagrangian masses r = M_L,n / M_L,m,
//   H_mn = H_nm = min(1e12, max(1e5, r^2, 1/r^2))   [W/(m^3 K)],
// Uintah's five branches (r^2 < 1e-12: 1e12; < 1e-5: 1/r^2; < 1e5: 1e5;
// < 1e12: r^2; else 1e12) in one line. H: n x n row-major, zero diagonal.
inline void variable_heat_coefficients(std::span<const double> mass_L, double* H) {
  const std::size_t n = mass_L.size();
  for (std::size_t m = 0; m < n; ++m) {
    H[m * n + m] = 0.0;
    for (std::size_t q = m + 1; q < n; ++q) {
      const double r = mass_L[q] / mass_L[m], r2 = r * r;
      const double h = std::min(1e12, std::max({1e5, r2, 1.0 / r2}));
      H[m * n + q] = H[q * n + m] = h;
    }
  }
}

}  // namespace tephra
