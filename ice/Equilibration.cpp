#include "ice/Equilibration.h"

#include <cmath>
#include <limits>

#include "models/eos/IdealGas.h"

namespace tephra {

namespace {

// Per-thread work arrays (the equilibration runs once per (j, k) row of
// cells, possibly on several threads): no allocation per call once warm.
struct EquilibrationScratch {
  std::vector<EosState> states;        // nm x n, material-major, by position in the active list
  std::vector<double> rho, temp;       // nm x n: gathered inputs of the active cells
  std::vector<double> press;           // n: pressures of the active cells
  std::vector<std::size_t> active;     // the cells still iterating, ascending
  std::vector<char> done;              // per active cell: converged in this iteration
  std::vector<char> absent;            // nm x n, material-major: material absent from the cell
  std::vector<std::size_t> n_absent;   // nm: absent cells of each material in this row
  std::vector<double> theta_absent;    // n: sum of the absent materials' theta (frozen in the Newton)
  std::vector<std::size_t> pos, cell;  // n: positions in the active list / cell indices of a subset
  std::vector<EosState> sub_states;    // n: states of a subset
  std::vector<double> sub_p;           // n: pressures of a subset
  std::vector<std::size_t> sub_done;   // positions of the cells to check for absent materials
  std::vector<unsigned char> absent_in_cell;  // n: number of absent materials in the cell
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
    s.absent.resize(n * nm);
  }
  if (s.press.size() < n) {
    s.press.resize(n);
    s.done.resize(n);
    s.theta_absent.resize(n);
    s.pos.resize(n);
    s.cell.resize(n);
    s.sub_states.resize(n);
    s.sub_p.resize(n);
    s.absent_in_cell.resize(n);
  }
  s.n_absent.assign(nm, 0);
  for (std::size_t k = 0; k < nm; ++k) {
    EquilibrationMaterial& m = mats[k];
    for (std::size_t i = 0; i < n; ++i) m.vol_frac[i] = m.rho_CC[i] / m.rho_micro[i];
  }

  // Absent materials (header): theta_m <= absent_volume_fraction(tol) at the
  // starting guess. They leave the Newton: their sum theta_absent is a
  // constant of the iteration (target sum_present theta = 1 - theta_absent),
  // and their rho(p, T) is solved only when the present materials have
  // converged; if that moves theta_absent by more than tol/2 the cell
  // iterates on with the new constant, and a material whose theta at that p
  // exceeds the threshold rejoins the Newton in that cell (a bad starting
  // guess: an extra cell's initial sp_vol). A cell keeps at least one material.
  const double theta_max = absent_volume_fraction(tol);
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0.0;
    std::size_t present = 0;
    for (std::size_t k = 0; k < nm; ++k) {
      const bool a = !(mats[k].vol_frac[i] > theta_max);  // NaN counts as present (the Newton reports it)
      s.absent[k * n + i] = a;
      if (a) sum += mats[k].vol_frac[i];
      else ++present;
    }
    if (present == 0) {
      for (std::size_t k = 0; k < nm; ++k) s.absent[k * n + i] = 0;
      sum = 0.0;
    }
    s.theta_absent[i] = sum;
    s.absent_in_cell[i] = static_cast<unsigned char>(present == 0 ? 0 : nm - present);
    for (std::size_t k = 0; k < nm; ++k) s.n_absent[k] += s.absent[k * n + i];
  }

  // Only the cells still iterating are evaluated (gathered into contiguous
  // arrays when some have converged): a converged cell's p, rho_m and theta_m
  // are final, and re-evaluating it (as an all-cells loop would) gives the
  // same values, so the result does not depend on the batching.
  s.active.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.active[i] = i;

  // The positions a in `list` (into the active list) of the cells where
  // material k is present (absent == 0) or absent (absent == 1): s.pos, s.cell.
  auto subset = [&](std::size_t k, const std::size_t* list, std::size_t nl, char absent) {
    std::size_t nb = 0;
    for (std::size_t b = 0; b < nl; ++b) {
      const std::size_t a = list ? list[b] : b;
      const std::size_t i = s.active[a];
      if (s.absent[k * n + i] == absent) {
        s.pos[nb] = a;
        s.cell[nb++] = i;
      }
    }
    return nb;
  };
  // rho_m = rho(p, T_m), theta_m = rho_CC / rho_m for the subset s.pos/s.cell of material k.
  auto solve_subset = [&](std::size_t k, std::size_t nb) {
    EquilibrationMaterial& m = mats[k];
    double* r = s.rho.data() + k * n;
    double* T = s.temp.data() + k * n;
    for (std::size_t b = 0; b < nb; ++b) {
      T[b] = m.temp[s.cell[b]];
      s.sub_p[b] = press[s.cell[b]];
    }
    density(m, {s.sub_p.data(), nb}, {T, nb}, s.cell.data(), {r, nb});
    for (std::size_t b = 0; b < nb; ++b) {
      const std::size_t i = s.cell[b];
      m.rho_micro[i] = r[b];
      m.vol_frac[i] = m.rho_CC[i] / r[b];
    }
  };

