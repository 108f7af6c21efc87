#pragma once
// Ideal gas (Vaango/Uintah ICE "ideal_gas"; the theory manual uses it for air
// in every validation case without stating it, inventory ch. 24 "gaps"):
//   p = (gamma - 1) rho e,   e = cv T
//   dp/drho|_e = (gamma - 1) e,   dp/de|_rho = (gamma - 1) rho
//   c^2 = dp/drho + p/rho^2 dp/de = gamma (gamma - 1) cv T = gamma p / rho
//   rho(p, T) = p / ((gamma - 1) cv T),   beta = 1/T
// The constants come from the ICE material (<gamma>, <specific_heat>).
#include "models/eos/EquationOfState.h"

namespace tephra {

class IdealGas final : public EquationOfState {
 public:
  IdealGas(double gamma, double cv) : gamma_(gamma), cv_(cv) {}
  std::string type() const override { return "ideal_gas"; }

  static EosState state(double gamma, double cv, double rho, double T) {
    const double e = cv * T;
    EosState s;
    s.p = (gamma - 1.0) * rho * e;
    s.dp_drho = (gamma - 1.0) * e;
    s.dp_de = (gamma - 1.0) * rho;
    s.c2 = s.dp_drho + s.dp_de * s.p / (rho * rho);
    return s;
  }

  void evaluate(std::span<const double> rho, std::span<const double> T, std::span<EosState> out) const override;
  void density(std::span<const double> p, std::span<const double> T, std::span<double> rho) const override;
  void thermal_expansivity(std::span<const double> rho, std::span<const double> T,
                           std::span<double> beta) const override;

  double gamma() const { return gamma_; }
  double cv() const { return cv_; }

 private:
  double gamma_, cv_;
};

}  // namespace tephra
