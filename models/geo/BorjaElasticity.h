#pragma once
// Borja's hyperelastic law of the Cam-Clay model (VT §20.2.1, eq. 7.11-7.12;
// Borja & Tamagnini 1998), in the invariants of the elastic strain eps^e:
//
//   eps_v = tr(eps^e),  e = dev(eps^e),  eps_s = sqrt(2/3) |e|
//   W(eps_v, eps_s) = W_vol + W_dev
//   W_vol = -p0 kt exp(-(eps_v - eps_v0)/kt)                     (kt = kappa-tilde)
//   W_dev = (3/2) mu eps_s^2,  mu = mu0 - alpha p0 exp(-(eps_v - eps_v0)/kt)
//   p = dW/d eps_v = p0 beta exp(-(eps_v - eps_v0)/kt),  beta = 1 + (3/2)(alpha/kt) eps_s^2
//   q = dW/d eps_s = 3 mu eps_s
//   dp/d eps_v = -p/kt,  dp/d eps_s = dq/d eps_v = 3 alpha p0 exp(...) eps_s / kt,
//   dq/d eps_s = 3 mu
//
// Tension positive: p = tr(sigma)/3 is the mean stress, p0 < 0 (Vaango's
// schema: 'negative'), so p < 0 and the bulk modulus K = dp/d eps_v = -p/kt > 0.
// [ERRATUM] VT §20.3.2 writes dq/d eps_v with a minus sign and dq/d eps_s =
// 3 mu0 + 3 p0 alpha exp(...); both contradict q = 3 mu eps_s with the mu
// above (and the symmetry d2W/d eps_v d eps_s): the derivatives here are the
// exact ones (test_model_camclay checks them by finite differences).
#include <Eigen/Core>

namespace tephra {

struct BorjaElasticParams {
  double p0 = 0.0;       // reference mean stress at eps_v = eps_v0, eps_s = 0 [Pa], < 0
  double alpha = 0.0;    // volumetric-deviatoric coupling [-], >= 0
  double kappa = 0.0;    // kappa-tilde, elastic compressibility index [-], > 0
  double eps_v0 = 0.0;   // elastic volumetric strain at p = p0 [-]
  double mu0 = 0.0;      // shear modulus constant [Pa], > 0
};

// p, q and their derivatives at (eps_v, eps_s).
struct BorjaInvariants {
  double p = 0, q = 0, mu = 0;
  double dp_dv = 0, dp_ds = 0, dq_dv = 0, dq_ds = 0;
};

BorjaInvariants borja_invariants(const BorjaElasticParams& b, double eps_v, double eps_s);

// The stored energy W(eps_v, eps_s) [J/m^3].
double borja_energy(const BorjaElasticParams& b, double eps_v, double eps_s);

// Stress of an elastic strain tensor: sigma = p I + sqrt(2/3) q n, n = e/|e|
// (VT §20.3); also returns the invariants.
Eigen::Matrix3d borja_stress(const BorjaElasticParams& b, const Eigen::Matrix3d& eps_e, BorjaInvariants* inv = nullptr);

// The elastic tangent d sigma/d eps^e (VT eq. 20.3-20.7) as a 9x9 matrix on
// row-major vec(eps) (entry (3i+j, 3k+l) = C_ijkl, minor-symmetric):
//   C = c (1 (x) n + n (x) 1) + (K - 2mu/3) 1 (x) 1 + 2 mu I^s,
//   c = sqrt(6) alpha p0 exp(-(eps_v - eps_v0)/kt) eps_s / kt,  K = -p/kt.
// This is eq. 20.7 with q/eps_s = 3 mu, which cancels its n (x) n term
// (2(mu - q/(3 eps_s)) = 0) and turns (2/9) q/eps_s into 2mu/3 and (2/3) q/eps_s
// into 2mu. [ERRATUM] eq. 20.5 carries the sign of dq/d eps_v noted above; with
// the exact sign both cross terms are +c, as eq. 20.7 (symmetric) has them.
Eigen::Matrix<double, 9, 9> borja_elastic_tangent(const BorjaElasticParams& b, const Eigen::Matrix3d& eps_e);

// The MPMICE hooks (VT §20.3 Remarks 1-2), with eps_s = 0 and the small-strain
// identification eps_v = J - 1 = rho0/rho - 1:
//   p(rho) = p0 exp(-(rho0/rho - 1 - eps_v0)/kt)
//   rho(p) = rho0 / [1 + eps_v0 - kt ln(p/p0)]
// [ERRATUM] Remark 2 prints "+ kt ln(p/(p0 beta))"; inverting p(eps_v) gives
// eps_v = eps_v0 - kt ln(p/p0), hence the minus (Vaango's Pressure_Borja has it).
double borja_mean_stress_at_density(const BorjaElasticParams& b, double rho, double rho0);
// Returns +infinity when no J > 0 gives p (compression beyond J -> 0) and 0
// when p >= 0 (a tension the law never reaches: J -> infinity).
double borja_density_at_mean_stress(const BorjaElasticParams& b, double p, double rho0);

}  // namespace tephra
