#pragma once
// Vaango's hypo-elastic-plastic metal model, type "elastic_plastic_hp" (VT
// ch. 17, Algorithm 1 of §17.2.3 for the von Mises case; Vaango class
// ElasticPlasticHP), composed from the sub-models of models/plasticity/.
//
// One step of a point (unrotated frame, Green-Naghdi, VT eq. 17.1-17.2):
//   F = R U;  tau_n = R_n^T sigma_n R_n;
//   de = sym((U_{n+1} - U_n) ((U_n + U_{n+1})/2)^{-1})     (~ d_hat dt; as hypo_elastic)
//   pressure: p_{n+1} = EOS(J, p_n, tr de / dt, dt)        (mean stress, VT ch. 6)
//   T_m = melt(p̄, ρ), μ = shear(p̄, ρ, T, T_m)               (VT ch. 13, 7)
//   s_trial = s_n + 2 μ dev(de)                            (VT eq. 17.50)
//   elastic if σ_eff(s_trial) <= σ_y(ε_p,n, 0, T), otherwise radial return
//   for von Mises (N = 3/2 s/σ_eff, ε̇_p = Δε_p/Δt; VT 17.79 specialised):
//     g(Δ) = σ_eff_trial - 3 μ Δ - σ_y(ε_p,n + Δ, Δ/Δt, T) = 0,
//   Newton with the flow model's exact derivatives
//     g'(Δ) = -3μ - ∂σ_y/∂ε_p - (∂σ_y/∂ε̇_p)/Δt,
//   safeguarded by bisection on [0, σ_eff_trial/(3μ)] (g(0) > 0 >= g(upper));
//   s_{n+1} = s_trial (1 - 3 μ Δ / σ_eff_trial);  sigma_{n+1} = R_{n+1} (p I + s) R_{n+1}^T.
// Heating (adiabatic, VT eq. 17.27 with h^T): dT/dt = χ σ_y ε̇_p / (ρ C_p),
// χ = <taylor_quinney_coeff>; 0 when <isothermal>. Plastic work per reference
// volume: J σ_y Δε_p. Melting (<do_melting>): s = 0 when T >= T_m.
// Wave speed c² = (κ + 4μ/3)/ρ with the tangent bulk modulus κ = J ∂p/∂J (VT 17.164).
// Stored energy: J [p²/(2K) + s:s/(4μ)] (complementary energy, as hypo_elastic).
//
// Mie-Grüneisen: the energy term Γ0 E uses E = 0 (the Hugoniot reference; the
// internal energy is not carried yet).
// Porosity, damage and the failure flag after the return (uncoupled, as Algorithm 1
// says; models/solid/MetalFailure.h, Vaango's defaults: evolve_porosity and
// evolve_damage true, TEPLA and max-stress checks on).
// Stability checks (<stability_check>, VT ch. 16) after a plastic step: MetalFailure.h.
// Yield conditions gurson / rousselier: the two-invariant backward-Euler return of
// models/plasticity/PorousReturn.h (isothermal in the return, heating χ σ:Δε^p/(ρ C_p Δt)
// after it; porosity grows by (1 - φ) tr Δε^p); the plastic volume ln J^p is history and the
// EOS is evaluated at J^e = J/J^p. Stability checks with a porous yield use the J2-I1
// continuum tangent of the returned state (models/plasticity/ContinuumTangent.h, VT §18.6.2).
// Kinematic hardening (<kinematic_hardening_model> prager / armstrong_frederick, VT ch. 11)
// with the von Mises yield: f = sqrt(3/2)|ξ| - σ_y, ξ = s - β (VT ch. 8). The backstress β
// (history "backStress", unrotated frame, deviatoric) follows the backward Euler of eq. 11.3
//   β_{n+1} = a (β_n + (2/3) H_1 Δε^p),  a = 1/(1 + H_2 ||Δε^p||)   (H_2 = 0: Prager 11.2)
// with Δε^p = sqrt(3/2) Δ n̂, n̂ = ξ_{n+1}/|ξ_{n+1}|, Δ = Δε_p. Then ξ_{n+1} is parallel to
// ξ* = s_trial - a β_n and the return is one scalar equation
//   g(Δ) = sqrt(3/2)|ξ*(Δ)| - (3μ + a H_1) Δ - σ_y(ε_p,n + Δ, Δ/Δt, T) = 0
// (Prager: ξ* = ξ_trial, the radial return with modulus 3μ + H_1), bracketed by
// [0, sqrt(3/2)(|s_trial| + |β_n|)/(3μ)]; s_{n+1} = s_trial - 2μ Δε^p. Without kinematic
// hardening β = 0 and this is the radial return above. Heating and plastic work use
// σ:Δε^p (VT eq. 12.14), which is σ_y Δ without a backstress.
// MTS flow: the structure stress σ_e is history ("mtsStructureStress"), σ_e = σ_e,n + θ(σ_e,n) Δ
// inside the return (the flow model's ∂σ_y/∂ε_p carries S_e θ μ/μ_0), as in elastic_plastic.
// Stability checks with kinematic hardening use the J2 tangent on n̂ = ξ/|ξ| with the modulus
// H = ∂σ_y/∂ε_p + H_1 - 3/2 H_2 β:n̂ (KinematicHardeningModel::j2_modulus).
// <plastic_convergence_algo> radialReturn / biswajit: both take the returns above.
// Thermal expansion (<coeff_thermal_expansion> α, default 0 as Vaango; VT eq. 17.3-17.5 with
// the closed form of 18.12): the mean stress is the EOS's minus the thermal pressure,
//   p = p_EOS(J^e) - 3 κ α (T - T_0),   κ = J^e dp_EOS/dJ^e,
// T_0 the point's first temperature (history "thermalReferenceTemperature"); the rate-form
// default_hypo integrates the mechanical part p_EOS (the thermal part of p_n is removed first,
// as in elastic_plastic). For default_hypo (κ = K, p_EOS = K ln J) free heating gives σ = 0 at
// ln J = 3 α ΔT (log strain α ΔT per direction); heating at F = I gives σ = -3 K α ΔT I.
// Vaango's explicit ElasticPlasticHP reads α and does not use it ("only used in implicit code").
// α = 0 when the deck's <MPM><DoThermalExpansion> is false (Vaango MPMFlags, default true).
// <useModifiedEOS>: only the MPMICE hooks change (as in Vaango): in expansion p = p_ref
// (rho/rho0)^(K0/p_ref), K0 the EOS sub-model's tangent at J = 1 (models/solid/ModifiedEos.h).
// MTS with a porous yield: σ_e inside the two-invariant return (PorousReturn.h).
// MissingFeature: kinematic hardening with a porous yield,
// deviatoric_stress_model other than hypoElastic.
#include <memory>

