#include "mpmice/SolidEos.h"

#include "core/base/Errors.h"
#include "models/solid/CompNeoHookPlastic.h"

namespace tephra {

SolidEos::SolidEos(ConstitutiveModelP model, double density0, double p_ref, const DeckNode& where)
    : model_(std::move(model)), rho0_(density0), p_ref_(p_ref) {
  if (!model_->pressure_at_density(rho0_, rho0_, 300.0)) {
    // <useModifiedEOS> of comp_neo_hook_plastic / UCNH: the hook needs p_ref
    // and is offered as modified_eos_pressure (CompNeoHookPlastic.h).
    if (dynamic_cast<const CompNeoHookPlastic*>(model_.get()) != nullptr) {
      modified_neo_hookean_ = true;
    } else {
      where.missing_feature("constitutive_model '" + model_->type() +
                            "' in MPMICE (it has no pressure_at_density/density_at_pressure hooks yet)");
    }
  }
}

SolidEosPoint SolidEos::point(double rho, double T) const {
  if (modified_neo_hookean_) return modified_eos_pressure(rho, rho0_, model_->bulk_modulus(), p_ref_);
  return *model_->pressure_at_density(rho, rho0_, T);
}

double SolidEos::rho_at(double p_gauge, double T) const {
  if (modified_neo_hookean_) return modified_eos_density(p_gauge, rho0_, model_->bulk_modulus(), p_ref_);
  return *model_->density_at_pressure(p_gauge, rho0_, T);
}

void SolidEos::evaluate(std::span<const double> rho, std::span<const double> T, std::span<EosState> out) const {
  for (std::size_t i = 0; i < rho.size(); ++i) {
    const SolidEosPoint e = point(rho[i], T[i]);
    out[i] = {p_ref_ + e.pressure, e.dp_drho, 0.0, e.c2};
  }
}

void SolidEos::density(std::span<const double> p, std::span<const double> T, std::span<double> rho) const {
  for (std::size_t i = 0; i < p.size(); ++i) rho[i] = rho_at(p[i] - p_ref_, T[i]);
}

void SolidEos::thermal_expansivity(std::span<const double> rho, std::span<const double>, std::span<double> beta) const {
  for (std::size_t i = 0; i < rho.size(); ++i) beta[i] = 0.0;
}

}  // namespace tephra
