#include "models/solid/Water.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/ViscousFluid.h"

namespace tephra {

double water_pressure(double J, const WaterParams& p) { return p.kappa * std::expm1(-p.gamma * std::log(J)); }

long Water::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const double p = water_pressure(J, p_);
    const Eigen::Matrix3d tau = viscous_shear_stress(in.L[i], p_.viscosity);
    out.stress[i] = -p * I + tau;  // eq. 3.6
    out.energy_density[i] = power_law_energy(J, p_.kappa, p_.gamma);
    out.wave_speed[i] = std::sqrt(p_.gamma * p_.kappa * std::pow(J, -p_.gamma) * J / in.density0);
    // Viscous dissipation of the step per reference volume: J (tau : d) dt, tau : d = tau : eta >= 0.
    out.plastic_work[i] = p_.viscosity > 0.0 ? J * tau.squaredNorm() / (2.0 * p_.viscosity) * in.dt : 0.0;
    out.heating[i] = 0.0;  // Vaango: pdTdt = 0
    return out.stress[i].allFinite();
  });
}

std::optional<SolidEosPoint> Water::pressure_at_density(double rho, double density0, double) const {
  SolidEosPoint e;
  const double x = rho / density0;
  e.pressure = p_.kappa * std::expm1(p_.gamma * std::log(x));
  e.dp_drho = p_.gamma * p_.kappa * std::pow(x, p_.gamma - 1.0) / density0;
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> Water::density_at_pressure(double p_gauge, double density0, double) const {
  const double q = p_gauge / p_.kappa;
  if (!(q > -1.0)) return std::numeric_limits<double>::quiet_NaN();
  return density0 * std::exp(std::log1p(q) / p_.gamma);
}

ConstitutiveModelP Water::create(const ModelParameters& params) {
  WaterParams p;
  p.kappa = params.get_double("bulk_modulus");
  p.viscosity = params.get_double("viscosity");
  p.gamma = params.get_double("gamma");
  if (!(p.kappa > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  if (!(p.gamma > 0.0)) params.fail("gamma", "gamma must be > 0");
  if (!(p.viscosity >= 0.0)) params.fail("viscosity", "viscosity must be >= 0");
  return std::make_shared<Water>(p);
}

}  // namespace tephra
