#include "mpmice/SolidEos.h"

#include "core/base/Errors.h"
#include "models/solid/AbsolutePressureEos.h"
#include "models/solid/ModifiedEos.h"

namespace tephra {

SolidEos::SolidEos(ConstitutiveModelP model, double density0, double p_ref, const DeckNode& where)
    : model_(std::move(model)), rho0_(density0), p_ref_(p_ref) {
  if (!model_->pressure_at_density(rho0_, rho0_, 300.0) &&
      !absolute_pressure_eos(*model_))
    where.missing_feature("constitutive_model '" + model_->type() +
                          "' in MPMICE (it has no pressure_at_density/density_at_pressure hooks yet)");
  if (model_->modified_eos() && !(p_ref_ > 0.0))
    where.fail("useModifiedEOS of constitutive_model '" + model_->type() +
               "' needs a positive reference pressure (p = p_ref (rho/rho0)^(K/p_ref) in expansion)");
}

// The model's hooks, or with <useModifiedEOS> the expansion branch of models/solid/ModifiedEos.h,
// in absolute pressure (a pressure far below p_ref keeps its digits).
SolidEosPoint SolidEos::point(double rho, double T) const {
  return *mpmice_absolute_pressure_at_density(*model_, rho, rho0_, T, p_ref_);
}

double SolidEos::rho_at(double p, double T) const {
  return *mpmice_density_at_absolute_pressure(*model_, p, rho0_, T, p_ref_);
}

void SolidEos::evaluate(std::span<const double> rho, std::span<const double> T, std::span<EosState> out) const {
  for (std::size_t i = 0; i < rho.size(); ++i) {
    const SolidEosPoint e = point(rho[i], T[i]);
    out[i] = {e.pressure, e.dp_drho, 0.0, e.c2};
  }
}

void SolidEos::density(std::span<const double> p, std::span<const double> T, std::span<double> rho) const {
  for (std::size_t i = 0; i < p.size(); ++i) rho[i] = rho_at(p[i], T[i]);
}

void SolidEos::thermal_expansivity(std::span<const double> rho, std::span<const double>, std::span<double> beta) const {
  for (std::size_t i = 0; i < rho.size(); ++i) beta[i] = 0.0;
}

}  // namespace tephra
