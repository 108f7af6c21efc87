#include "models/solid/CnhDamage.h"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"

namespace tephra {

double cnh_damage_criterion(const Eigen::Matrix3d& F, const Eigen::Matrix3d& intact_stress,
                            const CnhDamageParams& p) {
  Eigen::Matrix3d A;
  if (p.failure_by_stress) {
    A = 0.5 * (intact_stress + intact_stress.transpose());
  } else {
    A = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());  // Green-Lagrange strain
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(A, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();  // eigenvalues ascending; maxCoeff guards the order
}

std::vector<HistoryVariable> CnhDamage::history() const {
  return {{"localized", 1, {0.0}, "failure flag: 0 intact, 1 failed (eroded, zero stress) [-]"}};
}

long CnhDamage::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const SolidPointResult r = comp_neo_hookean_point(in.F_new[i], in.density0, p_.elastic);
    if (!r.stress.allFinite()) return false;
    double& localized = out.history[0][i];
    double released = 0.0;
    if (localized == 0.0 && cnh_damage_criterion(in.F_new[i], r.stress, p_) > p_.failure_threshold) {
      localized = 1.0;
      released = r.energy_density;  // the stored energy lost with the stress
    }
    const bool failed = localized != 0.0;
    out.stress[i] = failed ? Eigen::Matrix3d::Zero() : r.stress;
    out.energy_density[i] = failed ? 0.0 : r.energy_density;
    out.wave_speed[i] = r.wave_speed;  // intact material speed, kept for the time step
    out.plastic_work[i] = released;
    out.heating[i] = 0.0;
    return true;
  });
}

ConstitutiveModelP CnhDamage::create(const ModelParameters& params) {
  CnhDamageParams p;
  p.elastic.bulk_modulus = params.get_double("bulk_modulus");
  p.elastic.shear_modulus = params.get_double("shear_modulus");
  if (!(p.elastic.bulk_modulus > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  if (!(p.elastic.shear_modulus > 0.0)) params.fail("shear_modulus", "shear_modulus must be > 0");
  p.failure_threshold = params.get_double("failure_variable_mean");
  if (!(p.failure_threshold > 0.0))
    params.fail("failure_variable_mean", "failure_variable_mean (failure threshold) must be > 0");
  p.failure_by_stress = params.get_bool("failure_by_stress", false);
  if (params.get_double("failure_variable_std", 0.0) != 0.0)
    params.missing_feature("failure_variable_std",
                           "cnh_damage random failure thresholds (failure_variable_std != 0, distrib " +
                               params.get_string("failure_variable_distrib", "constant") + ")");
  if (params.get_bool("useModifiedEOS", false))
    params.missing_feature("useModifiedEOS", "cnh_damage with useModifiedEOS = true");
  return std::make_shared<CnhDamage>(p);
}

}  // namespace tephra
