#include "models/solid/CnhMms.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/ElasticPointLoop.h"

namespace tephra {

SolidPointResult cnh_mms_point(const Eigen::Matrix3d& F, double density0, const CnhMmsParams& p) {
  const double mu = p.shear_modulus, lambda = p.lambda();
  const double J = F.determinant();
  const double lnJ = std::log(J);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d B = F * F.transpose();
  SolidPointResult r;
  r.stress = (lambda * lnJ * I + mu * (B - I)) / J;
  r.energy_density = 0.5 * lambda * lnJ * lnJ - mu * lnJ + 0.5 * mu * (B.trace() - 3.0);
  r.wave_speed = std::sqrt((p.bulk_modulus + 4.0 * mu / 3.0) * J / density0);
  return r;
}

Eigen::Matrix3d cnh_mms_first_piola(const Eigen::Matrix3d& F, const CnhMmsParams& p) {
  const Eigen::Matrix3d FinvT = F.inverse().transpose();
  return p.shear_modulus * (F - FinvT) + p.lambda() * std::log(F.determinant()) * FinvT;
}

long CnhMms::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_elastic_points(in, out, [&](const Eigen::Matrix3d& F, double rho0) { return cnh_mms_point(F, rho0, p_); });
}

ConstitutiveModelP CnhMms::create(const ModelParameters& params) {
  CnhMmsParams p;
  p.bulk_modulus = params.get_double("bulk_modulus");
  p.shear_modulus = params.get_double("shear_modulus");
  if (!(p.bulk_modulus > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  if (!(p.shear_modulus > 0.0)) params.fail("shear_modulus", "shear_modulus must be > 0");
  if (params.get_bool("useModifiedEOS", false))
    params.missing_feature("useModifiedEOS", "cnh_mms with useModifiedEOS = true");
  return std::make_shared<CnhMms>(p);
}

}  // namespace tephra
