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
//   explicit update does not use it); initial_std_porosity /
//   initial_std_scalar_damage and the *_distrib tags (Gaussian initial values:
//   MissingFeature when a standard deviation is given with a non-zero value and
//   the distribution is asked for).
//
// Evolution over a PLASTIC step only (elastic steps keep phi and D):
//   porosity, VT eq. 12.5-12.9:  phi_{n+1} = phi_n + dt [(1 - phi) tr(d^p) + A eps_p_dot],
//     A = f_n/(s_n sqrt(2 pi)) exp(-1/2 ((eps_p - eps_n)/s_n)^2)  (strain-controlled nucleation);
//     von Mises flow is isochoric, tr(d^p) = 0, so only nucleation acts.
//   damage, VT ch. 15:  D_{n+1} = D_n + dt D_dot(sigma_{n+1}, eps_p_dot, T).
// Failure (VT ch. 16; checked as Vaango does, the stability test by the model):
//   melted (T > T_m);  plastic and TEPLA (phi/f_c)^2 + D^2 > 1;
//   max principal stress > critical_stress.
// The model only flags the point (history "localized" = 1); what a failed
// particle does (<erosion algorithm>) is the MPM driver's business.
#include <memory>

#include <Eigen/Core>

#include "models/ModelParameters.h"
#include "models/plasticity/PlasticState.h"
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
  std::shared_ptr<const DamageModel> damage;  // nullptr: no <damage_model>

  double initial_damage() const { return damage ? damage->initial_damage() : 0.0; }
};

// Reads the tags above (and the <damage_model> block) of a composed model.
MetalFailureParams read_metal_failure(const ModelParameters& params, const SubModelContext& ctx,
                                      const std::string& model);

// The nucleation factor A of VT eq. 12.9 at plastic strain eps_p.
double void_nucleation_factor(const MetalFailureParams& f, double eps_p);

// phi and D after a plastic step of length dt at the state st (eps_p, eps_p_rate, T, T_m)
// with the updated Cauchy stress.
void evolve_porosity_and_damage(const MetalFailureParams& f, const Eigen::Matrix3d& stress, const PlasticState& st,
                                double dt, double& porosity, double& damage);

// The failure tests above (without the stability check).
bool metal_point_failed(const MetalFailureParams& f, bool melted, bool plastic, double porosity, double damage,
                        const Eigen::Matrix3d& stress);

}  // namespace tephra
