// Two-invariant backward-Euler return (PorousReturn.h).
#include "models/plasticity/PorousReturn.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace tephra {

namespace {
const double kS32 = std::sqrt(1.5), kS23 = std::sqrt(2.0 / 3.0);

Eigen::Matrix3d stress_of(double q, double I1, const Eigen::Matrix3d& n) {
  return (I1 / 3.0) * Eigen::Matrix3d::Identity() + kS23 * q * n;
}

struct Eval {
  double f, fq, fI1, sy, H, sigma_e;
};

Eval evaluate(const YieldCondition& y, const FlowStressModel& flow, const PorousReturnInput& in,
              const Eigen::Matrix3d& n_hat, double q, double I1, double dep) {
  PlasticState s = in.state;
  s.eps_p = in.state.eps_p + dep;
  s.eps_p_rate = in.dt > 0.0 ? dep / in.dt : 0.0;
  // MTS (PorousReturn.h): sigma_e(Delta eps_p) by eq. 10.19 over the increment; unchanged for the other laws.
  s.sigma_e = flow.evolve_internal_stress(s, dep);
  const FlowStress fs = flow.evaluate(s);
  const Eigen::Matrix3d sig = stress_of(q, I1, n_hat);
  const double phi = in.state.porosity;
  const Eigen::Matrix3d g = y.gradient(sig, fs.sigma_y, phi);
  return {y.value(sig, fs.sigma_y, phi), g.cwiseProduct(n_hat).sum() / kS32, g.trace() / 3.0, fs.sigma_y,
          fs.d_eps_p, s.sigma_e};
}

bool has_backstress(const PorousReturnInput& in) {
  return in.H_lin != 0.0 || in.H_rec != 0.0 || !in.beta_n.isZero(0.0);
}

// The backstress part of the residuals (header): a(Δλ), n̂ = ξ*/|ξ*|, q*, I1*.
struct Shift {
  double a = 1.0;
  Eigen::Matrix3d n_hat;
  double q_star = 0.0, I1_star = 0.0;
};

Shift shift_at(const PorousReturnInput& in, double dl, double fq, double fI1) {
  Shift k;
  if (!has_backstress(in)) {
    k.n_hat = in.n_hat;
    k.q_star = in.q_trial;
    k.I1_star = in.I1_trial;
    return k;
  }
  k.a = 1.0 / (1.0 + in.H_rec * dl * std::sqrt(1.5 * fq * fq + 3.0 * fI1 * fI1));
  const double tr_b = in.beta_n.trace();
  const Eigen::Matrix3d xs =
      kS23 * in.q_trial * in.n_hat - k.a * (in.beta_n - tr_b / 3.0 * Eigen::Matrix3d::Identity());
  k.n_hat = unit_deviator(xs);
  k.q_star = kS32 * (xs - xs.trace() / 3.0 * Eigen::Matrix3d::Identity()).norm();
  k.I1_star = in.I1_trial - k.a * tr_b;
  return k;
}
}  // namespace

ShiftedTrial shifted_trial(const PorousReturnInput& in) {
  const Shift k = shift_at(in, 0.0, 0.0, 0.0);
  return {k.q_star, k.I1_star, k.n_hat};
}

Eigen::Matrix3d unit_deviator(const Eigen::Matrix3d& s) {
  const Eigen::Matrix3d d = s - s.trace() / 3.0 * Eigen::Matrix3d::Identity();
  const double n = d.norm();
  if (n > 0.0) return d / n;
  Eigen::Matrix3d e = Eigen::Matrix3d::Zero();
  e(0, 0) = 1.0 / std::sqrt(2.0);
  e(1, 1) = -1.0 / std::sqrt(2.0);
  return e;
}

double yield_at(const YieldCondition& y, double q, double I1, const Eigen::Matrix3d& n_hat, double sigma_y,
                double porosity) {
  return y.value(stress_of(q, I1, n_hat), sigma_y, porosity);
}

