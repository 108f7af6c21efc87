#include "ice/Equilibration.h"

#include <cmath>
#include <limits>

#include "models/eos/IdealGas.h"

namespace tephra {

namespace {

// Per-thread work arrays (the equilibration runs once per (j, k) row of
// cells, possibly on several threads): no allocation per call once warm.
struct EquilibrationScratch {
  std::vector<EosState> states;        // nm x n, material-major, of the active cells
  std::vector<double> rho, temp;       // nm x n: gathered inputs of the active cells
  std::vector<double> press;           // n: pressures of the active cells
  std::vector<std::size_t> active;     // the cells still iterating, ascending
  std::vector<char> done;              // per active cell: converged in this iteration
};

// out[a] = the state of material m at (rho[a], T[a]); cell[a] (or a when
// cell is null) is the index of that cell in m's spans (for a per-cell gas).
void evaluate(const EquilibrationMaterial& m, std::span<const double> rho, std::span<const double> T,
              const std::size_t* cell, std::span<EosState> out) {
  if (m.cell_gamma.empty()) return m.eos->evaluate(rho, T, out);
  for (std::size_t a = 0; a < out.size(); ++a) {
    const std::size_t i = cell ? cell[a] : a;
    out[a] = IdealGas::state(m.cell_gamma[i], m.cell_cv[i], rho[a], T[a]);
  }
}

// rho[a] = rho(p[a], T[a]) of material m; for a per-cell gas
// rho = p / ((gamma_i - 1) cv_i T) (IdealGas.h).
void density(const EquilibrationMaterial& m, std::span<const double> p, std::span<const double> T,
             const std::size_t* cell, std::span<double> rho) {
  if (m.cell_gamma.empty()) return m.eos->density(p, T, rho);
  for (std::size_t a = 0; a < rho.size(); ++a) {
    const std::size_t i = cell ? cell[a] : a;
    rho[a] = p[a] / ((m.cell_gamma[i] - 1.0) * m.cell_cv[i] * T[a]);
  }
}

// Sum over the materials of theta_m = rho_CC_m / rho_m(p, T_m) in cell i, with
// rho_micro_m(i) set to rho_m(p, T_m).
double volume_fraction_sum(std::vector<EquilibrationMaterial>& mats, std::size_t i, double p) {
  double sum = 0.0;
  for (EquilibrationMaterial& m : mats) {
    const double T = m.temp[i];
    double rho = 0.0;
    density(m, {&p, 1}, {&T, 1}, &i, {&rho, 1});
    m.rho_micro[i] = rho;
    sum += m.rho_CC[i] / rho;
  }
  return sum;
}

// The fallback when Newton stalls in a cell, as Uintah's
// MPMICE::binaryPressureSearch (a bisection between DBL_EPSILON and
// 1/DBL_EPSILON Pa; the stall it rescues: a near-vacuum guess, e.g.
// JWLppCuRS2d's copper with traces of gas behind the initiation end at
// p = 1e-12 Pa, where Newton crawls up by doublings). f(p) = sum theta_m(p) - 1
// decreases with p (every rho_m(p, T) increases with p), so the root is
// bracketed when f(lo) > 0 > f(hi); the bisection is on log p (the bracket
// spans 31 decades). Converged when |f| <= tol, or when the bracket is at the
// round-off of p (hi - lo <= 4 eps hi: the root is then resolved as far as a
// double can). Sets press, rho_micro and vol_frac of cell i; false when f
// does not change sign on the bracket or the bisection runs out of steps.
bool bisect_cell_pressure(std::vector<EquilibrationMaterial>& mats, std::size_t i, double& press, double tol) {
  const double eps = std::numeric_limits<double>::epsilon();
  double lo = eps, hi = 1.0 / eps;
  if (!(volume_fraction_sum(mats, i, lo) - 1.0 > 0.0) || !(volume_fraction_sum(mats, i, hi) - 1.0 < 0.0)) return false;
  for (int k = 0; k < 400; ++k) {  // 31 decades to 4 eps: about 60 halvings of log p
    const double mid = std::sqrt(lo * hi);
    const double f = volume_fraction_sum(mats, i, mid) - 1.0;
    if (std::abs(f) <= tol || hi - lo <= 4.0 * eps * hi) {
      press = mid;
      for (EquilibrationMaterial& m : mats) m.vol_frac[i] = m.rho_CC[i] / m.rho_micro[i];
      return true;
    }
    (f > 0.0 ? lo : hi) = mid;
  }
  return false;
}

}  // namespace

EquilibrationResult equilibrate_pressure(std::vector<EquilibrationMaterial>& mats, std::span<double> press,
                                         int max_iterations, double tol) {
  const std::size_t n = press.size();
  const std::size_t nm = mats.size();
  thread_local EquilibrationScratch s;
  EquilibrationResult result;
  if (s.states.size() < n * nm) s.states.resize(n * nm);
  if (nm == 1) {
    EquilibrationMaterial& m = mats[0];
    const std::span<EosState> st(s.states.data(), n);
    evaluate(m, m.rho_micro, m.temp, nullptr, st);
    for (std::size_t i = 0; i < n; ++i) {
      press[i] = st[i].p;
      m.vol_frac[i] = 1.0;
      m.c2[i] = st[i].c2;
    }
    return result;
  }

  if (s.rho.size() < n * nm) {
    s.rho.resize(n * nm);
    s.temp.resize(n * nm);
  }
  if (s.press.size() < n) {
    s.press.resize(n);
    s.done.resize(n);
  }
  for (EquilibrationMaterial& m : mats)
    for (std::size_t i = 0; i < n; ++i) m.vol_frac[i] = m.rho_CC[i] / m.rho_micro[i];

  // Only the cells still iterating are evaluated (gathered into contiguous
  // arrays when some have converged): a converged cell's p, rho_m and theta_m
  // are final, and re-evaluating it (as an all-cells loop would) gives the
  // same values, so the result does not depend on the batching.
  s.active.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.active[i] = i;
  int it = 0;
  for (; it < max_iterations && !s.active.empty(); ++it) {
    const std::size_t na = s.active.size();
    const bool all = na == n;  // the active cells are 0..n-1: no gather
    for (std::size_t k = 0; k < nm; ++k) {
      const EquilibrationMaterial& m = mats[k];
      const std::span<EosState> st(s.states.data() + k * n, na);
      if (all) {
        evaluate(m, m.rho_micro, m.temp, nullptr, st);
        continue;
      }
      double* r = s.rho.data() + k * n;
      double* T = s.temp.data() + k * n;
      for (std::size_t a = 0; a < na; ++a) {
        r[a] = m.rho_micro[s.active[a]];
        T[a] = m.temp[s.active[a]];
      }
      evaluate(m, {r, na}, {T, na}, s.active.data(), st);
    }
    for (std::size_t a = 0; a < na; ++a) {
      const std::size_t i = s.active[a];
      double A = 0, B = 0, C = 0;
      for (std::size_t k = 0; k < nm; ++k) {
        const EosState& st = s.states[k * n + a];
        const double theta = mats[k].vol_frac[i];
        const double Q = press[i] - st.p;
        // 1/y = theta^2 / (dp/drho rho_CC) = rho_CC / (rho^2 dp/drho) -> 0 with
        // rho_CC: a material with no mass in the cell (theta = 0) has no
        // share (0/0 otherwise: NaN, and the cell never converged).
        const double inv_y = mats[k].rho_CC[i] > 0.0 ? theta * theta / (st.dp_drho * mats[k].rho_CC[i]) : 0.0;
        A += theta;
        B += Q * inv_y;
        C += inv_y;
      }
      double dp = (A - 1.0 - B) / C;
      if (!(press[i] + dp > 0.0)) dp = -0.5 * press[i];
      press[i] += dp;
      s.press[a] = press[i];
      // Convergence is judged on the step just taken; theta is refreshed below.
      // The step is small enough when |dp| <= tol p, or when it changes
      // sum theta (by C dp, C = -d sum theta/dp) by no more than the round-off
      // of that sum (4 nm ulp): when every material is stiff (a cell filled by
      // solids with a trace of gas: C p ~ 1e-6) the pressure is resolved only
      // to eps/C ~ 1e-10 p and Newton cycles between neighbouring values at
      // that distance (guni2dRT.ups at step 0).
      const double resolution = 4.0 * double(nm) * std::numeric_limits<double>::epsilon();
      s.done[a] = (std::abs(dp) <= tol * press[i] || std::abs(dp) * C <= resolution) && std::abs(A - 1.0) <= tol;
    }
    for (std::size_t k = 0; k < nm; ++k) {
      EquilibrationMaterial& m = mats[k];
      if (all) {
        density(m, press, m.temp, nullptr, m.rho_micro);
        for (std::size_t i = 0; i < n; ++i) m.vol_frac[i] = m.rho_CC[i] / m.rho_micro[i];
        continue;
      }
      double* r = s.rho.data() + k * n;
      double* T = s.temp.data() + k * n;
      for (std::size_t a = 0; a < na; ++a) T[a] = m.temp[s.active[a]];
      density(m, {s.press.data(), na}, {T, na}, s.active.data(), {r, na});
      for (std::size_t a = 0; a < na; ++a) {
        const std::size_t i = s.active[a];
        m.rho_micro[i] = r[a];
        m.vol_frac[i] = m.rho_CC[i] / r[a];
      }
    }
    std::size_t kept = 0;
    for (std::size_t a = 0; a < na; ++a)
      if (!s.done[a]) s.active[kept++] = s.active[a];
    s.active.resize(kept);
  }
  result.iterations = it;
  // Cells where Newton stalled: Uintah's bisection fallback (bisect_cell_pressure).
  for (const std::size_t i : s.active)
    if (!bisect_cell_pressure(mats, i, press[i], tol)) {
      result.converged = false;
      result.failed_cell = static_cast<long long>(i);
      break;
    }
  for (std::size_t k = 0; k < nm; ++k) {
    const std::span<EosState> st(s.states.data() + k * n, n);
    evaluate(mats[k], mats[k].rho_micro, mats[k].temp, nullptr, st);
    for (std::size_t i = 0; i < n; ++i) mats[k].c2[i] = st[i].c2;
  }
  return result;
}

}  // namespace tephra
