#pragma once
// Material-stability (loss of uniqueness / ellipticity) checks of the metal
// models, VT ch. 16 (Vaango's <stability_check type="...">):
//   none            never unstable;
//   drucker         Drucker's stability postulate in Vaango's rate form: unstable when
//                     (C : D) : D <= 0,
//                   C the continuum elasto-plastic tangent at the returned state and D the
//                   step's TOTAL rate of deformation (Vaango: DruckerCheck::checkStability
//                   contracts Cep with deformRate, stable only if the product is > 0; called by
//                   ElasticPlastic(HP)::computeStressTensor only after a plastic step, with the
//                   updated stress and the rate of deformation DD/tensorD, and a failed check sets
//                   pLocalized; bbanerjee/ParSim, Vaango/.../PlasticityModels/DruckerCheck.cc).
//                   VT eq. 16.2 prints σ̇ : d^p <= 0 with σ̇ the stress rate; Tephra's earlier
//                   literal reading (σ̇ = the step's (τ - τ_n)/Δt) fired at first yield in
//                   explicit runs whenever the flow stress fell within a step, and is gone.
//                   For the J2 tangent below, with D = a n̂ + D'_⊥ + (tr D/3) I:
//                     (C : D) : D = K (tr D)² + 2μ |D'_⊥|² + 2μ a² H/(3μ + H),
//                   so hardening (H > 0) is always stable, softening is unstable when D'
//                   lies close enough to the flow direction n̂ (test_plasticity_stability).
//                   D = 0 in a plastic step gives 0: unstable, as in Vaango (<= 0).
//   acoustic        loss of ellipticity (16.28): unstable when det A(n) <= 0 for some unit n,
//                   A_jk(n) = n_i C_ijkl n_l (the acoustic tensor of the tangent C); searched
//                   over a hemisphere grid, then refined around the grid minimum;
//   becker          Becker's simplification (16.29-16.41): C rotated into the principal-stress
//                   frame, n in the σ1-σ3 plane, det Ã(α = n3/n1) = Ã22 q(β), β = α² with the
//                   CORRECTED quadratic (inventory erratum 5; det Ã = Ã22(Ã11Ã33 - Ã13Ã31)):
//                     q(β) = C3113 C3333 β² + (C1111 C3333 + C3113 C1331
//                            - (C1133 + C3131)(C3311 + C1313)) β + C1111 C1331;
//                   unstable when q has two real non-negative roots β (four real n3/n1, 16.41);
//                   two real roots (one β < 0) count as stable, as the manual says;
//   drucker_becker  unstable when either check says so (Vaango's DruckerBeckerCheck: the
//                   same (C : D) : D <= 0 first, then Becker).
// C is the continuum (elasto-plastic) tangent σ̇ = C : d, stored as a full 3x3x3x3 array.
// Vaango's von Mises tangent (VonMisesYield::computeElasPlasTangentModulus) differs from the
// consistent one used here: with f = σ_eq² - σ_y² it takes ∂f/∂ε_p = H (not -2σ_y H), so its
// denominator is 12μσ_y² - 2σ_y H instead of 4σ_y²(3μ + H): in practice the perfectly plastic
// tangent. Tephra uses the consistent J2 tangent (VT 18.31-18.39) and the J2-I1 tangent of
// ContinuumTangent.h for porous yields.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/plasticity/SubModelTable.h"

namespace tephra {

// A fourth-order tensor C_ijkl (row-major [i][j][k][l]).
struct Tangent4 {
  std::array<double, 81> c{};
  double& operator()(int i, int j, int k, int l) { return c[27 * i + 9 * j + 3 * k + l]; }
  double operator()(int i, int j, int k, int l) const { return c[27 * i + 9 * j + 3 * k + l]; }
  // C : d
  Eigen::Matrix3d contract(const Eigen::Matrix3d& d) const;
  // The tensor in a frame with base vectors the columns of Q: C'_ijkl = Q_ai Q_bj Q_ck Q_dl C_abcd.
  Tangent4 rotated(const Eigen::Matrix3d& Q) const;
};

// Isotropic elasticity, C = λ I⊗I + 2μ I_sym.
Tangent4 isotropic_tangent(double lambda, double mu);
// The J2 continuum elasto-plastic tangent (VT 18.31-18.39 specialised to von Mises,
// r = sqrt(3/2) n̂, ε̇_p = γ̇): C^ep = K I⊗I + 2μ (I_dev - 3μ/(3μ + H) n̂⊗n̂),
// n̂ = s/|s| the unit deviatoric flow direction, H = dσ_y/dε_p (may be < 0: softening).
Tangent4 j2_elastoplastic_tangent(double K, double mu, double H, const Eigen::Matrix3d& n_hat);

// The acoustic tensor A_jk(n) = n_i C_ijkl n_l.
Eigen::Matrix3d acoustic_tensor(const Tangent4& C, const Eigen::Vector3d& n);
// min over unit n of det A(n) (grid search + local refinement); n_min receives the minimiser.
double min_acoustic_determinant(const Tangent4& C, Eigen::Vector3d* n_min = nullptr);

// Becker's corrected quadratic q(β) = a1 β² + a2 β + a3 for C in the principal-stress frame.
struct BeckerQuadratic {
  double a1 = 0, a2 = 0, a3 = 0;
};
BeckerQuadratic becker_quadratic(const Tangent4& C_principal);
// True when q has two real roots β >= 0 (four real n3/n1, 16.41).
bool becker_unstable(const BeckerQuadratic& q);

struct StabilityInput {
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();            // Cauchy stress (principal frame from it)
  Eigen::Matrix3d deformation_rate = Eigen::Matrix3d::Zero();  // D, the total rate of deformation
  Tangent4 tangent;                                            // C (stress, D and C in one frame)
};

// Drucker's product (C : D) : D (Vaango's DruckerCheck); unstable when <= 0.
double drucker_product(const Tangent4& C, const Eigen::Matrix3d& D);

class StabilityCheck {
 public:
  virtual ~StabilityCheck() = default;
  virtual std::string type() const = 0;
  // True when the state is unstable (the point fails). Called after a plastic step only.
  virtual bool unstable(const StabilityInput& in) const = 0;
};

const std::vector<SubModelEntry<StabilityCheck>>& stability_checks();
std::unique_ptr<StabilityCheck> create_stability_check(const std::string& key, const ModelParameters& p,
                                                       const SubModelContext& ctx = {});

}  // namespace tephra
