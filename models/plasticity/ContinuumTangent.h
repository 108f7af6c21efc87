#pragma once
// The continuum elasto-plastic tangent of a pressure-dependent (J2-I1) yield condition,
// VT §18.6.2 (and §18.6 eq. 18.26-18.29 for the plastic modulus), with associated flow:
//   σ̇ = C^e : (d - γ̇ N),  C^e = (κ - 2μ/3) 1⊗1 + 2μ I^4s,  N = ∂f/∂σ,
//   consistency ḟ = N : σ̇ + (∂f/∂ε_p) ε̇_p = 0,  ε̇_p = γ̇ h^α,
//   γ̇ = (N : C^e : d)/(N : C^e : N + H_p),  H_p = -(∂f/∂ε_p) h^α,
//   C^ep = C^e - (C^e : N) ⊗ (N : C^e)/(N : C^e : N + H_p).
// (The manual's 𝔻^e form of §18.6.2 is this expression with M̂ = N/|N|; the scale of N cancels.)
// For the metal yield conditions of VT ch. 8 (f(ξ, σ_y, φ)), ∂f/∂ε_p = (∂f/∂σ_y) dσ_y/dε_p and
// ε_p follows from the equivalent plastic work (VT 17.156 / 18.107; the porous return's R4):
//   (1 - φ) σ_y ε̇_p = σ : d^p  =>  h^α = σ : N/((1 - φ) σ_y).
// The porosity is held fixed (h^φ = 0), as in the two-invariant return (PorousReturn.h) whose
// h -> 0 response this tangent is (checked by finite differences in test_plasticity_tangent).
// For von Mises this is j2_elastoplastic_tangent (StabilityCheck.h): C^e - 6μ²/(3μ + H) n̂⊗n̂.
#include <Eigen/Core>

#include "models/plasticity/StabilityCheck.h"
#include "models/plasticity/YieldCondition.h"

namespace tephra {

// C^ep for the flow direction N and the plastic modulus H_p (may be < 0: softening).
Tangent4 j2i1_elastoplastic_tangent(double K, double mu, const Eigen::Matrix3d& N, double H_p);

// C^ep of `yield` at the stress `sigma` (on the surface f(σ, σ_y, φ) = 0), with the hardening
// slope H_y = dσ_y/dε_p; ∂f/∂σ_y by a central difference of the yield function (relative step
// 1e-6: the condition's interface gives f and ∂f/∂σ only).
// With kinematic hardening `sigma` is the shifted stress ξ = σ - β and the plastic modulus gains
// the backstress term N : h^β, h^β = (2/3) H_lin N - H_rec β |N| (VT 11.3 with d^p = γ̇ N, eq. 18.64):
// ḟ = N : (σ̇ - β̇) + ... = 0.
Tangent4 yield_continuum_tangent(const YieldCondition& yield, const Eigen::Matrix3d& sigma, double sigma_y, double H_y,
                                 double porosity, double K, double mu, const KinematicHardeningModel* kin = nullptr,
                                 const Eigen::Matrix3d& beta = Eigen::Matrix3d::Zero());

}  // namespace tephra
