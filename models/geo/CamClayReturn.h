#pragma once
// The Cam-Clay yield condition and its return algorithm (VT §20.2.2, §20.3.1-20.3.2),
// on the invariants of the elastic strain (BorjaElasticity.h). Tension positive:
// p < 0 and p_c < 0.
//
//   f = (q/M)^2 + p (p - p_c)                                     (VT §20.2.2)
//   p_c,n+1 = p_c,n exp[(eps_v_trial - eps_v,n+1)/(kt - lt)]       (VT §20.3.1; lt = lambda-tilde)
//
// Backward-Euler return with associated flow, three unknowns
// x = (eps_v, eps_s, dgamma) and residuals (VT eq. 20.2)
//   r1 = eps_v - eps_v_trial + dgamma (2p - p_c)
//   r2 = eps_s - eps_s_trial + dgamma 2q/M^2
//   r3 = f
// solved by Newton with the exact Jacobian condensed to one 2x2 solve
// (VT §20.3.2: dx3 = (r3 - C A^-1 r_vs)/(C A^-1 B), dx_vs = -A^-1 r_vs - A^-1 B dx3).
// Tephra scales the unknowns (dgamma |p_c,n|) and r3 (/p_c,n^2) so that all are
// dimensionless, halves the Newton step while the residual norm grows, and stops
// when every scaled residual is below 1e-13.
//
// Identities (inventory oracle 16): f = 0 at (p, q) = (0, 0) and (p_c, 0); the
// critical-state point p = p_c/2, q = M |p| has f = 0 and df/dp = 0.
#include "models/geo/BorjaElasticity.h"

namespace tephra {

struct CamClayParams {
  BorjaElasticParams elastic;
  double M = 0.0;        // slope of the critical-state line [-]
  double lambda = 0.0;   // lambda-tilde, plastic compressibility index [-], > kappa-tilde
  double pc0 = 0.0;      // initial consolidation pressure [Pa], < 0
};

inline double camclay_yield(double M, double p, double q, double pc) { return (q / M) * (q / M) + p * (p - pc); }

// p_c after the step, from the elastic volumetric strains (VT §20.3.1).
double camclay_pc_update(const CamClayParams& c, double pc_n, double eps_v_trial, double eps_v);

struct CamClayReturnResult {
  bool converged = false;
  int iterations = 0;
  double eps_v = 0, eps_s = 0, dgamma = 0, pc = 0;
  BorjaInvariants inv;   // p, q, ... at the returned strains
};

// Returns the trial state (eps_v_trial, eps_s_trial, p_c,n) onto f = 0.
// Precondition: the trial state is outside (f > 0).
CamClayReturnResult camclay_return(const CamClayParams& c, double eps_v_trial, double eps_s_trial, double pc_n);

}  // namespace tephra
