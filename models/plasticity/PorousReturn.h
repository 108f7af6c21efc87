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
// A flow law with an internal stress (MTS, FlowStressModel::internal_stress_rate) evolves it
// with the return as the von Mises returns do: σ_e = σ_e,n + θ(σ_e,n; ε̇_p, T) Δε_p
// (σ_e,n = state.sigma_e), inside the residuals (the Jacobian's differences see it).
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
};

struct PorousReturnResult {
  double q = 0.0, I1 = 0.0;   // returned invariants
  double delta_lambda = 0.0;  // Δλ
  double delta_eps_p = 0.0;   // Δε_p
  double sigma_y = 0.0;       // σ_y at the returned state
  double hardening = 0.0;     // ∂σ_y/∂ε_p at the returned state
  double sigma_e = 0.0;       // MTS structure stress at the returned state (state.sigma_e otherwise)
  double f = 0.0;             // yield function at the returned state
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();        // (I1/3) I + sqrt(2/3) q n̂
  Eigen::Matrix3d plastic_strain = Eigen::Matrix3d::Zero();  // Δε^p
  int iterations = 0;
  bool converged = false;
};

// The yield function at a stress of invariants (q, I1) along n̂ (σ_y at the state `s`).
double yield_at(const YieldCondition& y, double q, double I1, const Eigen::Matrix3d& n_hat, double sigma_y,
                double porosity);

PorousReturnResult porous_return(const YieldCondition& yield, const FlowStressModel& flow,
                                 const PorousReturnInput& in);

// A unit deviator along s (a fixed one, diag(1, -1, 0)/sqrt(2), when s = 0).
Eigen::Matrix3d unit_deviator(const Eigen::Matrix3d& s);

}  // namespace tephra