  int it = 0;
  for (; it < max_iterations && !s.active.empty(); ++it) {
    const std::size_t na = s.active.size();
    const bool all = na == n;  // the active cells are 0..n-1: no gather
    for (std::size_t k = 0; k < nm; ++k) {
      const EquilibrationMaterial& m = mats[k];
      const std::span<EosState> st(s.states.data() + k * n, na);
      if (s.n_absent[k] > 0) {  // the present cells only, scattered back to their positions
        const std::size_t nb = subset(k, nullptr, na, 0);
        double* r = s.rho.data() + k * n;
        double* T = s.temp.data() + k * n;
        for (std::size_t b = 0; b < nb; ++b) {
          r[b] = m.rho_micro[s.cell[b]];
          T[b] = m.temp[s.cell[b]];
        }
        evaluate(m, {r, nb}, {T, nb}, s.cell.data(), {s.sub_states.data(), nb});
        for (std::size_t b = 0; b < nb; ++b) st[s.pos[b]] = s.sub_states[b];
        continue;
      }
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
      double A = s.theta_absent[i], B = 0, C = 0;
      for (std::size_t k = 0; k < nm; ++k) {
        if (s.absent[k * n + i]) continue;
        const EosState& st = s.states[k * n + a];
        const double theta = mats[k].vol_frac[i];
        const double Q = press[i] - st.p;
        const double inv_y = theta * theta / (st.dp_drho * mats[k].rho_CC[i]);
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
      if (s.n_absent[k] > 0) {
        solve_subset(k, subset(k, nullptr, na, 0));
        continue;
      }
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
    // The cells done with absent materials: their rho(p, T) at the converged
    // p, and the check that theta_absent has not moved by more than tol/2.
    std::size_t nd = 0;
    for (std::size_t a = 0; a < na; ++a)
      if (s.done[a] && s.absent_in_cell[s.active[a]] > 0) s.cell[nd++] = a;  // positions, reused below
    if (nd > 0) {
      std::vector<std::size_t>& list = s.sub_done;
      list.assign(s.cell.begin(), s.cell.begin() + static_cast<std::ptrdiff_t>(nd));
      for (std::size_t k = 0; k < nm; ++k)
        if (s.n_absent[k] > 0) solve_subset(k, subset(k, list.data(), nd, 1));
      for (std::size_t a : list) {
        const std::size_t i = s.active[a];
        double sum = 0.0;
        bool promoted = false;
        for (std::size_t k = 0; k < nm; ++k) {
          if (!s.absent[k * n + i]) continue;
          if (!(mats[k].vol_frac[i] <= theta_max)) {  // no longer a trace at this p: back into the Newton
            s.absent[k * n + i] = 0;
            --s.n_absent[k];
            --s.absent_in_cell[i];
            promoted = true;
            continue;
          }
          sum += mats[k].vol_frac[i];
        }
        if (promoted || std::abs(sum - s.theta_absent[i]) > 0.5 * tol) s.done[a] = 0;
        s.theta_absent[i] = sum;
      }
    }
    std::size_t kept = 0;
    for (std::size_t a = 0; a < na; ++a)
      if (!s.done[a]) s.active[kept++] = s.active[a];
    s.active.resize(kept);
  }
  result.iterations = it;
  if (!s.active.empty()) {
    result.converged = false;
    result.failed_cell = static_cast<long long>(s.active[0]);
  }
  for (std::size_t k = 0; k < nm; ++k) {
    const std::span<EosState> st(s.states.data() + k * n, n);
    evaluate(mats[k], mats[k].rho_micro, mats[k].temp, nullptr, st);
    for (std::size_t i = 0; i < n; ++i) mats[k].c2[i] = st[i].c2;
  }
  return result;
}

}  // namespace tephra
