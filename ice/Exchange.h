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
// diagonally dominant by rows); N <= kMaxExchangeMaterials.
#include <span>

namespace tephra {

constexpr int kMaxExchangeMaterials = 16;

// x: in = values before exchange, out = after. theta, sp_vol, scale: per
// material. coeff: n x n row-major, symmetric. x is scalar per material; call
// once per velocity component.
void solve_exchange(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                    std::span<const double> scale, std::span<const double> coeff, std::span<double> x);

// Same for three components at once (one matrix factorisation).
void solve_exchange3(double dt, std::span<const double> theta, std::span<const double> sp_vol,
                     std::span<const double> coeff, std::span<double> ux, std::span<double> uy,
                     std::span<double> uz);

}  // namespace tephra
