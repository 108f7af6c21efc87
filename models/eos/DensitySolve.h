#pragma once
// rho(p, T) for an EOS without a closed-form inverse: Newton's method on
// f(rho) = p(rho, T) - p_target, safeguarded by a bracket [lo, hi] with
// f(lo) < 0 < f(hi) (a step leaving the bracket, or not halving |f|
// fast enough, is replaced by bisection). The bracket starts at
// [lo, hi] given by the model and hi is doubled until f(hi) > 0.
// This is the hybrid Newton-bisection Uintah uses for JWL (JWL.cc, due to
// C. Xiong), applied to every iterative EOS here. Returns NaN when no bracket
// exists or the iteration does not converge (the caller's state check then
// stops the run with a NumericalFailure naming the cell).
#include <cmath>
#include <limits>

namespace tephra {

// f(rho) returns {p(rho) - p_target, dp/drho}.
template <class F>
double solve_density_bracketed(F&& f, double lo, double hi, double hi_limit = std::numeric_limits<double>::infinity(),
                               double rel_tol = 1e-14) {
  auto [f_hi, d_hi] = f(hi);
  (void)d_hi;
  for (int k = 0; k < 200 && !(f_hi > 0); ++k) {
    if (f_hi == 0) return hi;
    lo = hi;
    hi = std::min(2.0 * hi, hi_limit);
    f_hi = f(hi).first;
    if (hi == hi_limit && !(f_hi > 0)) return std::numeric_limits<double>::quiet_NaN();
  }
  if (!(f_hi > 0)) return std::numeric_limits<double>::quiet_NaN();
  double x = 0.5 * (lo + hi);
  double dx_old = hi - lo;
  for (int it = 0; it < 200; ++it) {
    const auto [fx, dfx] = f(x);
    if (fx == 0) return x;
    if (fx < 0) lo = x;
    else hi = x;
    double xn = x - fx / dfx;
    const bool newton_ok = std::isfinite(xn) && xn > lo && xn < hi && std::abs(xn - x) < 0.5 * dx_old;
    if (!newton_ok) xn = 0.5 * (lo + hi);
    dx_old = std::abs(xn - x);
    x = xn;
    if (dx_old <= rel_tol * x || (hi - lo) <= rel_tol * x) return x;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace tephra
