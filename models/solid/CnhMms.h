#pragma once
// Vaango's "cnh_mms": the compressible neo-Hookean solid its manufactured
// solutions are built on (Vaango CNH_MMS::computeStressTensor):
//   sigma = [ lambda ln J I + mu (F F^T - I) ] / J,   lambda = K - 2 mu / 3,
// the Cauchy stress of W(F) = lambda/2 (ln J)^2 - mu ln J + mu/2 (tr C - 3)
// (per reference volume; Vaango sums no strain energy for this model, Tephra
// reports this W). First Piola-Kirchhoff stress (used by the MMS body forces):
//   P = J sigma F^{-T} = mu (F - F^{-T}) + lambda ln J F^{-T}.
// Wave speed as Vaango: c = sqrt((K + 4 mu / 3) / rho), rho = rho0 / J.
// Small-strain limit: sigma -> lambda tr(eps) I + 2 mu eps.
#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct CnhMmsParams {
  double bulk_modulus = 0.0;   // K [Pa], <bulk_modulus>
  double shear_modulus = 0.0;  // mu [Pa], <shear_modulus>
  double lambda() const { return bulk_modulus - 2.0 * shear_modulus / 3.0; }
};

SolidPointResult cnh_mms_point(const Eigen::Matrix3d& F, double density0, const CnhMmsParams& p);
// P(F) = mu (F - F^{-T}) + lambda ln J F^{-T}.
Eigen::Matrix3d cnh_mms_first_piola(const Eigen::Matrix3d& F, const CnhMmsParams& p);

class CnhMms final : public ConstitutiveModel {
 public:
  explicit CnhMms(const CnhMmsParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "cnh_mms"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.bulk_modulus; }
  double shear_modulus() const override { return p_.shear_modulus; }
  bool hyperelastic() const override { return true; }
  const CnhMmsParams& params() const { return p_; }

 private:
  CnhMmsParams p_;
};

}  // namespace tephra
