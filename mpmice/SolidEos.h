#pragma once
// The equation of state of an MPM material as ICE's equilibration sees it
// (Vaango theory manual sec. 26.2: an MPM material in MPMICE supplies p(rho),
// dp/drho and rho(p); Uintah's computePressEOSCM / computeRhoMicroCM). It
// wraps the constitutive model's hooks, which return the gauge pressure
// p - p_ref, and adds the deck's <reference_pressure>:
//   p(rho, T) = p_ref + p_gauge(rho, rho0, T),   rho(p, T) = rho_gauge(p - p_ref).
// dp/de = 0 (the solid's pressure does not depend on its internal energy in
// these hooks) and the thermal expansivity is 0 (departure: Uintah's MPM
// materials have none in the specific-volume equation either unless the model
// sets one). A model without the hooks is a MissingFeature at deck reading.
#include <string>

#include "core/deck/DeckNode.h"
#include "models/eos/EquationOfState.h"
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

class SolidEos final : public EquationOfState {
 public:
  // Throws MissingFeature at `where` if `model` lacks the MPMICE hooks.
  SolidEos(ConstitutiveModelP model, double density0, double p_ref, const DeckNode& where);
  std::string type() const override { return "mpm:" + model_->type(); }
  void evaluate(std::span<const double> rho, std::span<const double> T, std::span<EosState> out) const override;
  void density(std::span<const double> p, std::span<const double> T, std::span<double> rho) const override;
  void thermal_expansivity(std::span<const double> rho, std::span<const double> T,
                           std::span<double> beta) const override;

 private:
  SolidEosPoint point(double rho, double T) const;
  double rho_at(double p, double T) const;  // absolute p
  ConstitutiveModelP model_;
  double rho0_, p_ref_;
};

}  // namespace tephra
