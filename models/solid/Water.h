#pragma once
// Vaango's water material, type "water" (VT §3.3, eqs. 3.6-3.8; Vaango class
// Water). Explicit MPM only; the manual: "not validated, but gives qualitatively
// reasonable behavior".
//
//   sigma = -p I + 2 mu eta,  eta = dev(d), d = sym(l)      (3.6-3.7)
//   p(J) = kappa (J^{-gamma} - 1)                           (3.8)
//
// Stored energy of the pressure part W(J) = kappa [(J^{1-gamma} - 1)/(gamma - 1) + J - 1]
// (sigma_vol = W'(J) I); the viscous part dissipates 2 mu eta:eta per unit
// current volume and time, reported as plastic_work = J 2 mu eta:eta dt per
// reference volume. Wave speed (Vaango): c^2 = gamma kappa J^{-gamma} / rho, rho = rho0/J.
// Small-strain moduli: K = gamma kappa (= -dp/dJ at J = 1), G = 0.
//
// MPMICE hooks: the same EOS in density form, J = rho0/rho,
//   p = kappa ((rho/rho0)^gamma - 1),  dp/drho = gamma kappa rho^{gamma-1} / rho0^gamma = c^2,
//   rho(p) = rho0 (1 + p/kappa)^{1/gamma}   (NaN for p <= -kappa: no density gives it).
// Deviation: Vaango's Water::computePressEOSCM uses the compressible neo-Hookean
// pressure 0.5 kappa (rho/rho0 - rho0/rho) instead, inconsistent with eq. 3.8;
// Tephra uses eq. 3.8 so MPM and MPMICE see one material.
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct WaterParams {
  double kappa = 0.0;      // <bulk_modulus> kappa [Pa] (> 0)
  double gamma = 0.0;      // <gamma> [-] (> 0)
  double viscosity = 0.0;  // <viscosity> mu [Pa s] (>= 0)
};

double water_pressure(double J, const WaterParams& p);  // eq. 3.8

class Water final : public ConstitutiveModel {
 public:
  explicit Water(const WaterParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "water"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.gamma * p_.kappa; }
  double shear_modulus() const override { return 0.0; }
  // sigma depends on F only when there is no viscosity.
  bool hyperelastic() const override { return p_.viscosity == 0.0; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

 private:
  WaterParams p_;
};

}  // namespace tephra
