#include "models/solid/MetalFailure.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "models/solid/SubModelAssembly.h"

namespace tephra {

MetalFailureParams read_metal_failure(const ModelParameters& p, const SubModelContext& ctx, const std::string& model) {
  MetalFailureParams f;
  f.evolve_porosity = p.get_bool("evolve_porosity", true);
  f.evolve_damage = p.get_bool("evolve_damage", true);
  f.check_tepla = p.get_bool("check_TEPLA_failure_criterion", true);
  f.check_max_stress = p.get_bool("check_max_stress_failure", true);
  f.initial_porosity = p.get_double("initial_mean_porosity", 0.002);
  f.critical_porosity = p.get_double("critical_porosity", 0.5);
  f.fn = p.get_double("frac_nucleation", 0.1);
  f.en = p.get_double("meanstrain_nucleation", 0.3);
  f.sn = p.get_double("stddevstrain_nucleation", 0.1);
  f.critical_stress = p.get_double("critical_stress", 2.0e9);
  if (!(f.initial_porosity >= 0.0 && f.initial_porosity < 1.0)) p.fail("initial_mean_porosity", "must be in [0, 1)");
  if (!(f.critical_porosity > 0.0)) p.fail("critical_porosity", "must be > 0");
  if (f.fn > 0.0 && !(f.sn > 0.0)) p.fail("stddevstrain_nucleation", "must be > 0");
  p.get_double("critical_scalar_damage", 1.0);
  p.get_double("initial_mean_scalar_damage", 0.0);  // Vaango: the mean of a Gaussian initial damage only
  // Random initial fields: Vaango draws Gaussian values unless the distribution is "constant".
  for (const auto& [dist, std_tag] : {std::pair<const char*, const char*>{"initial_porosity_distrib", "initial_std_porosity"},
                                      {"initial_scalar_damage_distrib", "initial_std_scalar_damage"}}) {
    const std::string d = p.get_string(dist, "constant");
    p.get_double(std_tag, 0.0);
    if (d != "constant") p.missing_feature(dist, model + " random (Gaussian) initial " + std::string(dist));
  }
  p.has("porosity_seed");
  p.has("scalar_damage_seed");
  // Vaango's ElasticPlastic has no internal-variable model: the block is accepted, unused.
  if (const ModelParameters* b = p.block("internal_variable_model"))
    for (const char* n : {"vol_frac_nucleation", "mean_strain_nucleation", "stddev_strain_nucleation"}) b->has(n);
  if (p.block("damage_model"))
    f.damage = assembly::sub_model(p, model, "damage_model", damage_models(), "", ctx,
                                   [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                                     return create_damage_model(k, q, c);
                                   });
  return f;
}

double void_nucleation_factor(const MetalFailureParams& f, double eps_p) {
  if (!(f.fn > 0.0)) return 0.0;
  const double z = (eps_p - f.en) / f.sn;
  return f.fn / (f.sn * std::sqrt(2.0 * M_PI)) * std::exp(-0.5 * z * z);
}

void evolve_porosity_and_damage(const MetalFailureParams& f, const Eigen::Matrix3d& stress, const PlasticState& st,
                                double dt, double& porosity, double& damage) {
  if (f.evolve_porosity) {
    // VT eq. 12.5 with tr(d^p) = 0 (isochoric J2 flow): nucleation only.
    porosity = std::min(1.0, porosity + dt * void_nucleation_factor(f, st.eps_p) * st.eps_p_rate);
  }
  if (f.evolve_damage && f.damage) damage += dt * f.damage->damage_rate(stress, st);
}

bool metal_point_failed(const MetalFailureParams& f, bool melted, bool plastic, double porosity, double damage,
                        const Eigen::Matrix3d& stress) {
  if (melted) return true;
  if (plastic && f.check_tepla) {
    const double phi = porosity / f.critical_porosity;
    if (phi * phi + damage * damage > 1.0) return true;  // TEPLA-F (VT 16.1, Vaango's damage form)
  }
  if (f.check_max_stress) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(stress, Eigen::EigenvaluesOnly);
    if (eig.eigenvalues().maxCoeff() > f.critical_stress) return true;
  }
  return false;
}

}  // namespace tephra
