#include "models/solid/ModifiedEos.h"

#include <cmath>

#include "models/solid/AbsolutePressureEos.h"

namespace tephra {

SolidEosPoint modified_eos_expansion(double rho, double density0, double K0, double p_ref) {
  const double n = K0 / p_ref;
  const double rn = std::pow(rho / density0, n);
  SolidEosPoint e;
  e.pressure = p_ref * rn - p_ref;
  e.dp_drho = (K0 / rho) * rn;
  e.c2 = e.dp_drho;
  return e;
}

double modified_eos_expansion_density(double p_gauge, double density0, double K0, double p_ref) {
  return density0 * std::pow((p_gauge + p_ref) / p_ref, p_ref / K0);
}

namespace {
// K0 = rho0 dp/drho at rho0 of the compression branch.
std::optional<double> reference_bulk_modulus(const ConstitutiveModel& model, double density0, double T) {
  const auto e = model.pressure_at_density(density0, density0, T);
  if (!e) return std::nullopt;
  return density0 * e->dp_drho;
}
}  // namespace

std::optional<SolidEosPoint> mpmice_pressure_at_density(const ConstitutiveModel& model, double rho, double density0,
                                                        double T, double p_ref) {
  if (const AbsolutePressureEos* a = absolute_pressure_eos(model)) {
    SolidEosPoint e = a->absolute_pressure_at_density(rho, density0, T, p_ref);
    e.pressure -= p_ref;
    return e;
  }
  if (!model.modified_eos() || rho >= density0) return model.pressure_at_density(rho, density0, T);
  const auto K0 = reference_bulk_modulus(model, density0, T);
  if (!K0) return std::nullopt;
  return modified_eos_expansion(rho, density0, *K0, p_ref);
}

std::optional<double> mpmice_density_at_pressure(const ConstitutiveModel& model, double p_gauge, double density0,
                                                 double T, double p_ref) {
  if (const AbsolutePressureEos* a = absolute_pressure_eos(model))
    return a->density_at_absolute_pressure(p_gauge + p_ref, density0, T, p_ref);
  if (!model.modified_eos() || p_gauge >= 0.0) return model.density_at_pressure(p_gauge, density0, T);
  const auto K0 = reference_bulk_modulus(model, density0, T);
  if (!K0) return std::nullopt;
  return modified_eos_expansion_density(p_gauge, density0, *K0, p_ref);
}

std::optional<SolidEosPoint> mpmice_absolute_pressure_at_density(const ConstitutiveModel& model, double rho,
                                                                 double density0, double T, double p_ref) {
  if (const AbsolutePressureEos* a = absolute_pressure_eos(model))
    return a->absolute_pressure_at_density(rho, density0, T, p_ref);
  std::optional<SolidEosPoint> e;
  if (!model.modified_eos() || rho >= density0) {
    e = model.pressure_at_density(rho, density0, T);
    if (e) e->pressure += p_ref;
    return e;
  }
  const auto K0 = reference_bulk_modulus(model, density0, T);
  if (!K0) return std::nullopt;
  e = modified_eos_expansion(rho, density0, *K0, p_ref);
  e->pressure = p_ref * std::pow(rho / density0, *K0 / p_ref);  // absolute, no p_ref - p_ref
  return e;
}

std::optional<double> mpmice_density_at_absolute_pressure(const ConstitutiveModel& model, double p, double density0,
                                                          double T, double p_ref) {
  if (const AbsolutePressureEos* a = absolute_pressure_eos(model))
    return a->density_at_absolute_pressure(p, density0, T, p_ref);
  if (!model.modified_eos() || p >= p_ref) return model.density_at_pressure(p - p_ref, density0, T);
  const auto K0 = reference_bulk_modulus(model, density0, T);
  if (!K0) return std::nullopt;
  return density0 * std::pow(p / p_ref, p_ref / *K0);
}

}  // namespace tephra
