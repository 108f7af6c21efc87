#pragma once
// Porosity, scalar damage and the failure (localization) tests of the composed
// metal models (elastic_plastic, elastic_plastic_hp), as Vaango's
// ElasticPlastic/ElasticPlasticHP read and apply them (VT ch. 12, 15, 16).
//
// Tags of <constitutive_model> (Vaango's defaults, ElasticPlastic.cc):
//   evolve_porosity (true), initial_mean_porosity f0 (0.002), critical_porosity
//   f_c (0.5), frac_nucleation f_n (0.1), meanstrain_nucleation eps_n (0.3),
//   stddevstrain_nucleation s_n (0.1); evolve_damage (true); the damage law and
//   its initial value D0 from <damage_model> (none: D = 0, Vaango's NullDamage);
//   check_TEPLA_failure_criterion (true); check_max_stress_failure (true),
//   critical_stress (2e9 Pa); critical_scalar_damage (1.0, read; Vaango's
//   explicit update does not use it).
// Gaussian initial fields (VT ch. 12, 15; Vaango's initial_porosity_distrib /
// initial_scalar_damage_distrib = "gauss"): phi_0 ~ N(initial_mean_porosity,
// initial_std_porosity^2) and D_0 ~ N(initial_mean_scalar_damage,
// initial_std_scalar_damage^2), drawn once per point at its first update from a
// counter-based generator (SplitMix64 of <porosity_seed> / <scalar_damage_seed>
// and the point's index in its material, Box-Muller), so a run is reproducible;
// values are clipped to [0, 1) (porosity) and [0, inf) (damage). "constant" (the
// default) keeps the mean (porosity) / the damage model's D0 (damage).
//
// Evolution over a PLASTIC step only (elastic steps keep phi and D):
//   porosity, VT eq. 12.5-12.9:  phi_{n+1} = phi_n + dt [(1 - phi) tr(d^p) + A eps_p_dot],
//     A = f_n/(s_n sqrt(2 pi)) exp(-1/2 ((eps_p - eps_n)/s_n)^2)  (strain-controlled nucleation);
//     von Mises flow is isochoric, tr(d^p) = 0, so only nucleation acts.
//   damage, VT ch. 15:  D_{n+1} = D_n + dt D_dot(sigma_{n+1}, eps_p_dot, T).
// Failure (VT ch. 16; checked as Vaango does):
//   melted (T > T_m);  plastic and TEPLA (phi/f_c)^2 + D^2 > 1;
//   max principal stress > critical_stress;  plastic and <stability_check> unstable.
// The model only flags the point (history "localized" = 1); what a failed
// particle does (<erosion algorithm>) is the MPM driver's business.
#include <memory>

#include <Eigen/Core>

#include "models/ModelParameters.h"
#include "models/plasticity/PlasticState.h"
#include "models/plasticity/StabilityCheck.h"
#include "models/plasticity/YieldCondition.h"
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

// What a composed metal model's point update returns besides its history.
struct MetalPointOut {
  SolidPointResult r;
  double plastic_work = 0.0;  // dissipated work of the step per V0 [J/m^3]
  double heating = 0.0;       // adiabatic heating rate dT/dt [K/s]
};

struct MetalFailureParams {
  bool evolve_porosity = true;
  bool evolve_damage = true;
  bool check_tepla = true;
  bool check_max_stress = true;
  double initial_porosity = 0.002;  // f0
  double critical_porosity = 0.5;   // f_c
  double fn = 0.1, en = 0.3, sn = 0.1;
  double critical_stress = 2.0e9;
  bool gauss_porosity = false, gauss_damage = false;  // *_distrib = "gauss"
  double std_porosity = 0.0, mean_damage = 0.0, std_damage = 0.0;
  unsigned long long porosity_seed = 0, damage_seed = 0;
  std::shared_ptr<const DamageModel> damage;  // nullptr: no <damage_model>
  std::shared_ptr<const StabilityCheck> stability;  // <stability_check> (absent: "none")

  double initial_damage() const { return damage ? damage->initial_damage() : 0.0; }
  bool random_initial_fields() const { return gauss_porosity || gauss_damage; }
};

// A standard normal deviate, a pure function of (seed, index) (SplitMix64 + Box-Muller).
double seeded_normal(unsigned long long seed, unsigned long long index);

// The Gaussian initial porosity and damage of point `index` (MetalFailure.h header comment);
// leaves a field alone when its distribution is "constant".
void draw_initial_fields(const MetalFailureParams& f, unsigned long long index, double& porosity, double& damage);

// Reads the tags above (and the <damage_model> block) of a composed model.
MetalFailureParams read_metal_failure(const ModelParameters& params, const SubModelContext& ctx,
                                      const std::string& model);

// The nucleation factor A of VT eq. 12.9 at plastic strain eps_p.
double void_nucleation_factor(const MetalFailureParams& f, double eps_p);

// phi and D after a plastic step of length dt at the state st (eps_p, eps_p_rate, T, T_m)
// with the updated Cauchy stress.
// trace_dp: tr(Delta eps^p) of the step (0 for isochoric J2 flow): growth (1 - phi) tr(Delta eps^p), VT 12.6.
void evolve_porosity_and_damage(const MetalFailureParams& f, const Eigen::Matrix3d& stress, const PlasticState& st,
                                double dt, double& porosity, double& damage, double trace_dp = 0.0);

// The stability check of a plastic J2 step (VT ch. 16; Vaango's ElasticPlastic(HP) Check 3:
// after a plastic step only), in the unrotated frame: de the step's total strain increment
// (D = de/dt, the rate of deformation), tau the stress at t_{n+1}; xi the flow direction at
// t_{n+1}: the deviator relative to the backstress xi = s - beta (the deviator without kinematic
// hardening); K, mu the moduli; H the total (isotropic + kinematic) hardening modulus of the
// continuum tangent (models/plasticity/StabilityCheck.h). Unstable: (C^ep : D) : D <= 0 (drucker).
bool metal_point_unstable(const MetalFailureParams& f, const Eigen::Matrix3d& de, const Eigen::Matrix3d& tau,
                          const Eigen::Matrix3d& xi, double dt, double K, double mu, double H);
// The same with a given continuum tangent C (a porous yield: the J2-I1 tangent of
// models/plasticity/ContinuumTangent.h).
bool metal_point_unstable(const MetalFailureParams& f, const Eigen::Matrix3d& de, const Eigen::Matrix3d& tau,
                          double dt, const Tangent4& C);
// Whether a stability check is configured (the porous branches build their tangent only then).
inline bool has_stability_check(const MetalFailureParams& f) { return f.stability && f.stability->type() != "none"; }

// The failure tests above (without the stability check).
bool metal_point_failed(const MetalFailureParams& f, bool melted, bool plastic, double porosity, double damage,
                        const Eigen::Matrix3d& stress);

}  // namespace tephra
