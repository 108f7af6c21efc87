#include "models/solid/Water.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/ViscousFluid.h"

namespace tephra {

double water_pressure(double J, const WaterParams& p) { return power_law_pressure(J, p.kappa, p.gamma); }

long Water::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_power_law_fluid(in, out, p_.kappa, p_.gamma, p_.viscosity);  // eqs. 3.6-3.8
}

std::optional<SolidEosPoint> Water::pressure_at_density(double rho, double density0, double) const {
  return power_law_eos_point(rho, density0, p_.kappa, p_.gamma);
}

std::optional<double> Water::density_at_pressure(double p_gauge, double density0, double) const {
  return power_law_density(p_gauge, density0, p_.kappa, p_.gamma);
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
