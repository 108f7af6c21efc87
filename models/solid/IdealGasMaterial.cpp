#include "models/solid/IdealGasMaterial.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/ViscousFluid.h"

namespace tephra {

double ideal_gas_pressure(double J, const IdealGasParams& p) {
  if (J >= 1.0) return 0.0;  // eps_v = 0 for J >= 1 (eq. 3.4): no tension
  return p.reference_pressure * std::expm1(-p.gamma * std::log(J));  // p_ref [exp(gamma eps_v) - 1]
}

long IdealGasMaterial::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J = in.F_new[i].determinant();
    const double J_old = in.F_old[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J) || !(J_old > 0.0)) return false;
    const double p = ideal_gas_pressure(J, p_);
    const double rho = in.density0 / J;
    out.stress[i] = -p * I;  // eq. 3.3
    out.energy_density[i] = J < 1.0 ? power_law_energy(J, p_.reference_pressure, p_.gamma) : 0.0;
    out.wave_speed[i] = std::sqrt(p_.gamma * (p + p_.reference_pressure) / rho);
    out.plastic_work[i] = 0.0;
    // eq. 3.5: compression (J_new < J_old) heats the gas.
    out.heating[i] = in.dt > 0.0 ? (1.0 - J / J_old) * p / (rho * p_.cv) / in.dt : 0.0;
    return std::isfinite(p) && std::isfinite(out.heating[i]);
  });
}

std::optional<SolidEosPoint> IdealGasMaterial::pressure_at_density(double rho, double, double T) const {
  SolidEosPoint e;
  const double P = (p_.gamma - 1.0) * rho * p_.cv * T;  // absolute pressure
  e.pressure = P - p_.reference_pressure;
  e.dp_drho = (p_.gamma - 1.0) * p_.cv * T;
  e.c2 = p_.gamma * P / rho;  // dp/drho + dp/de P/rho^2, dp/de = (gamma - 1) rho
  return e;
}

std::optional<double> IdealGasMaterial::density_at_pressure(double p_gauge, double, double T) const {
  return (p_gauge + p_.reference_pressure) / ((p_.gamma - 1.0) * p_.cv * T);
}

ConstitutiveModelP IdealGasMaterial::create(const ModelParameters& params) {
  IdealGasParams p;
  p.gamma = params.get_double("gamma");
  p.cv = params.get_double("specific_heat");
  p.reference_pressure = params.get_double("reference_pressure", p.reference_pressure);
  p.reference_temperature = params.get_double("reference_temperature", p.reference_temperature);
  if (!(p.gamma > 1.0)) params.fail("gamma", "gamma must be > 1");
  if (!(p.cv > 0.0)) params.fail("specific_heat", "specific_heat must be > 0");
  if (!(p.reference_pressure > 0.0)) params.fail("reference_pressure", "reference_pressure must be > 0");
  if (!(p.reference_temperature > 0.0)) params.fail("reference_temperature", "reference_temperature must be > 0");
  return std::make_shared<IdealGasMaterial>(p);
}

}  // namespace tephra
