#pragma once
// Vaango's unified compressible neo-Hookean solid, types "comp_neo_hook_plastic"
// and "UCNH" (Vaango class UCNH; "comp_neo_hook_plastic" is UCNH with
// usePlasticity = true). Hyperelastic-plastic, multiplicative split F = F_e F_p,
// J2 flow with linear isotropic hardening, return mapping on the Kirchhoff
// deviator (Simo & Hughes, "Computational Inelasticity" 1998, §9.3, Box 9.1).
//
// State: bbar_e = J^{-2/3} F_e F_e^T (history "bElBar", det bbar_e = 1) and the
// equivalent plastic strain alpha (history "plasticStrain").
//
// One step (f = F_{n+1} F_n^{-1}):
//   fbar = det(f)^{-1/3} f,   bbar_trial = fbar bbar_n fbar^T          (Box 9.1 step 1)
//   I_e = tr(bbar_trial)/3,   mubar = G I_e,   s_trial = G dev(bbar_trial)
//   f_trial = |s_trial| - sqrt(2/3) (sigma_y + H alpha_n)              (step 2)
//   f_trial <= 0: s = s_trial, bbar = bbar_trial
//   f_trial  > 0: dgamma = f_trial / (2 mubar (1 + H/(3 mubar)))       (step 3, linear hardening)
//                 s = s_trial - 2 mubar dgamma n,  n = s_trial/|s_trial|
//                 alpha += sqrt(2/3) dgamma
//                 bbar = s/G + x I with x the root of det(s/G + x I) = 1 nearest I_e
//   tau = J p(J) I + s,   sigma = tau / J,   p(J) = K/2 (J - 1/J)        (Vaango HyperElasticEOS)
// The consistency |s_{n+1}| = sqrt(2/3)(sigma_y + H alpha_{n+1}) holds exactly.
// The volume-preserving choice of x (Simo & Hughes §9.3.2, the det bbar_e = 1
// correction) keeps det F_p = 1 exactly; Vaango's UCNH uses x = I_e, which
// differs by O(dgamma |s|/G) per plastic step (its det bbar_e drifts). The
// stress of the step is the same.
// Without plasticity (UCNH default) bbar = J^{-2/3} F F^T: the comp_neo_hook stress.
//
// Outputs: W = K/2[(J^2-1)/2 - ln J] + G/2 (tr bbar_e - 3) per reference volume
// (Vaango's StrainEnergy sum); c^2 = (K_t + 4G/3)/rho with K_t = K/2 (1 + 1/J^2);
// plastic work per reference volume = the stored energy the return releases at
// fixed F, Psi(bbar_trial) - Psi(bbar_{n+1}) = 3G/2 (I_e - x) (closes the
// balance stress work = Psi + dissipation; |s| dgamma agrees to O(|s|/G));
// heating 0 (Vaango's UCNH sets pdTdt = 0).
//
// MPMICE hooks: the standard EOS as comp_neo_hook. <useModifiedEOS> (Vaango
// UCNH::computePressEOSCM): for rho < rho0 the absolute pressure is
// p = p_ref (rho/rho0)^n, n = K/p_ref, which depends on the run's reference
// pressure: modified_eos() is true, the hooks give the standard (compression)
// branch and MPMICE adds the expansion branch (models/solid/ModifiedEos.h, the
// same mechanism as the metal models and visco_scram).
//
// MissingFeature: useDamage, useInitialStress, yield_distrib other than
// "constant", an <equation_of_state> other than Vaango's default.
#include <optional>

#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct CompNeoHookPlasticParams {
  double bulk_modulus = 0.0;       // K [Pa], <bulk_modulus>
  double shear_modulus = 0.0;      // G [Pa], <shear_modulus>
  bool use_plasticity = true;      // <usePlasticity>
  double yield_stress = 0.0;       // sigma_y [Pa], <yield_stress>
  double hardening_modulus = 0.0;  // H [Pa], <hardening_modulus>
  double initial_alpha = 0.0;      // <alpha>: initial equivalent plastic strain
  bool use_modified_eos = false;   // <useModifiedEOS>
};

class CompNeoHookPlastic final : public ConstitutiveModel {
 public:
  CompNeoHookPlastic(const CompNeoHookPlasticParams& p, std::string type) : p_(p), type_(std::move(type)) {}
  // `type` is the deck key: "comp_neo_hook_plastic" (usePlasticity defaults
  // to true) or "UCNH" (defaults to false).
  static ConstitutiveModelP create(const ModelParameters& params, const std::string& type);

  std::string type() const override { return type_; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.bulk_modulus; }
  double shear_modulus() const override { return p_.shear_modulus; }
  // Elastic only: sigma depends on F alone and W(F) is its potential.
  bool hyperelastic() const override { return !p_.use_plasticity; }

  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  bool modified_eos() const override { return p_.use_modified_eos; }

  // The point update. hist = {bbar_e (9, row-major), alpha}, read at t_n and
  // overwritten with t_{n+1}. Returns false for an inadmissible state.
  struct PointOut {
    SolidPointResult r;
    double plastic_work = 0.0;  // per reference volume [J/m^3]
  };
  bool update_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new, double density0, double* hist,
                    PointOut& out) const;

  const CompNeoHookPlasticParams& params() const { return p_; }

 private:
  CompNeoHookPlasticParams p_;
  std::string type_;
};

// Vaango's modified EOS (useModifiedEOS, UCNH::computePressEOSCM), with the
// reference pressure p_ref [Pa] of the run: gauge pressure p - p_ref at rho.
//   rho >= rho0: the standard EOS, p - p_ref = K/2 (rho/rho0 - rho0/rho),
//                dp/drho = K/2 (1/rho0 + rho0/rho^2) = c^2 (as comp_neo_hook;
//                Vaango's tmp there is K/rho, equal at rho0);
//   rho <  rho0: p = p_ref (rho/rho0)^n, n = K/p_ref, dp/drho = (K/rho)(rho/rho0)^n = c^2.
// Both branches give p = p_ref and dp/drho = K/rho0 at rho = rho0.
SolidEosPoint modified_eos_pressure(double rho, double density0, double K, double p_ref);
// The inverse: p_gauge >= 0 the standard root rho0 (q + sqrt(q^2 + 1)), q = p_gauge/K;
// p_gauge < 0: rho = rho0 ((p_gauge + p_ref)/p_ref)^{1/n}.
double modified_eos_density(double p_gauge, double density0, double K, double p_ref);

}  // namespace tephra
