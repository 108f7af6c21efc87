#pragma once
// Equilibration pressure (Vaango theory manual eq. 24.7, step 1 of the ICE
// step): in each cell find p such that the materials, each at its own
// temperature T_m and bulk density rho_CC_m, fill the cell exactly:
//     sum_m theta_m = 1,   theta_m = rho_CC_m / rho_m(p, T_m).
// Newton's method as in Uintah's computeEquilibrationPressure: with
//     Q_m = p - p_m(rho_m, T_m),   y_m = dp_m/drho * rho_CC_m / theta_m^2,
//     dp = (sum theta - 1 - sum Q_m/y_m) / sum 1/y_m,
// then rho_m = rho_m(p + dp, T_m) and theta_m = rho_CC_m / rho_m (Q_m = 0
// after the first iteration, so this is Newton on sum theta_m(p) = 1, since
// dtheta_m/dp = -1/y_m). A step that would make p <= 0 is halved instead.
// One material needs no iteration: theta = 1, p = p_eos(rho_micro, T).
#include <span>
#include <vector>

#include "models/eos/EquationOfState.h"

namespace tephra {

struct EquilibrationMaterial {
  const EquationOfState* eos = nullptr;
  std::span<const double> rho_CC, temp;  // in
  std::span<double> rho_micro;           // in: starting guess (1/sp_vol); out
  std::span<double> vol_frac, c2;        // out
  // Optional per-cell ideal gas (a model's mixture, e.g. SimpleRxn): when
  // both are non-empty the material is p = (gamma_i - 1) rho cv_i T in cell
  // i (models/eos/IdealGas.h with the cell's constants) and `eos` is unused.
  std::span<const double> cell_gamma, cell_cv;
};

struct EquilibrationResult {
  bool converged = true;
  long long failed_cell = -1;  // first cell (index into the spans) that did not converge
  int iterations = 0;          // the largest count over the cells
};

// All spans have the same length n (cells). `press` holds a starting guess on
// entry (used by Newton only; one material ignores it) and the result on exit.
// Converged when |sum theta - 1| <= tol and the last Newton step dp is below
// tol * p or below the round-off resolution of sum theta (|dp| C <= 4 nm eps,
// C = -d sum theta/dp) in every cell.
EquilibrationResult equilibrate_pressure(std::vector<EquilibrationMaterial>& mats, std::span<double> press,
                                         int max_iterations, double tol = 1e-11);

}  // namespace tephra
