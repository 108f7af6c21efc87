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
// the weight w_m = theta_m / (v_m s_m) (the mass per volume M_m/V, times cv_m
// for heat) shows the change w_m beta_mn = dt theta_m theta_n C_mn is
// symmetric in (m, n): the weighted sum S = sum_m w_m x_m (total momentum
// sum M_m u_m, energy sum M_m cv_m T_m) is conserved.
//
// Solved so that S is kept to round-off for any number of materials and any
// stiffness (session 17; the plain elimination of x^new drifted by ~eps beta:
// 1.3e-8 relative for three materials at K = 1e15). The matrix
// a = I + diag(sum_n beta_mn) - beta has unit row sums, a 1 = 1, so with the
// conserved weighted mean xbar = S / sum_m w_m
//
//   x^new = xbar + y,   a y = x - xbar                               (1)
//
// exactly. (1) solves for the deviations y, which are small when the
// exchange is stiff (|y| ~ |x - xbar| / beta): the elimination's error along
// a's ill-conditioned direction (the constant vector, eigenvalue 1 against
// ~beta for the others) is ~eps beta |y| ~ eps |x - xbar|, round-off. In exact
// arithmetic sum_m w_m y_m = 0 (1^T W a = 1^T W, since W a is symmetric with
// row sums w); the computed y is projected on it, y -= (sum w y)/(sum w)
// (a shift along the constant vector, the direction that carries the solve's
// error, so the solution's accuracy is kept). Then S(x^new) = S(x) up to the
// rounding of xbar, of the projection and of xbar + y: a few n eps sum w|x|
// (test_ice_exchange ConservesTheSumsToRoundOff states the bound).
//
// The N x N system is solved by Gaussian elimination without pivoting and
// without cancellation (solve_dominant); N <= kMaxExchangeMaterials; N = 2
// by its closed form (TwoByTwo). C must be symmetric (the deck's
// <exchange_coefficients> list the pairs once, IceDeck parse_coefficients).
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
// nrhs right-hand sides (overwritten with the solutions), for the exchange
// matrix: off-diagonals a_mk <= 0 and unit row sums, a_mm = 1 + sum_k |a_mk|
// (non-negative coefficients, volume fractions and specific volumes). It is
// strictly diagonally dominant by rows, a property elimination keeps, so no
// pivot is needed (Golub & Van Loan, Matrix Computations, sec. 3.4.10).
// Every step is free of cancellation (the idea of the Grassmann-Taksar-
// Heyman algorithm for Markov chains, Grassmann et al., Oper. Res. 33 (1985)
// 1107): the Schur complement of the active block keeps off-diagonals <= 0,
// made more negative by the update a_rc -= f a_pc (f = a_rp/a_pp <= 0), and
// positive row sums e_r (the "excess", 1 at the start), updated as
// e_r += |f| e_p; the pivot is formed as e_p + sum_{c>p} |a_pc| instead of
// the difference 1 + sum beta - (...), which loses ~eps beta when beta >>
// 1 (session 17: 1.2e-12 against 2.6e-13 on a cell whose materials form two
// weakly coupled groups). Back substitution x_p = (b_p + sum |a_pc| x_c)/a_pp
// adds positive multiples. So the solution is accurate to ~n eps of the
// data's scale whatever the stiffness.
inline void solve_dominant(int n, double* a, std::span<double>* b, int nrhs) {
  double e[kMaxExchangeMaterials];
  for (int m = 0; m < n; ++m) e[m] = 1.0;
  for (int p = 0; p < n; ++p) {
    double pivot = e[p];
    for (int c = p + 1; c < n; ++c) pivot -= a[p * n + c];
    a[p * n + p] = pivot;
    const double inv = 1.0 / pivot;
    for (int r = p + 1; r < n; ++r) {
      const double f = a[r * n + p] * inv;
      if (f == 0.0) continue;
      for (int c = p + 1; c < n; ++c)
        if (c != r) a[r * n + c] -= f * a[p * n + c];
      e[r] -= f * e[p];
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

// Weights w_m = theta_m / (v_m s_m) and their sum (Exchange.h header).
inline double exchange_weights(std::span<const double> theta, std::span<const double> sp_vol,
                               std::span<const double> scale, double* w) {
  double W = 0;
  for (std::size_t m = 0; m < theta.size(); ++m) {
    w[m] = theta[m] / (sp_vol[m] * (scale.empty() ? 1.0 : scale[m]));
    W += w[m];
  }
  return W;
}

// Deviation form (1) for nrhs <= 3 right-hand sides sharing the matrix:
// x -> xbar + y with a y = x - xbar, then sum w y = 0 enforced. a: the
// matrix (overwritten by the elimination), or two: the n = 2 closed form,
// y1 - y2 = (x1 - x2)/det and w1 y1 + w2 y2 = 0, i.e. y1 = w2 t, y2 = -w1 t
// with t = (x1 - x2)/(det W).
inline void solve_conservative(std::span<const double> theta, std::span<const double> sp_vol,
                               std::span<const double> scale, const TwoByTwo* two, double* a,
                               std::span<double>* x, int nrhs) {
  const int n = static_cast<int>(theta.size());
  assert(nrhs <= 3);
  double w[kMaxExchangeMaterials];
  const double W = exchange_weights(theta, sp_vol, scale, w);
  if (!(W > 0.0)) {  // no material with volume: nothing to conserve, the plain solve
    if (two)
      for (int q = 0; q < nrhs; ++q) two->solve(x[q]);
    else
      solve_dominant(n, a, x, nrhs);
    return;
  }
  const double inv_W = 1.0 / W;
  double xbar[3];
  for (int q = 0; q < nrhs; ++q) {
    double S = 0;
    for (int m = 0; m < n; ++m) S += w[m] * x[q][m];
    xbar[q] = S * inv_W;
  }
  if (two) {
    const double f = two->inv_det * inv_W;
    for (int q = 0; q < nrhs; ++q) {
      const double t = (x[q][0] - x[q][1]) * f;
      x[q][0] = xbar[q] + w[1] * t;
      x[q][1] = xbar[q] - w[0] * t;
    }
    return;
  }
  for (int q = 0; q < nrhs; ++q)
    for (int m = 0; m < n; ++m) x[q][m] -= xbar[q];
  solve_dominant(n, a, x, nrhs);
  for (int q = 0; q < nrhs; ++q) {
    double Sy = 0;
    for (int m = 0; m < n; ++m) Sy += w[m] * x[q][m];
    const double c = Sy * inv_W;
    for (int m = 0; m < n; ++m) x[q][m] = xbar[q] + (x[q][m] - c);
  }
}

}  // namespace exchange_detail

inline void solve_exchange(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                    std::span<const double> scale, std::span<const double> coeff, std::span<double> x) {
  if (theta.size() == 2) {
    const exchange_detail::TwoByTwo two(dt, theta, sp_vol, scale, coeff);
    exchange_detail::solve_conservative(theta, sp_vol, scale, &two, nullptr, &x, 1);
    return;
  }
  double a[kMaxExchangeMaterials * kMaxExchangeMaterials];
  exchange_detail::exchange_matrix(dt, theta, sp_vol, scale, coeff, a);
  exchange_detail::solve_conservative(theta, sp_vol, scale, nullptr, a, &x, 1);
}

inline void solve_exchange3(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                     std::span<const double> coeff, std::span<double> ux, std::span<double> uy,
                     std::span<double> uz) {
  std::span<double> b[3] = {ux, uy, uz};
  if (theta.size() == 2) {
    const exchange_detail::TwoByTwo two(dt, theta, sp_vol, {}, coeff);
    exchange_detail::solve_conservative(theta, sp_vol, {}, &two, nullptr, b, 3);
    return;
  }
  double a[kMaxExchangeMaterials * kMaxExchangeMaterials];
  exchange_detail::exchange_matrix(dt, theta, sp_vol, {}, coeff, a);
  exchange_detail::solve_conservative(theta, sp_vol, {}, nullptr, a, b, 3);
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
