#pragma once
// Vaango's ideal gas material (class IdealGasMaterial: models/eos has the ICE IdealGas), type "ideal_gas" (VT §3.2, eqs. 3.3-3.5; Vaango
// class IdealGasMP). Explicit MPM only. An isentropic gas without tension:
//
//   p(J) = p_ref [exp(gamma eps_v) - 1] = p_ref (J^{-gamma} - 1)  for J < 1,  0 for J >= 1   (3.4)
//   sigma = -p I                                                                      (3.3)
//   dT/dt = (1/dt) (1 - J_{n+1}/J_n) p / (rho c_v),   rho = rho0 / J_{n+1}            (3.5)
//
// (the manual writes sigma = p_bar I with p_bar = -p: compression negative).
// Stored energy W(J) = p_ref [(J^{1-gamma} - 1)/(gamma - 1) + J - 1] for J < 1, 0 otherwise,
// so sigma = W'(J) I (hyperelastic). Wave speed: the isentropic sound speed of the
// absolute pressure P = p + p_ref, c^2 = gamma P / rho (= gamma p_ref / rho0 at J = 1;
// Vaango's stable-time-step estimate uses gamma p_ref too). Small-strain moduli
// K = gamma p_ref (dp/dJ at J = 1), G = 0.
//
// MPMICE hooks (Vaango IdealGasMP::computePressEOSCM / computeRhoMicroCM): the
// thermal ideal-gas law P = (gamma - 1) rho c_v T. Vaango returns the absolute P;
// Tephra's hooks return a gauge pressure, p_gauge = P - p_ref with this model's
// <reference_pressure> (the two agree when the ICE reference pressure equals it).
//   dp/drho = (gamma - 1) c_v T,  c^2 = dp/drho + dp/de P/rho^2 = gamma P / rho.
//   rho(p_gauge) = (p_gauge + p_ref) / ((gamma - 1) c_v T).
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct IdealGasParams {
  double gamma = 0.0;                  // <gamma>, ratio of specific heats [-] (> 1)
  double cv = 0.0;                     // <specific_heat>, c_v [J/(kg K)] (> 0)
  double reference_pressure = 101325;  // <reference_pressure>, p_ref [Pa] (Vaango default)
  double reference_temperature = 298;  // <reference_temperature> [K] (Vaango default; read, unused by VT 3.3-3.5)
};

// p(J) of eq. 3.4 (no tension: 0 for J >= 1).
double ideal_gas_pressure(double J, const IdealGasParams& p);

class IdealGasMaterial final : public ConstitutiveModel {
 public:
  explicit IdealGasMaterial(const IdealGasParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "ideal_gas"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.gamma * p_.reference_pressure; }
  double shear_modulus() const override { return 0.0; }
  bool hyperelastic() const override { return true; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

 private:
  IdealGasParams p_;
};

}  // namespace tephra
