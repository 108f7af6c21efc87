#pragma once
// Vaango's rigid material, type "rigid" (Vaango class RigidMaterial; VT §3.1):
//
//   sigma(F, t) = 0  and  F(t) = I                                  (VT eq. 3.1)
//
// The particles move with the grid velocity; the driver keeps F = I (so the
// volume stays V0) because rigid() is true. No strain energy, no wave speed
// (c = 0: the material puts no limit on the step beyond dx/|v|; Vaango puts
// a fixed dt = 1 instead). It acts as a rigid surface only with the
// specified-velocity contact (VT eq. 1.110, 3.2).
// Parameters: <shear_modulus>, <bulk_modulus> [Pa], optional, Vaango default
// 1e200; they enter only the MPMICE pressure hooks (Vaango computePressEOSCM:
// p = p_ref, dp/drho = c^2 = K/rho0; computeRhoMicroCM: rho = rho0).
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

class RigidMaterial final : public ConstitutiveModel {
 public:
  RigidMaterial(double bulk, double shear) : K_(bulk), G_(shear) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "rigid"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return K_; }
  double shear_modulus() const override { return G_; }
  bool rigid() const override { return true; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

 private:
  double K_, G_;
};

}  // namespace tephra
