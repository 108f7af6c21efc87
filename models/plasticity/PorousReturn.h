#pragma once
// Backward-Euler return of a pressure-dependent yield condition f(q, I1; σ_y, φ)
// (Gurson-Tvergaard-Needleman, Rousselier; von Mises too) with associated flow,
// in the two invariants of the stress (the J2-I1 return of VT §18.5.2 / §18.7,
// Aravas' two-invariant form): q = sqrt(3/2)|s|, I1 = tr σ, the deviator stays
// along the unit trial direction n̂ (f depends on s through q only):
//   σ = (I1/3) I + sqrt(2/3) q n̂,   ∂f/∂σ = f_q sqrt(3/2) n̂ + f_I1 I,
//   Δε^p = Δλ ∂f/∂σ:  dev Δε^p = Δλ f_q sqrt(3/2) n̂,  tr Δε^p = 3 Δλ f_I1.
// Unknowns (q, I1, Δλ, Δε_p), residuals (hypo-elastic trial, moduli K, μ):
//   R1 = q - q_tr + 3 μ Δλ f_q
//   R2 = I1 - I1_tr + 9 K Δλ f_I1
//   R3 = f(q, I1; σ_y(ε_p,n + Δε_p, Δε_p/Δt, T), φ)
//   R4 = (1 - φ) σ_y Δε_p - σ : Δε^p = (1 - φ) σ_y Δε_p - Δλ (f_q q + f_I1 I1)
// (R4: equivalent plastic work, VT 17.156 / 18.107; with φ = 0 and von Mises Δε_p = Δλ).
// f_q and f_I1 come from the yield condition's gradient (YieldCondition.h):
// f_q = (∂f/∂σ : n̂)/sqrt(3/2), f_I1 = tr(∂f/∂σ)/3. Newton on the 4x4 system with a
// forward-difference Jacobian and backtracking; φ and T are held at their t_n values
// (porosity and temperature are updated after the return, as VT Algorithm 1 does).
// A flow law with an internal stress (MTS, FlowStressModel::evolve_internal_stress) evolves it
// with the return as the von Mises returns do: σ_e(Δε_p) = dσ_e/dε_p = θ(σ_e; ε̇_p, T) integrated
// from σ_e,n = state.sigma_e over the increment, inside the residuals (the Jacobian's differences see it).
//
// Kinematic hardening (VT §18.7.1, eqs. 18.64-18.70): the yield is evaluated on the shifted
// stress ξ = σ - β, the flow is Δε^p = Δλ ∂f/∂ξ (the whole gradient, with its trace, as
// eq. 18.64's h^β = (2/3) H M of eq. 12.11 uses the flow direction M), and the backstress is
// the backward Euler of VT 11.2/11.3 (KinematicHardeningModel::backstress_after):
//   β = a (β_n + (2/3) H_lin Δε^p),  a = 1/(1 + H_rec |Δε^p|),  |Δε^p| = Δλ sqrt(3/2 f_q² + 3 f_I1²).
// Then ξ = σ_trial - C^e:Δε^p - β, so with q, I1 now the invariants of ξ and
//   ξ* = s_trial - a dev β_n,  q* = sqrt(3/2)|ξ*|,  I1* = I1_tr - a tr β_n,
//   R1 = q - q* + (3 μ + a H_lin) Δλ f_q,  R2 = I1 - I1* + (9 K + 2 a H_lin) Δλ f_I1,
// the deviator of ξ stays along n̂ = ξ*/|ξ*| (collinear with dev Δε^p), R3 = f(ξ), and R4 with
// ξ : Δε^p (Gurson's matrix work, the J2 kinematic return's ξ:Δε^p = σ_y Δε_p). With β_n = 0 and
// H_lin = H_rec = 0 these are the residuals above; at φ = 0 (Gurson = von Mises, f_I1 = 0) they
// are the J2 kinematic return of ElasticPlastic (VT 18.52 with a(Δγ)).
#include <Eigen/Core>

#include "models/plasticity/FlowStressModel.h"
#include "models/plasticity/PlasticState.h"
#include "models/plasticity/YieldCondition.h"

namespace tephra {

struct PorousReturnInput {
  double q_trial = 0.0;   // sqrt(3/2)|s_trial| [Pa]
  double I1_trial = 0.0;  // tr σ_trial [Pa]
  Eigen::Matrix3d n_hat = Eigen::Matrix3d::Zero();  // unit trial deviator direction
  double K = 0.0, mu = 0.0;  // bulk and shear moduli [Pa]
  double dt = 0.0;           // step [s]
  double tolerance = 1e-10;  // relative tolerance of the residuals
  PlasticState state;        // at t_n (eps_p, T, porosity, ...)
  // Kinematic hardening (header): the backstress at t_n and the moduli of
  // KinematicHardeningModel (linear_modulus, recovery_modulus); all 0 without it.
  Eigen::Matrix3d beta_n = Eigen::Matrix3d::Zero();
  double H_lin = 0.0, H_rec = 0.0;
};

struct PorousReturnResult {
  double q = 0.0, I1 = 0.0;   // returned invariants (of ξ = σ - β with a backstress)
  double delta_lambda = 0.0;  // Δλ
  double delta_eps_p = 0.0;   // Δε_p
  double sigma_y = 0.0;       // σ_y at the returned state
  double hardening = 0.0;     // ∂σ_y/∂ε_p at the returned state
  double sigma_e = 0.0;       // MTS structure stress at the returned state (state.sigma_e otherwise)
  double f = 0.0;             // yield function at the returned state
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();        // σ = ξ + β, ξ = (I1/3) I + sqrt(2/3) q n̂
  Eigen::Matrix3d xi = Eigen::Matrix3d::Zero();            // ξ (= stress without a backstress)
  Eigen::Matrix3d backstress = Eigen::Matrix3d::Zero();    // β at t_{n+1} (β_n when H_lin = H_rec = 0)
  Eigen::Matrix3d plastic_strain = Eigen::Matrix3d::Zero();  // Δε^p
  int iterations = 0;
  bool converged = false;
};

// The trial shifted stress ξ_trial = σ_trial - β_n of the input: its q, I1 and unit deviator.
struct ShiftedTrial {
  double q = 0.0, I1 = 0.0;
  Eigen::Matrix3d n_hat = Eigen::Matrix3d::Zero();
};
ShiftedTrial shifted_trial(const PorousReturnInput& in);

// The yield function at a stress of invariants (q, I1) along n̂ (σ_y at the state `s`).
double yield_at(const YieldCondition& y, double q, double I1, const Eigen::Matrix3d& n_hat, double sigma_y,
                double porosity);

PorousReturnResult porous_return(const YieldCondition& yield, const FlowStressModel& flow,
                                 const PorousReturnInput& in);

// A unit deviator along s (a fixed one, diag(1, -1, 0)/sqrt(2), when s = 0).
Eigen::Matrix3d unit_deviator(const Eigen::Matrix3d& s);

}  // namespace tephra
