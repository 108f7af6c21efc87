#pragma once
// Vaango's metal-plasticity model of the "traditional approach", type
// "elastic_plastic" (VT ch. 18), composed from the sub-models of
// models/plasticity/ (EOS, shear modulus, flow stress, melting temperature,
// specific heat, damage).
//
// One step of a point, in the unrotated frame (Green-Naghdi, VT eq. 18.1):
//   F = R U;  tau_n = R_n^T sigma_n R_n;  de = sym((U_{n+1} - U_n) ((U_n + U_{n+1})/2)^{-1})  (~ d_hat dt)
//   moduli at the start of the step (§18.2, last paragraph; §18.7.1 "mu_{n+1} = mu_n"):
//     p̄_n = -tr(tau_n)/3, T_m = melt(p̄_n, rho), mu = shear(p̄_n, rho, T_n, T_m)
//   trial deviator (18.45): s_trial = s_n + 2 mu dev(de);  q_trial = sqrt(3/2) |s_trial|
//   yield (18.82): f = sqrt(3/2)|xi| - sigma_y(eps_p, eps_p_dot, T), xi = s - beta (beta: kinematic hardening, below)
//   flow (18.84-18.86): r = sqrt(3/2) xi/|xi|, d^p = gamma_dot r, eps_p_dot = gamma_dot (h^alpha = 1)
//   heating (18.20, 18.55): T = T_n + Delta_gamma h^T, h^T = chi sigma_y/(rho C_p)
//   Backward Euler (18.52-18.56) collapses for J2 to the scalar pair
//     r_f = q_trial - 3 mu Dg - sigma_y(eps_p,n + Dg, Dg/dt, T) = 0
//     r_T = T - T_n - Dg chi sigma_y/(rho C_p) = 0,
//   solved by Newton with static condensation of T (18.77): for each iterate Dg,
//   T(Dg) from r_T = 0 (scalar Newton, contraction factor Dg chi |d sigma_y/dT|/(rho C_p) << 1), and
//     dr_f/dDg = -3 mu - d sigma_y/d eps_p - (d sigma_y/d eps_p_dot)/dt - (d sigma_y/dT) dT/dDg,
//     dT/dDg = c (sigma_y + Dg (d sigma_y/d eps_p + (d sigma_y/d eps_p_dot)/dt)) / (1 - Dg c d sigma_y/dT),
//   c = chi/(rho C_p); safeguarded by bisection on [0, q_trial/(3 mu)] (r_f(0) > 0 >= r_f(upper)).
//   s_{n+1} = s_trial (1 - 3 mu Dg/q_trial) (18.80), so q_{n+1} = sigma_y(eps_p,n+1, eps_p_dot, T_{n+1}).
//   mean stress (18.81): sigma_m = p(J) - 3 kappa alpha (T_{n+1} - T_0), kappa = J dp/dJ;
//   sigma_{n+1} = R_{n+1} (sigma_m I + s_{n+1}) R_{n+1}^T.
// Outputs: heating dT/dt = (T_{n+1} - T_n)/dt = chi sigma_y eps_p_dot/(rho C_p) (Vaango's Tdot_PW;
// the driver adds it to the particle temperature, which is then the T_{n+1} of the return);
// plastic work J sigma_y Dg per reference volume; wave speed sqrt((kappa + 4 mu/3)/rho);
// stored energy J [sigma_m^2/(2K) + s:s/(4 mu)].
//
// Errata of ch. 18 and choices (docs/models/plasticity.md):
//   - (18.78) prints beta^{(k+1)} = beta_n + h^beta without Dg: read as beta_n + Dg h^beta (18.48).
//   - eps_p scaling: the convention of §18.8.1 (r = sqrt(3/2) n, eps_p_dot = gamma_dot).
//   - (18.76) evaluates the yield check at eps_dot_n; here the rate is Dg/dt throughout (the
//     check at Dg = 0 uses rate 0), so the check and the converged state satisfy the same
//     backward-Euler equations.
//   - T_0 of (18.81) is the point's temperature at its first update (the reference state is
//     stress free, as Vaango's rate form D - alpha T_dot I integrates to); the tag
//     <initial_material_temperature> is read and handed to no law (as in Vaango).
// MTS flow: the structure stress sigma_e is history, sigma_e = sigma_e,n + theta Dg inside the return.
// Stability checks (<stability_check>, VT ch. 16) after a plastic step: MetalFailure.h.
// Yield conditions gurson / rousselier: the two-invariant backward-Euler return of
// models/plasticity/PorousReturn.h, isothermal in the return (T_new = T + chi sigma:Delta eps^p
// /(rho C_p) after it); porosity grows by (1 - phi) tr Delta eps^p; ln J^p is history and the
// EOS is evaluated at J^e = J/J^p (exact on the returned surface for default_hypo; other EOS
// are re-evaluated at the new J^e, so f = O(Delta eps_v^2) off it). Stability checks with a
// porous yield use the J2-I1 continuum tangent (models/plasticity/ContinuumTangent.h, VT §18.6.2).
// Kinematic hardening (<kinematic_hardening_model> prager / armstrong_frederick, VT ch. 11 and
// eq. 18.47-18.52) with the von Mises yield: f = sqrt(3/2)|xi| - sigma_y, xi = s - beta, flow
// Delta eps^p = sqrt(3/2) Dg n, n = xi_{n+1}/|xi_{n+1}|, and the backward Euler of eq. 11.3 (18.48
// with h^beta Dg; the erratum of 18.78 resolved with the Dg factor):
//   beta_{n+1} = a (beta_n + (2/3) H_1 Delta eps^p),  a = 1/(1 + H_2 ||Delta eps^p||)  (H_2 = 0: Prager).
// Then xi_{n+1} is parallel to xi* = s_trial - a beta_n and r_f becomes
//   r_f = sqrt(3/2)|xi*(Dg)| - (3 mu + a H_1) Dg - sigma_y(eps_p,n + Dg, Dg/dt, T) = 0,
// solved with the same condensed Newton (T from r_T) and bracket [0, sqrt(3/2)(|s_trial| + |beta_n|)/(3 mu)];
// the backstress history column is "backStress" (unrotated frame). Heating uses sigma_y (18.20),
// the plastic work sigma : Delta eps^p; the stability tangent adds the kinematic modulus
// H_1 - 3/2 H_2 beta : n (KinematicHardeningModel::j2_modulus).
// <useModifiedEOS>: only the MPMICE hooks change (as in Vaango): in expansion p = p_ref
// (rho/rho0)^(K0/p_ref), K0 the EOS sub-model's tangent at J = 1 (models/solid/ModifiedEos.h).
// <coeff_thermal_expansion> is set to 0 when the deck's <MPM><DoThermalExpansion> is false
// (Vaango MPMFlags, default true).
// MTS with a porous yield: sigma_e inside the two-invariant return (PorousReturn.h).
// MissingFeature: kinematic hardening with a porous yield.
#include <memory>

