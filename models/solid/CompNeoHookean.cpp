#include "models/solid/CompNeoHookean.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/ElasticPointLoop.h"

namespace tephra {

SolidPointResult comp_neo_hookean_point(const Eigen::Matrix3d& F, double density0,
                                        const CompNeoHookeanParams& p) {
  const double K = p.bulk_modulus, G = p.shear_modulus;
  const double J = F.determinant();
  const Eigen::Matrix3d B = F * F.transpose();
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  // Bbar = J^{-2/3} B: the isochoric left Cauchy-Green tensor (det Bbar = 1).
  const Eigen::Matrix3d Bbar = std::pow(J, -2.0 / 3.0) * B;
  const double trBbar = Bbar.trace();
  const Eigen::Matrix3d devBbar = Bbar - (trBbar / 3.0) * I;

  SolidPointResult r;
  // sigma = K/2 (J - 1/J) I + (G/J) dev(Bbar)   (Simo & Hughes 1998, eq. 9.2.x; Vaango CompNeoHook)
  r.stress = (0.5 * K * (J - 1.0 / J)) * I + (G / J) * devBbar;
  // W = K/2 [ (J^2-1)/2 - ln J ] + G/2 (tr Bbar - 3), per reference volume.
  r.energy_density = 0.5 * K * (0.5 * (J * J - 1.0) - std::log(J)) + 0.5 * G * (trBbar - 3.0);
  // Dilatational wave speed in the current configuration, as Vaango's UCNH
  // (the class behind "comp_neo_hook") evaluates it from its default
  // HyperElasticEOS: c^2 = (K_t + 4G/3) / rho, rho = rho0/J, with the tangent
  // bulk modulus K_t = dp/dJ = K/2 (1 + 1/J^2) (= K at J = 1).
  const double rho = density0 / J;
  const double K_t = 0.5 * K * (1.0 + 1.0 / (J * J));
  r.wave_speed = std::sqrt((K_t + 4.0 * G / 3.0) / rho);
  return r;
}

long CompNeoHookean::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_elastic_points(in, out, [&](const Eigen::Matrix3d& F, double rho0) { return comp_neo_hookean_point(F, rho0, p_); });
}

std::optional<SolidEosPoint> CompNeoHookean::pressure_at_density(double rho, double density0, double) const {
  const double K = p_.bulk_modulus;
  SolidEosPoint e;
  e.pressure = 0.5 * K * (rho / density0 - density0 / rho);
  e.dp_drho = 0.5 * K * (1.0 / density0 + density0 / (rho * rho));
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> CompNeoHookean::density_at_pressure(double p_gauge, double density0, double) const {
  const double q = p_gauge / p_.bulk_modulus;
  return density0 * (q + std::sqrt(q * q + 1.0));
}

ConstitutiveModelP CompNeoHookean::create(const ModelParameters& params) {
  CompNeoHookeanParams p;
  p.bulk_modulus = params.get_double("bulk_modulus");
  p.shear_modulus = params.get_double("shear_modulus");
  if (!(p.bulk_modulus > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  if (!(p.shear_modulus > 0.0)) params.fail("shear_modulus", "shear_modulus must be > 0");
  // Vaango's optional modified EOS (a different pressure in compression) is not implemented.
  if (params.get_bool("useModifiedEOS", false))
    params.missing_feature("useModifiedEOS", "comp_neo_hook with useModifiedEOS = true");
  return std::make_shared<CompNeoHookean>(p);
}

}  // namespace tephra
