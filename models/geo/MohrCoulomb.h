#pragma once
// Vaango's Mohr-Coulomb model, type "mohr_coulomb" (VT ch. 19), the classic
// variant: linear isotropic hypoelasticity (eq. 19.1-19.3) made objective with
// the Green-Naghdi rotation (§19.1: unrotate with the decomposition at the
// start of the step, rotate back with the one at its end; strain increment as
// hypo_elastic: de = sym((U_{n+1} - U_n)((U_n + U_{n+1})/2)^{-1})), the classic
// yield surface (eq. 19.5) with perfect plasticity and a dilation angle
// (eq. 19.28-19.29), returned in principal stresses (MohrCoulombReturn.h).
//
//   tau_n = R_n^T sigma_n R_n,  tau_tr = tau_n + (K - 2G/3) tr(de) I + 2G de
//   tau_tr = V diag(s_tr) V^T (s_tr ordered) -> return -> tau = V diag(s) V^T
//   sigma_{n+1} = R_{n+1} tau R_{n+1}^T
// Plastic work per reference volume: J tau_{n+1} : de_p with the step's plastic
// strain de_p = C^{-1} : (tau_tr - tau_{n+1}) (>= 0 for psi = phi; with psi < phi
// it is still >= 0 here since the flow points outward from the apex side).
// Stored energy: the complementary energy J [p^2/(2K) + s:s/(4G)] (as hypo_elastic).
//
// Deck (Vaango names): <model_type>classic</model_type>;
// <model_parameters>: shear_modulus, bulk_modulus, cohesion (>= 0),
//   angle_internal_friction, angle_dilation [degrees, 0..90, psi <= phi];
// <integration_parameters>: read and not used — the closed-form return replaces
//   Vaango's bisection/Runge-Kutta integrator (its tolerances and algorithm names
//   change nothing here).
// MissingFeature (exit 3): model_type classic_semiimplicit and sheng (eq. 19.14-19.18);
// max_hydrostatic_tension != 0 (not described in the seed); every use_* option
// (variable moduli 19.4, rate/depth/softening/suction cohesion 19.19-19.27, nonlocal
// correction 19.32-19.35, water retention) and initial_suction != 0.
#include <string>

#include "models/geo/MohrCoulombReturn.h"
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

class MohrCoulomb final : public ConstitutiveModel {
 public:
  explicit MohrCoulomb(const MohrCoulombParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "mohr_coulomb"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.K; }
  double shear_modulus() const override { return p_.G; }
  const MohrCoulombParams& params() const { return p_; }

 private:
  MohrCoulombParams p_;
};

}  // namespace tephra