#include "models/plasticity/FlowStressModel.h"
#include "models/plasticity/PlasticityEos.h"
#include "models/plasticity/ThermalModels.h"
#include "models/plasticity/YieldCondition.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/MetalFailure.h"

namespace tephra {

struct ElasticPlasticHPParams {
  double bulk_modulus = 0.0;    // <bulk_modulus> K [Pa]
  double shear_modulus = 0.0;   // <shear_modulus> μ_0 [Pa]
  double taylor_quinney = 0.9;  // <taylor_quinney_coeff> χ
  double tolerance = 1e-12;     // <tolerance>: relative tolerance of the return
  bool isothermal = false;      // <isothermal>
  // <compute_specific_heat> (Vaango's, default false): the heating's c_p from the
  // <specific_heat_model>; false: the material's <specific_heat> (specific_heat below).
  bool compute_specific_heat = false;
  double specific_heat = 0.0;  // the material's <specific_heat> [J/(kg K)]
  bool do_melting = true;       // <do_melting> (Vaango's default)
  double alpha = 0.0;           // <coeff_thermal_expansion> [1/K] (Vaango's default 0)
  bool use_modified_eos = false;  // <useModifiedEOS>: MPMICE expansion branch (models/solid/ModifiedEos.h)
};

class ElasticPlasticHP final : public ConstitutiveModel {
 public:
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "elastic_plastic_hp"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.bulk_modulus; }
  double shear_modulus() const override { return p_.shear_modulus; }
  // MPMICE hooks from the EOS sub-model (PlasticityEos.h: gauge p̄(ρ) at J = ρ0/ρ, E = 0,
  // default_hypo integrated to p = K ln J; the thermal term of VT 18.81 is left out).
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  bool modified_eos() const override { return p_.use_modified_eos; }

  // The point update (what update() does for one point; unit tests call it).
  // hist = {ε_p, ε̇_p, φ, D, localized, strainRate, [ln J^p], [drawn], [σ_e], [β (9, row-major)]} (flat),
  // read at t_n and overwritten with t_{n+1}.
  using PointOut = MetalPointOut;
  bool update_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new, const Eigen::Matrix3d& stress_old,
                    double T, double dt, double density0, double* hist, PointOut& out) const;

  ElasticPlasticHPParams p_;
  MetalFailureParams failure_;  // porosity, damage, failure tests (models/solid/MetalFailure.h)
  std::shared_ptr<const PlasticityEos> eos_;
  std::shared_ptr<const ShearModulusModel> shear_;
  std::shared_ptr<const FlowStressModel> flow_;
  std::shared_ptr<const MeltingTemperatureModel> melt_;
  std::shared_ptr<const SpecificHeatModel> cp_;
  std::shared_ptr<const YieldCondition> yield_;  // nullptr: von Mises (radial return)
  std::shared_ptr<const KinematicHardeningModel> kin_;  // nullptr: no backstress
  int k_sigma_e_ = -1;  // history "mtsStructureStress" (MTS flow only)
  int k_beta_ = -1;   // flat offset of history "backStress" (9 values, last column; kinematic only)
  int k_evp_ = -1;    // history "plasticVolumetricStrain" (porous yield only)
  int k_drawn_ = -1;  // history "initialFieldsDrawn" (Gaussian initial fields only)
  int k_T0_ = -1, k_Tprev_ = -1;  // thermal reference and last temperature (alpha != 0 only)
  int history_count_ = 5;
};

}  // namespace tephra
