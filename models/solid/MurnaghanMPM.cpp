#include "models/solid/MurnaghanMPM.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/ViscousFluid.h"

namespace tephra {

// Eq. 3.11 is the power-law fluid p = a (J^{-g} - 1) with a = K/K', g = K' (ViscousFluid.h).
double murnaghan_pressure(double J, const MurnaghanParams& p) { return power_law_pressure(J, p.K / p.Kprime, p.Kprime); }

long MurnaghanMPM::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_power_law_fluid(in, out, p_.K / p_.Kprime, p_.Kprime, p_.viscosity);  // eqs. 3.9-3.11
}

// Eq. 3.11 at J = rho0/rho on both sides of rho0 (the MPM stress's pressure);
// the inverse x = (1 + K' p / K)^{1/K'} is NaN for p <= -K/K'.
std::optional<SolidEosPoint> MurnaghanMPM::pressure_at_density(double rho, double density0, double) const {
  return power_law_eos_point(rho, density0, p_.K / p_.Kprime, p_.Kprime);
}

std::optional<double> MurnaghanMPM::density_at_pressure(double p_gauge, double density0, double) const {
  return power_law_density(p_gauge, density0, p_.K / p_.Kprime, p_.Kprime);
}

ConstitutiveModelP MurnaghanMPM::create(const ModelParameters& params) {
  MurnaghanParams p;
  p.K = params.get_double("K");
  p.Kprime = params.get_double("Kprime");
  p.P0 = params.get_double("pressure");
  p.rho0 = params.get_double("rho0");
  p.viscosity = params.get_double("viscosity");
  if (!(p.K > 0.0)) params.fail("K", "K must be > 0");
  if (!(p.Kprime > 0.0)) params.fail("Kprime", "Kprime must be > 0");
  if (!(p.P0 > 0.0)) params.fail("pressure", "pressure (the reference pressure P0) must be > 0");
  if (!(p.rho0 > 0.0)) params.fail("rho0", "rho0 must be > 0");
  if (!(p.viscosity >= 0.0)) params.fail("viscosity", "viscosity must be >= 0");
  const double density = params.enclosing_double("density", p.rho0);
  if (std::abs(density - p.rho0) > 1e-12 * p.rho0)
    params.fail("rho0", "rho0 must equal the material <density> (Tephra uses one reference density)");
  return std::make_shared<MurnaghanMPM>(p);
}

}  // namespace tephra