#include "models/plasticity/FlowStressModel.h"
#include "models/plasticity/PlasticityEos.h"
#include "models/plasticity/ThermalModels.h"
#include "models/plasticity/YieldCondition.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/MetalFailure.h"

namespace tephra {

struct ElasticPlasticParams {
  double bulk_modulus = 0.0;      // <bulk_modulus> K [Pa]
  double shear_modulus = 0.0;     // <shear_modulus> mu_0 [Pa]
  double alpha = 1.0e-5;          // <coeff_thermal_expansion> [1/K] (Vaango default)
  double taylor_quinney = 0.9;    // <taylor_quinney_coeff> chi
  double tolerance = 1.0e-10;     // <tolerance>: relative tolerance of |r_f| / q_trial
  bool isothermal = false;        // <isothermal>: no plastic heating
  bool do_melting = true;         // <do_melting>: s = 0 once T > T_m
  bool compute_specific_heat = false;  // <compute_specific_heat>: C_p from <specific_heat_model>
  double specific_heat = 0.0;     // the material's <specific_heat> (used otherwise) [J/(kg K)]
  bool use_modified_eos = false;  // <useModifiedEOS>: MPMICE expansion branch (models/solid/ModifiedEos.h)
};

class ElasticPlastic final : public ConstitutiveModel {
 public:
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "elastic_plastic"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.bulk_modulus; }
  double shear_modulus() const override { return p_.shear_modulus; }
  // MPMICE hooks from the EOS sub-model (PlasticityEos.h: gauge p̄(ρ) at J = ρ0/ρ, E = 0,
  // default_hypo integrated to p = K ln J; the thermal term of VT 18.81 is left out).
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  bool modified_eos() const override { return p_.use_modified_eos; }

