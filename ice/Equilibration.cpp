#include "ice/Equilibration.h"

#include <cmath>

namespace tephra {

EquilibrationResult equilibrate_pressure(std::vector<EquilibrationMaterial>& mats, std::span<double> press,
                                         int max_iterations, double tol) {
  const std::size_t n = press.size();
  EquilibrationResult result;
  std::vector<EosState> st(n);
  if (mats.size() == 1) {
    EquilibrationMaterial& m = mats[0];
    m.eos->evaluate(m.rho_micro, m.temp, st);
    for (std::size_t i = 0; i < n; ++i) {
      press[i] = st[i].p;
      m.vol_frac[i] = 1.0;
      m.c2[i] = st[i].c2;
    }
    return result;
  }

  const std::size_t nm = mats.size();
  std::vector<std::vector<EosState>> states(nm, std::vector<EosState>(n));
  std::vector<char> done(n, 0);
  for (EquilibrationMaterial& m : mats)
    for (std::size_t i = 0; i < n; ++i) m.vol_frac[i] = m.rho_CC[i] / m.rho_micro[i];

  std::size_t remaining = n;
  int it = 0;
  for (; it < max_iterations && remaining > 0; ++it) {
    for (std::size_t k = 0; k < nm; ++k) mats[k].eos->evaluate(mats[k].rho_micro, mats[k].temp, states[k]);
    for (std::size_t i = 0; i < n; ++i) {
      if (done[i]) continue;
      double A = 0, B = 0, C = 0;
      for (std::size_t k = 0; k < nm; ++k) {
        const double theta = mats[k].vol_frac[i];
        const double Q = press[i] - states[k][i].p;
        const double inv_y = theta * theta / (states[k][i].dp_drho * mats[k].rho_CC[i]);
        A += theta;
        B += Q * inv_y;
        C += inv_y;
      }
      double dp = (A - 1.0 - B) / C;
      if (!(press[i] + dp > 0.0)) dp = -0.5 * press[i];
      press[i] += dp;
      // Convergence is judged on the step just taken; theta is refreshed below.
      if (std::abs(dp) <= tol * press[i] && std::abs(A - 1.0) <= tol) {
        done[i] = 1;
        --remaining;
      }
    }
    for (std::size_t k = 0; k < nm; ++k) {
      EquilibrationMaterial& m = mats[k];
      m.eos->density(press, m.temp, m.rho_micro);
      for (std::size_t i = 0; i < n; ++i) m.vol_frac[i] = m.rho_CC[i] / m.rho_micro[i];
    }
  }
  result.iterations = it;
  if (remaining > 0) {
    result.converged = false;
    for (std::size_t i = 0; i < n; ++i)
      if (!done[i]) {
        result.failed_cell = static_cast<long long>(i);
        break;
      }
  }
  for (std::size_t k = 0; k < nm; ++k) {
    mats[k].eos->evaluate(mats[k].rho_micro, mats[k].temp, states[k]);
    for (std::size_t i = 0; i < n; ++i) mats[k].c2[i] = states[k][i].c2;
  }
  return result;
}

}  // namespace tephra
