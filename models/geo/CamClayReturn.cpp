#include "models/geo/CamClayReturn.h"

#include <algorithm>
#include <cmath>

namespace tephra {

double camclay_pc_update(const CamClayParams& c, double pc_n, double eps_v_trial, double eps_v) {
  return pc_n * std::exp((eps_v_trial - eps_v) / (c.elastic.kappa - c.lambda));
}

namespace {

struct Residual {
  double r1 = 0, r2 = 0, r3 = 0, pc = 0;
  BorjaInvariants inv;
  double norm() const { return std::max({std::abs(r1), std::abs(r2), std::abs(r3)}); }
};

// Residuals of VT eq. 20.2 at (eps_v, eps_s, g), g = dgamma * s (s = |p_c,n|), r3 scaled by s^2.
Residual residual(const CamClayParams& c, double ev_tr, double es_tr, double pc_n, double s, double ev, double es,
                  double g) {
  Residual r;
  r.inv = borja_invariants(c.elastic, ev, es);
  r.pc = camclay_pc_update(c, pc_n, ev_tr, ev);
  const double dgamma = g / s, M2 = c.M * c.M;
  r.r1 = ev - ev_tr + dgamma * (2.0 * r.inv.p - r.pc);
  r.r2 = es - es_tr + dgamma * 2.0 * r.inv.q / M2;
  r.r3 = camclay_yield(c.M, r.inv.p, r.inv.q, r.pc) / (s * s);
  return r;
}

}  // namespace

CamClayReturnResult camclay_return(const CamClayParams& c, double ev_tr, double es_tr, double pc_n) {
  const double s = std::abs(pc_n), M2 = c.M * c.M;
  const double dpc_dev_factor = 1.0 / (c.lambda - c.elastic.kappa);  // dp_c/d eps_v = p_c/(lt - kt)
  double ev = ev_tr, es = es_tr, g = 0.0;  // start at the trial state, dgamma = 0
  Residual r = residual(c, ev_tr, es_tr, pc_n, s, ev, es, g);
  CamClayReturnResult out;
  const double tol = 1e-13;
  for (int k = 0; k < 80; ++k) {
    out.iterations = k;
    if (r.norm() <= tol) {
      out.converged = true;
      break;
    }
    const BorjaInvariants& v = r.inv;
    const double dgamma = g / s;
    const double dpc = r.pc * dpc_dev_factor;
    const double dfdp = 2.0 * v.p - r.pc, dfdq = 2.0 * v.q / M2;
    // A = d(r1, r2)/d(eps_v, eps_s), B = d(r1, r2)/dg, C = d r3/d(eps_v, eps_s) (VT §20.3.2).
    const double a11 = 1.0 + dgamma * (2.0 * v.dp_dv - dpc), a12 = 2.0 * dgamma * v.dp_ds;
    const double a21 = dgamma * 2.0 * v.dq_dv / M2, a22 = 1.0 + dgamma * 2.0 * v.dq_ds / M2;
    const double b1 = dfdp / s, b2 = dfdq / s;
    const double c1 = (dfdq * v.dq_dv + dfdp * v.dp_dv - v.p * dpc) / (s * s);
    const double c2 = (dfdq * v.dq_ds + dfdp * v.dp_ds) / (s * s);
    const double det = a11 * a22 - a12 * a21;
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) break;
    // A^-1 r_vs and A^-1 B
    const double ar1 = (a22 * r.r1 - a12 * r.r2) / det, ar2 = (-a21 * r.r1 + a11 * r.r2) / det;
    const double ab1 = (a22 * b1 - a12 * b2) / det, ab2 = (-a21 * b1 + a11 * b2) / det;
    const double denom = c1 * ab1 + c2 * ab2;
    if (!(std::abs(denom) > 0.0) || !std::isfinite(denom)) break;
    const double dg = (r.r3 - (c1 * ar1 + c2 * ar2)) / denom;
    const double dev = -ar1 - ab1 * dg, des = -ar2 - ab2 * dg;
    // Damped step: halve while the residual grows or eps_s / dgamma turn negative.
    double step = 1.0;
    Residual trial;
    bool accepted = false;
    for (int h = 0; h < 40; ++h, step *= 0.5) {
      const double ev1 = ev + step * dev, es1 = es + step * des, g1 = g + step * dg;
      if (es1 < 0.0 || g1 < 0.0) continue;
      trial = residual(c, ev_tr, es_tr, pc_n, s, ev1, es1, g1);
      if (std::isfinite(trial.norm()) && trial.norm() < r.norm()) {
        ev = ev1, es = es1, g = g1;
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      out.converged = r.norm() <= 1e3 * tol;  // stalled at round-off
      break;
    }
    r = trial;
  }
  if (!out.converged && r.norm() <= tol) out.converged = true;
  out.eps_v = ev;
  out.eps_s = es;
  out.dgamma = g / s;
  out.pc = r.pc;
  out.inv = r.inv;
  return out;
}

}  // namespace tephra