PorousReturnResult porous_return(const YieldCondition& yield, const FlowStressModel& flow,
                                 const PorousReturnInput& in) {
  const double phi = in.state.porosity;
  const ShiftedTrial t0 = shifted_trial(in);
  const Eigen::Matrix3d& n0 = t0.n_hat;  // f, f_q, f_I1 of an isotropic yield do not depend on it
  const double S = std::max({in.q_trial, std::abs(in.I1_trial), t0.q, std::abs(t0.I1), 1.0});
  using V4 = Eigen::Vector4d;
  auto residual = [&](const V4& u, Eval* out) {
    const Eval e = evaluate(yield, flow, in, n0, u(0), u(1), u(3));
    if (out) *out = e;
    const Shift k = shift_at(in, u(2), e.fq, e.fI1);
    V4 r;
    r(0) = u(0) - k.q_star + (3.0 * in.mu + k.a * in.H_lin) * u(2) * e.fq;
    r(1) = u(1) - k.I1_star + (9.0 * in.K + 2.0 * k.a * in.H_lin) * u(2) * e.fI1;
    r(2) = e.f;
    r(3) = (1.0 - phi) * e.sy * u(3) - u(2) * (e.fq * u(0) + e.fI1 * u(1));
    return r;
  };
  // Initial guess: the linearisation at the trial state, isotropic hardening ignored.
  const Eval e0 = evaluate(yield, flow, in, n0, t0.q, t0.I1, 0.0);
  const double Gq = 3.0 * in.mu + in.H_lin, GI = 9.0 * in.K + 2.0 * in.H_lin;
  const double denom = Gq * e0.fq * e0.fq + GI * e0.fI1 * e0.fI1;
  const double dl0 = denom > 0.0 ? std::max(0.0, e0.f / denom) : 0.0;
  V4 u(std::max(0.0, t0.q - Gq * dl0 * e0.fq), t0.I1 - GI * dl0 * e0.fI1, dl0, 0.0);
  u(3) = e0.sy > 0.0 ? dl0 * (e0.fq * u(0) + e0.fI1 * u(1)) / ((1.0 - phi) * e0.sy) : 0.0;
  const V4 scale(S, S, std::max(std::abs(dl0), 1e-300), std::max(std::abs(u(3)), 1e-8));
  // Convergence norm: R1, R2 as stresses, R3 as f/|∂f/∂σ| (the first-order stress distance to
  // the surface; |∂f/∂σ|² = 3/2 f_q² + 3 f_I1²), R4/σ_y (a strain) times S.
  auto norm = [&](const V4& r, const Eval& e) {
    const double gn = std::sqrt(1.5 * e.fq * e.fq + 3.0 * e.fI1 * e.fI1);
    const double fs = gn > 0.0 ? std::abs(r(2)) / gn : std::abs(r(2));
    const double w = e.sy > 0.0 ? std::abs(r(3)) / e.sy * S : std::abs(r(3));
    return std::max({std::abs(r(0)), std::abs(r(1)), fs, w}) / S;
  };
  PorousReturnResult res;
  Eval e;
  V4 r = residual(u, &e);
  double rn = norm(r, e);
  for (int it = 1; it <= 100; ++it) {
    res.iterations = it;
    if (rn <= in.tolerance) {
      res.converged = true;
      break;
    }
    Eigen::Matrix4d Jac;
    for (int j = 0; j < 4; ++j) {
      V4 up = u;
      const double h = 1e-7 * std::max(std::abs(u(j)), scale(j));
      up(j) += h;
      Jac.col(j) = (residual(up, nullptr) - r) / h;
    }
    // Row and column equilibration (the unknowns and residuals differ by ~17 orders of
    // magnitude): rows by the convergence measures, columns by the variable scales.
    const double gn = std::sqrt(1.5 * e.fq * e.fq + 3.0 * e.fI1 * e.fI1);
    const V4 row(1.0 / S, 1.0 / S, gn > 0.0 ? 1.0 / (gn * S) : 1.0 / S, e.sy > 0.0 ? 1.0 / e.sy : 1.0 / S);
    V4 col;
    for (int j = 0; j < 4; ++j) col(j) = std::max(std::abs(u(j)), scale(j));
    const Eigen::Matrix4d Js = row.asDiagonal() * Jac * col.asDiagonal();
    const V4 du = col.cwiseProduct(Js.partialPivLu().solve(-row.cwiseProduct(r)));
    if (!du.allFinite()) break;
    double a = 1.0;
    for (int ls = 0; ls < 30; ++ls, a *= 0.5) {
      V4 un = u + a * du;
      un(0) = std::max(un(0), 0.0);
      un(2) = std::max(un(2), 0.0);
      un(3) = std::max(un(3), 0.0);
      Eval en;
      const V4 rn_vec = residual(un, &en);
      const double nn = norm(rn_vec, en);
      // Non-monotone acceptance: a full step may raise the norm (the cosh of Gurson makes the
      // stress-distance measure flat far outside the surface, where Newton moves I1 by ~2σy/q2).
      if (std::isfinite(nn) && (nn < rn || (ls == 0 && nn < 4.0 * rn) || ls == 29)) {
        u = un, r = rn_vec, e = en, rn = nn;
        break;
      }
    }
  }
  if (!res.converged && rn <= in.tolerance) res.converged = true;
  res.q = u(0);
  res.I1 = u(1);
  res.delta_lambda = u(2);
  res.delta_eps_p = u(3);
  res.sigma_y = e.sy;
  res.hardening = e.H;
  res.sigma_e = e.sigma_e;
  res.f = e.f;
  const Shift k = shift_at(in, u(2), e.fq, e.fI1);
  res.xi = stress_of(u(0), u(1), k.n_hat);
  res.plastic_strain = u(2) * (e.fq * kS32 * k.n_hat + e.fI1 * Eigen::Matrix3d::Identity());
  // β = a (β_n + (2/3) H_lin Δε^p) (KinematicHardeningModel::backstress_after); 0 without one.
  res.backstress = has_backstress(in) ? Eigen::Matrix3d(k.a * (in.beta_n + 2.0 / 3.0 * in.H_lin * res.plastic_strain))
                                      : Eigen::Matrix3d::Zero();
  res.stress = res.xi + res.backstress;
  return res;
}

}  // namespace tephra
