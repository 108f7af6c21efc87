#include "models/solid/CnhMms.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"

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
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const SolidPointResult r = cnh_mms_point(in.F_new[i], in.density0, p_);
    if (!r.stress.allFinite()) return false;
    out.stress[i] = r.stress;
    out.wave_speed[i] = r.wave_speed;
    out.energy_density[i] = r.energy_density;
    out.plastic_work[i] = 0.0;  // elastic: no dissipation, no heating
    out.heating[i] = 0.0;
    return true;
  });
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
