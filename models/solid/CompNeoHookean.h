#pragma once
// Vaango's compressible neo-Hookean solid, type "comp_neo_hook" (Vaango class
// CompNeoHook with useModifiedEOS = false), in the uncoupled volumetric /
// isochoric form of Simo & Hughes, "Computational Inelasticity" (1998) §9.2:
//
//   J = det F,  B = F F^T,  Bbar = J^{-2/3} B
//   W(F) = U(J) + G/2 (tr Bbar - 3),      U(J) = K/2 [ (J^2 - 1)/2 - ln J ]
//   sigma = U'(J) I + (G/J) dev(Bbar) = K/2 (J - 1/J) I + G J^{-5/3} dev(B)
//
// W is per unit reference volume; sigma = (1/J) dW/dF F^T follows from it.
// The stress is the one Vaango's CompNeoHook::computeStressTensor evaluates
// (p = 0.5 K (J - 1/J), deviatoric part = G dev(Bbar)/J), and W is the energy
// density it sums into StrainEnergy (times the reference volume).
// Wave speed (as Vaango's UCNH, the class behind "comp_neo_hook", with its default
// HyperElasticEOS): c = sqrt((K_t + 4G/3) / rho), rho = rho0 / J the current density,
// K_t = dp/dJ = K/2 (1 + 1/J^2) the tangent bulk modulus (K at J = 1).
// Small-strain limit: sigma -> K tr(eps) I + 2G dev(eps) (linear elasticity).
#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct CompNeoHookeanParams {
  double bulk_modulus = 0.0;   // K [Pa], deck <bulk_modulus>
  double shear_modulus = 0.0;  // G [Pa], deck <shear_modulus>
};

// The point function. Precondition: det F > 0 (the caller checks).
SolidPointResult comp_neo_hookean_point(const Eigen::Matrix3d& F, double density0,
                                        const CompNeoHookeanParams& p);

class CompNeoHookean final : public ConstitutiveModel {
 public:
  explicit CompNeoHookean(const CompNeoHookeanParams& p) : p_(p) {}
  // Reads <bulk_modulus>, <shear_modulus> (> 0) and <useModifiedEOS> (only false).
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "comp_neo_hook"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.bulk_modulus; }
  double shear_modulus() const override { return p_.shear_modulus; }
  bool hyperelastic() const override { return true; }
  // p(rho) = -U'(J) at J = rho0/rho = K/2 (rho/rho0 - rho0/rho) (Vaango UCNH's
  // HyperElasticEOS), dp/drho = K/2 (1/rho0 + rho0/rho^2), c^2 = dp/drho.
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  // Inverse: x = rho/rho0 solves x^2 - (2p/K) x - 1 = 0, x = p/K + sqrt((p/K)^2 + 1).
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  const CompNeoHookeanParams& params() const { return p_; }

 private:
  CompNeoHookeanParams p_;
};

}  // namespace tephra
