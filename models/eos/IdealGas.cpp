#include "models/eos/IdealGas.h"

namespace tephra {

void IdealGas::evaluate(std::span<const double> rho, std::span<const double> T, std::span<EosState> out) const {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = state(gamma_, cv_, rho[i], T[i]);
}

void IdealGas::density(std::span<const double> p, std::span<const double> T, std::span<double> rho) const {
  const double r = (gamma_ - 1.0) * cv_;
  for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = p[i] / (r * T[i]);
}

// v = (gamma - 1) cv T / p, so (1/v) dv/dT|_p = 1/T.
void IdealGas::thermal_expansivity(std::span<const double>, std::span<const double> T,
                                   std::span<double> beta) const {
  for (std::size_t i = 0; i < beta.size(); ++i) beta[i] = 1.0 / T[i];
}

}  // namespace tephra
