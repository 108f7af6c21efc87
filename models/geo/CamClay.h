#pragma once
// Vaango's Cam-Clay model after Borja et al., type "camclay" (VT ch. 20):
// Borja's hyperelastic p(eps_v^e, eps_s^e), q (BorjaElasticity.h), the
// Cam-Clay yield surface with the consolidation pressure p_c as internal
// variable and the Newton return of VT §20.3 (CamClayReturn.h).
//
// Kinematics (as Vaango's CamClay, made exact under superposed rotations):
// the elastic strain eps^e is carried in the unrotated frame of F = R U; the
// step's unrotated strain increment is the midpoint rule for
// d_hat = sym(U_dot U^{-1}) (as hypo_elastic),
//   de = sym( (U_{n+1} - U_n) ((U_n + U_{n+1})/2)^{-1} ),
// the trial elastic strain eps^e_trial = eps^e_n + de (VT §20.3.1), and the
// Cauchy stress sigma = R_{n+1} [p I + sqrt(2/3) q n] R_{n+1}^T with
// n = e^e/|e^e| (VT §20.3). The return keeps n = n_trial and moves
// (eps_v^e, eps_s^e) only (VT §20.3.1: n_{n+1} : e_trial = |e_trial|).
// When the Newton return does not converge the step is split into 2, 4, ...,
// 1024 equal sub-increments (each an elastic predictor and return); beyond
// that the point is reported inadmissible (NumericalFailure).
//
// Reference state: with eps^e = 0 the stress is sigma_0 = p(0, 0) I with
// p(0, 0) = p0 exp(eps_v0/kt) (a soil is never stress-free in this law).
// Tephra starts the particle at sigma_0 (Vaango starts at sigma = 0 and jumps
// to sigma_0 at the first step). The stored energy reported is W(eps^e) - W(0),
// the elastic energy above the reference state (per reference volume, small
// strain). bulk_modulus()/shear_modulus() are the tangent moduli at the
// reference state: K = -p(0,0)/kt, G = mu(eps_v = 0).
//
// Plastic work per step (per reference volume): J dgamma sigma : df/dsigma =
// J dgamma (p (2p - p_c) + 2 q^2/M^2) = J dgamma p p_c >= 0 on f = 0.
//
// Deck (Vaango names):
//   <equation_of_state type="borja_pressure"> p0 (< 0), alpha (>= 0), kappatilde (> 0), epse_v0
//   <shear_modulus_model type="borja_shear"> mu0 (> 0)   (alpha, p0, kappatilde, epse_v0 from the EOS)
//   <yield_condition type="camclay"> M (> 0)
//   <internal_variable_model type="borja_consolidation_pressure"> pc0 (< 0), lambdatilde (> kappatilde)
//     [kappatilde: older Vaango decks repeat it here; must equal the EOS value]
// History (output labels): p.elasticStrain (unrotated eps^e), p.p_c, p.deltaGamma.
#include <optional>
#include <string>

#include "models/geo/CamClayReturn.h"
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

class CamClay final : public ConstitutiveModel {
 public:
  explicit CamClay(const CamClayParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "camclay"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override;
  double shear_modulus() const override;

  // MPMICE hooks (VT §20.3 Remarks 1-2): gauge pressure relative to the
  // reference state, P = -(p(eps_v = rho0/rho - 1) - p(0)), positive in compression;
  // dP/drho = -p rho0/(kt rho^2); c^2 = (-p/kt)/rho (Vaango: K/rho).
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

  const CamClayParams& params() const { return p_; }

 private:
  CamClayParams p_;
};

}  // namespace tephra
