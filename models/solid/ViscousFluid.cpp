#include "models/solid/ViscousFluid.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/PointLoop.h"

namespace tephra {

double power_law_energy(double J, double a, double g) {
  const double lnJ = std::log(J);
  if (std::abs(g - 1.0) < 1e-12) return a * (-lnJ + (J - 1.0));
  // (J^{1-g} - 1)/(g - 1) = expm1((1 - g) ln J)/(g - 1): exact 0 at J = 1.
  return a * (std::expm1((1.0 - g) * lnJ) / (g - 1.0) + (J - 1.0));
}

double power_law_pressure(double J, double a, double g) { return a * std::expm1(-g * std::log(J)); }

long update_power_law_fluid(const SolidUpdateInput& in, const SolidUpdateOutput& out, double a, double g,
                            double mu) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const double p = power_law_pressure(J, a, g);
    const Eigen::Matrix3d tau = viscous_shear_stress(in.L[i], mu);
    out.stress[i] = -p * I + tau;  // VT eq. 3.6 / 3.9
    out.energy_density[i] = power_law_energy(J, a, g);
    out.wave_speed[i] = std::sqrt(g * a * std::pow(J, -g) * J / in.density0);
    // Viscous dissipation of the step per reference volume: J (tau : d) dt, tau : d = tau : eta >= 0.
    out.plastic_work[i] = mu > 0.0 ? J * tau.squaredNorm() / (2.0 * mu) * in.dt : 0.0;
    out.heating[i] = 0.0;
    return out.stress[i].allFinite();
  });
}

SolidEosPoint power_law_eos_point(double rho, double density0, double a, double g) {
  const double lnx = std::log(rho / density0);
  SolidEosPoint e;
  e.pressure = a * std::expm1(g * lnx);
  e.dp_drho = a * g * std::exp((g - 1.0) * lnx) / density0;
  e.c2 = e.dp_drho;
  return e;
}

double power_law_density(double p_gauge, double density0, double a, double g) {
  const double q = p_gauge / a;
  if (!(q > -1.0)) return std::numeric_limits<double>::quiet_NaN();
  return density0 * std::exp(std::log1p(q) / g);
}

}  // namespace tephra