  // The backward-Euler J2 return of one point (public for the unit tests).
  struct Return {
    double delta_gamma = 0.0;  // Dg = Delta eps_p
    double temperature = 0.0;  // T_{n+1}
    double sigma_y = 0.0;      // sigma_y(eps_p,n+1, Dg/dt, T_{n+1})
    double sigma_e = 0.0;      // MTS structure stress at n+1 (sigma_e,n otherwise)
    double hardening = 0.0;    // d sigma_y/d eps_p at the returned state
    double d_T = 0.0;          // d sigma_y/dT at the returned state
    double residual = 0.0;     // r_f at the returned Dg
    Eigen::Matrix3d plastic_strain = Eigen::Matrix3d::Zero();  // Delta eps^p = sqrt(3/2) Dg n, n = xi/|xi|
    int iterations = 0;
  };
  // st: the state at t_n (eps_p, T, rho, p̄, mu, T_m, sigma_e); c = chi/(rho C_p) (0: isothermal).
  // s_trial: the deviatoric trial stress (18.45); beta_n: the backstress at t_n (0 without kinematic hardening).
  Return plastic_return(const Eigen::Matrix3d& s_trial, const Eigen::Matrix3d& beta_n, double mu, double dt,
                        const PlasticState& st, double c) const;
  // The isotropic case (beta = 0) for a trial of von Mises stress q_trial.
  Return plastic_return(double q_trial, double mu, double dt, const PlasticState& st, double c) const;

  using PointOut = MetalPointOut;
  // hist: this model's history of the point (history() order), read at t_n, overwritten with t_{n+1}.
  bool update_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new, const Eigen::Matrix3d& stress_old,
                    double T, double dt, double density0, double* hist, PointOut& out) const;

  ElasticPlasticParams p_;
  MetalFailureParams failure_;
  std::shared_ptr<const PlasticityEos> eos_;
  std::shared_ptr<const ShearModulusModel> shear_;
  std::shared_ptr<const FlowStressModel> flow_;
  std::shared_ptr<const MeltingTemperatureModel> melt_;
  std::shared_ptr<const SpecificHeatModel> cp_;
  bool mts_ = false;          // the flow model carries sigma_e
  int k_sigma_e_ = -1;        // history index of sigma_e (MTS only)
  int k_T0_ = -1, k_Tprev_ = -1;  // thermal reference and last temperature (alpha != 0 only)
  int k_drawn_ = -1;          // "initialFieldsDrawn" (Gaussian initial porosity/damage only)
  int k_beta_ = -1;           // flat offset of "backStress" (9 values, last column; kinematic hardening only)
  std::shared_ptr<const KinematicHardeningModel> kin_;  // nullptr: no backstress
  int k_evp_ = -1;            // "plasticVolumetricStrain" ln J^p (porous yield only)
  std::shared_ptr<const YieldCondition> yield_;  // nullptr: von Mises (J2 return)
  int history_count_ = 6;
};

}  // namespace tephra
