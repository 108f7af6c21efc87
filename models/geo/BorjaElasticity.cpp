#include "models/geo/BorjaElasticity.h"

#include <cmath>
#include <limits>

namespace tephra {

BorjaInvariants borja_invariants(const BorjaElasticParams& b, double eps_v, double eps_s) {
  const double E = std::exp(-(eps_v - b.eps_v0) / b.kappa);  // exp(-(eps_v - eps_v0)/kt)
  const double beta = 1.0 + 1.5 * (b.alpha / b.kappa) * eps_s * eps_s;
  BorjaInvariants r;
  r.p = b.p0 * beta * E;
  r.mu = b.mu0 - b.alpha * b.p0 * E;
  r.q = 3.0 * r.mu * eps_s;
  r.dp_dv = -r.p / b.kappa;
  r.dp_ds = 3.0 * b.alpha * b.p0 * E * eps_s / b.kappa;
  r.dq_dv = r.dp_ds;  // d2W/(d eps_v d eps_s): d mu/d eps_v = alpha p0 E / kt
  r.dq_ds = 3.0 * r.mu;
  return r;
}

double borja_energy(const BorjaElasticParams& b, double eps_v, double eps_s) {
  const double E = std::exp(-(eps_v - b.eps_v0) / b.kappa);
  return -b.p0 * b.kappa * E + 1.5 * (b.mu0 - b.alpha * b.p0 * E) * eps_s * eps_s;
}

Eigen::Matrix3d borja_stress(const BorjaElasticParams& b, const Eigen::Matrix3d& eps_e, BorjaInvariants* inv) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double ev = eps_e.trace();
  const Eigen::Matrix3d e = eps_e - (ev / 3.0) * I;
  const double norm_e = e.norm();
  const double es = std::sqrt(2.0 / 3.0) * norm_e;
  const BorjaInvariants r = borja_invariants(b, ev, es);
  if (inv) *inv = r;
  // sqrt(2/3) q n with n = e/|e|, q = 3 mu eps_s: = 2 mu e (no division at e = 0).
  return r.p * I + (2.0 * r.mu) * e;
}

Eigen::Matrix<double, 9, 9> borja_elastic_tangent(const BorjaElasticParams& b, const Eigen::Matrix3d& eps_e) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double ev = eps_e.trace();
  const Eigen::Matrix3d e = eps_e - (ev / 3.0) * I;
  const double norm_e = e.norm(), es = std::sqrt(2.0 / 3.0) * norm_e;
  const BorjaInvariants r = borja_invariants(b, ev, es);
  const Eigen::Matrix3d n = norm_e > 0.0 ? Eigen::Matrix3d(e / norm_e) : Eigen::Matrix3d::Zero();
  const double E = std::exp(-(ev - b.eps_v0) / b.kappa);
  const double c = std::sqrt(6.0) * b.alpha * b.p0 * E * es / b.kappa;
  const double K = -r.p / b.kappa;
  Eigen::Matrix<double, 9, 9> C;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          C(3 * i + j, 3 * k + l) = c * (I(i, j) * n(k, l) + n(i, j) * I(k, l)) +
                                    (K - 2.0 * r.mu / 3.0) * I(i, j) * I(k, l) +
                                    r.mu * (I(i, k) * I(j, l) + I(i, l) * I(j, k));
  return C;
}

double borja_mean_stress_at_density(const BorjaElasticParams& b, double rho, double rho0) {
  return borja_invariants(b, rho0 / rho - 1.0, 0.0).p;
}

double borja_density_at_mean_stress(const BorjaElasticParams& b, double p, double rho0) {
  if (!(p < 0.0)) return 0.0;
  const double J = 1.0 + b.eps_v0 - b.kappa * std::log(p / b.p0);
  if (!(J > 0.0)) return std::numeric_limits<double>::infinity();
  return rho0 / J;
}

}  // namespace tephra
