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
  // Gaussian initial fields (header comment); Vaango's distributions are "constant" and "gauss".
  auto distribution = [&](const char* tag) {
    const std::string d = p.get_string(tag, "constant");
    if (d != "constant" && d != "gauss") p.fail(tag, "unknown distribution '" + d + "' (valid: constant, gauss)");
    return d == "gauss";
  };
  f.gauss_porosity = distribution("initial_porosity_distrib");
  f.gauss_damage = distribution("initial_scalar_damage_distrib");
  f.std_porosity = p.get_double("initial_std_porosity", 0.0);
  f.mean_damage = p.get_double("initial_mean_scalar_damage", 0.0);
  f.std_damage = p.get_double("initial_std_scalar_damage", 0.0);
  if (!(f.std_porosity >= 0.0)) p.fail("initial_std_porosity", "must be >= 0");
  if (!(f.std_damage >= 0.0)) p.fail("initial_std_scalar_damage", "must be >= 0");
  if (!(f.mean_damage >= 0.0)) p.fail("initial_mean_scalar_damage", "must be >= 0");
  auto seed = [&](const char* tag) {
    const double v = p.get_double(tag, 0.0);
    if (!(v >= 0.0) || v != std::floor(v)) p.fail(tag, "must be a non-negative integer");
    return static_cast<unsigned long long>(v);
  };
  f.porosity_seed = seed("porosity_seed");
  f.damage_seed = seed("scalar_damage_seed");
  // Vaango's ElasticPlastic has no internal-variable model: the block is accepted, unused.
  if (const ModelParameters* b = p.block("internal_variable_model"))
    for (const char* n : {"vol_frac_nucleation", "mean_strain_nucleation", "stddev_strain_nucleation"}) b->has(n);
  f.stability = assembly::sub_model(p, model, "stability_check", stability_checks(), "none", ctx,
                                    [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                                      return create_stability_check(k, q, c);
                                    });
  if (p.block("damage_model"))
    f.damage = assembly::sub_model(p, model, "damage_model", damage_models(), "", ctx,
                                   [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                                     return create_damage_model(k, q, c);
                                   });
  return f;
}

double seeded_normal(unsigned long long seed, unsigned long long index) {
  // SplitMix64 (Steele, Lea, Flood 2014) of two counters, then Box-Muller.
  auto mix = [](unsigned long long z) {
    z += 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  };
  const unsigned long long a = mix(seed * 0x9E3779B97F4A7C15ULL ^ mix(2 * index));
  const unsigned long long b = mix(a ^ mix(2 * index + 1));
  const double u1 = (double(a >> 11) + 0.5) * 0x1.0p-53;  // (0, 1)
  const double u2 = double(b >> 11) * 0x1.0p-53;          // [0, 1)
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

void draw_initial_fields(const MetalFailureParams& f, unsigned long long index, double& porosity, double& damage) {
  if (f.gauss_porosity)
    porosity = std::clamp(f.initial_porosity + f.std_porosity * seeded_normal(f.porosity_seed, index), 0.0,
                          std::nextafter(1.0, 0.0));
  if (f.gauss_damage) damage = std::max(0.0, f.mean_damage + f.std_damage * seeded_normal(f.damage_seed, index));
}

double void_nucleation_factor(const MetalFailureParams& f, double eps_p) {
  if (!(f.fn > 0.0)) return 0.0;
  const double z = (eps_p - f.en) / f.sn;
  return f.fn / (f.sn * std::sqrt(2.0 * M_PI)) * std::exp(-0.5 * z * z);
}

void evolve_porosity_and_damage(const MetalFailureParams& f, const Eigen::Matrix3d& stress, const PlasticState& st,
                                double dt, double& porosity, double& damage, double trace_dp) {
  if (f.evolve_porosity) {
    // VT eq. 12.5-12.9: growth (1 - phi) tr(Delta eps^p) (0 for isochoric J2 flow) plus nucleation.
    porosity = std::clamp(porosity + (1.0 - porosity) * trace_dp + dt * void_nucleation_factor(f, st.eps_p) * st.eps_p_rate,
                          0.0, 1.0);
  }
  if (f.evolve_damage && f.damage) damage += dt * f.damage->damage_rate(stress, st);
}

bool metal_point_unstable(const MetalFailureParams& f, const Eigen::Matrix3d& de, const Eigen::Matrix3d& tau,
                          const Eigen::Matrix3d& xi, double dt, double K, double mu, double H) {
  if (!has_stability_check(f) || !(dt > 0.0)) return false;
  const double nx = xi.norm();
  if (!(nx > 0.0)) return false;
  return metal_point_unstable(f, de, tau, dt, j2_elastoplastic_tangent(K, mu, H, xi / nx));
}

bool metal_point_unstable(const MetalFailureParams& f, const Eigen::Matrix3d& de, const Eigen::Matrix3d& tau,
                          double dt, const Tangent4& C) {
  if (!has_stability_check(f) || !(dt > 0.0)) return false;
  StabilityInput in;
  in.stress = tau;
  in.deformation_rate = de / dt;
  in.tangent = C;
  return f.stability->unstable(in);
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
