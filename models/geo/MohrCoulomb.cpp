#include "models/geo/MohrCoulomb.h"

#include <cmath>
#include <memory>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/PolarNewton.h"

namespace tephra {

long MohrCoulomb::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  using M3 = Eigen::Matrix3d;
  const M3 I = M3::Identity();
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    const PolarDecomposition a = polar_decomposition_newton(in.F_old[i]);
    const PolarDecomposition b = polar_decomposition_newton(in.F_new[i]);
    const M3 G = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
    const M3 de = 0.5 * (G + G.transpose());
    const M3 tau_n = a.R.transpose() * in.stress_old[i] * a.R;
    M3 tau_tr = tau_n + ((p_.K - 2.0 * p_.G / 3.0) * de.trace()) * I + (2.0 * p_.G) * de;
    tau_tr = (0.5 * (tau_tr + tau_tr.transpose())).eval();
    const Eigen::SelfAdjointEigenSolver<M3> eig(tau_tr);
    // ascending eigenvalues -> s1 >= s2 >= s3
    const Eigen::Vector3d s_tr(eig.eigenvalues()(2), eig.eigenvalues()(1), eig.eigenvalues()(0));
    const MohrCoulombReturnResult r = mohr_coulomb_return(p_, s_tr);
    M3 tau = tau_tr;
    double work = 0.0;
    if (r.region != MohrCoulombRegion::elastic) {
      const M3& V = eig.eigenvectors();
      tau = r.s(0) * V.col(2) * V.col(2).transpose() + r.s(1) * V.col(1) * V.col(1).transpose() +
            r.s(2) * V.col(0) * V.col(0).transpose();
      // de_p = C^-1 : (tau_tr - tau) (coaxial): volumetric /(3K), deviatoric /(2G)
      const M3 d = tau_tr - tau;
      const M3 dep = (d.trace() / (9.0 * p_.K)) * I + (d - d.trace() / 3.0 * I) / (2.0 * p_.G);
      work = J * (tau.cwiseProduct(dep)).sum();
    }
    M3 sigma = b.R * tau * b.R.transpose();
    sigma = (0.5 * (sigma + sigma.transpose())).eval();  // eval: no aliasing
    if (!sigma.allFinite()) return false;
    out.stress[i] = sigma;
    const double pr = sigma.trace() / 3.0;
    const M3 s = sigma - pr * I;
    out.energy_density[i] = J * (pr * pr / (2.0 * p_.K) + s.squaredNorm() / (4.0 * p_.G));
    out.wave_speed[i] = std::sqrt((p_.K + 4.0 * p_.G / 3.0) * J / in.density0);
    out.plastic_work[i] = work;
    out.heating[i] = 0.0;
    return true;
  });
}

ConstitutiveModelP MohrCoulomb::create(const ModelParameters& params) {
  const std::string type = params.get_string("model_type", "");
  if (type.empty()) params.fail("model_type", "mohr_coulomb needs <model_type> (classic, classic_semiimplicit, sheng)");
  if (type == "classic_semiimplicit" || type == "sheng")
    params.missing_feature("model_type", "mohr_coulomb model_type '" + type + "' (only 'classic' is built)");
  if (type != "classic")
    params.fail("model_type", "'" + type + "' is not one of classic, classic_semiimplicit, sheng");
  const ModelParameters* mp = params.block("model_parameters");
  if (!mp) params.fail("model_parameters", "mohr_coulomb needs <model_parameters>");
  MohrCoulombParams m;
  m.G = mp->get_double("shear_modulus");
  m.K = mp->get_double("bulk_modulus");
  m.c = mp->get_double("cohesion");
  const double phi = mp->get_double("angle_internal_friction"), psi = mp->get_double("angle_dilation");
  if (!(m.G > 0.0)) mp->fail("shear_modulus", "must be > 0");
  if (!(m.K > 0.0)) mp->fail("bulk_modulus", "must be > 0");
  if (!(m.c >= 0.0)) mp->fail("cohesion", "must be >= 0");
  if (!(phi >= 0.0 && phi < 90.0)) mp->fail("angle_internal_friction", "must be in [0, 90) degrees");
  if (!(psi >= 0.0 && psi <= phi)) mp->fail("angle_dilation", "must be in [0, angle_internal_friction] degrees");
  m.phi = phi * M_PI / 180.0;
  m.psi = psi * M_PI / 180.0;
  if (mp->get_double("max_hydrostatic_tension", 0.0) != 0.0)
    mp->missing_feature("max_hydrostatic_tension", "mohr_coulomb max_hydrostatic_tension != 0 (not in the seed)");
  if (mp->get_double("initial_suction", 0.0) != 0.0)
    mp->missing_feature("initial_suction", "mohr_coulomb suction cohesion (VT eq. 19.26-19.27)");
  for (const char* flag : {"use_water_retention", "use_undrained_shear_transition", "use_variable_elastic_modulus",
                           "use_linearly_varying_cohesion", "use_softening", "use_regularized_nonlocal_softening",
                           "use_nonlocal_correction"})
    if (mp->get_bool(flag, false))
      mp->missing_feature(flag, std::string("mohr_coulomb ") + flag + " (VT §19.2, 19.4, 19.6)");
  // Parameters of the options above: accepted (they only act when their option is on).
  for (const char* opt : {"phi_b", "water_retention_param_1", "water_retention_param_2", "water_retention_param_3",
                          "water_retention_param_4", "water_influence_A1", "water_influence_B1", "water_influence_W",
                          "beta_strain_rate", "ref_strain_rate", "variable_modulus_m", "variable_modulus_nu_y",
                          "linear_cohesion_a", "linear_cohesion_y_ref", "softening_St", "softening_strain_95",
                          "regularization_t_FE", "regularization_t_shear", "nonlocal_n", "nonlocal_l"})
    mp->get_double(opt, 0.0);
  mp->get_string("linear_cohesion_depth_direction", "");
  mp->get_string("retention_model", "");
  const ModelParameters* ip = params.block("integration_parameters");
  if (!ip) params.fail("integration_parameters", "mohr_coulomb needs <integration_parameters> (Vaango's schema)");
  for (const char* opt : {"max_iterations_pegasus", "alpha_check_pegasus", "alpha_change_pegasus", "alpha_ratio_pegasus",
                          "yield_tolerance", "integration_tolerance", "beta_safety_factor", "minimum_mean_stress",
                          "suction_tolerance"})
    ip->get_double(opt, 0.0);
  for (const char* opt : {"drift_correction_algorithm", "tolerance_algorithm", "solution_algorithm"})
    ip->get_string(opt, "");
  return std::make_shared<MohrCoulomb>(m);
}

}  // namespace tephra
