#include "models/solid/MurnaghanMPM.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/ViscousFluid.h"

namespace tephra {

double murnaghan_pressure(double J, const MurnaghanParams& p) {
  return (p.K / p.Kprime) * std::expm1(-p.Kprime * std::log(J));
}

long MurnaghanMPM::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const double p = murnaghan_pressure(J, p_);
    const Eigen::Matrix3d tau = viscous_shear_stress(in.L[i], p_.viscosity);
    out.stress[i] = -p * I + tau;  // eq. 3.9
    out.energy_density[i] = power_law_energy(J, p_.K / p_.Kprime, p_.Kprime);
    out.wave_speed[i] = std::sqrt(p_.K * std::pow(J, -(p_.Kprime + 1.0)) * J / in.density0);
    out.plastic_work[i] = p_.viscosity > 0.0 ? J * tau.squaredNorm() / (2.0 * p_.viscosity) * in.dt : 0.0;
    out.heating[i] = 0.0;  // Vaango: pdTdt = 0
    return out.stress[i].allFinite();
  });
}

std::optional<SolidEosPoint> MurnaghanMPM::pressure_at_density(double rho, double density0, double) const {
  // Eq. 3.11 at J = rho0/rho on both sides of rho0 (the MPM stress's pressure).
  SolidEosPoint e;
  const double lnx = std::log(rho / density0);
  e.pressure = (p_.K / p_.Kprime) * std::expm1(p_.Kprime * lnx);
  e.dp_drho = (p_.K / density0) * std::exp((p_.Kprime - 1.0) * lnx);
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> MurnaghanMPM::density_at_pressure(double p_gauge, double density0, double) const {
  // x = (1 + K' p / K)^{1/K'}; NaN for p < -K/K' (no density gives such a tension).
  return density0 * std::exp(std::log1p(p_.Kprime * p_gauge / p_.K) / p_.Kprime);
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
