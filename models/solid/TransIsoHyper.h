#pragma once
// Transversely isotropic hyperelastic solid (Weiss, Maker & Govindjee, CMAME 135
// (1996) 107), type "trans_iso_hyper" (VT §4.2.3, eqs. 4.13-4.19; Vaango class
// TransIsoHyper). A Mooney-Rivlin matrix reinforced by fibres along the
// reference unit vector a0 (<direction_of_symm>):
//
//   W = W_v + W_d,  W_v = kappa/2 (ln J)^2                                   (4.13-4.14)
//   W_d = C1 (I1b - 3) + C2 (I2b - 3) + W_f(lb),  lb = sqrt(a0 . Cb a0),  Cb = J^{-2/3} F^T F   (4.15-4.16)
//   lb dW_f/dlb = 0                         for lb < 1 (fibres carry no compression)
//               = C3 [exp(C4 (lb - 1)) - 1]   for 1 <= lb < lambda*
//               = C5 lb + C6                  for lb >= lambda*,  C6 = C3[exp(C4(lambda*-1)) - 1] - C5 lambda*
//   sigma = p I + sigma_d + sigma_f,  p = kappa ln J / J                      (4.18-4.19)
//   sigma_d = (2/J)[(C1 + C2 I1b) Bb - C2 Bb^2 - (C1 I1b + 2 C2 I2b)/3 I]
//   sigma_f = (lb dW_f/dlb / J)(f (x) f - I/3),  f = J^{-1/3} F a0 / lb      (4.17: the convected fibre)
//
// ERRATUM (VT eq. 4.15): as printed, W_d = ... + C3[exp(C4(lb - 1)) - 1] would give
// sigma_f = C3 C4 (f f - I/3) at F = I; the stress of eqs. 4.19 with Weiss's
// lb dW_f/dlb above (what Vaango evaluates, C6 as Vaango) is zero at F = I.
// Its energy, for W's reported value: W_f = C3 [e^{-C4} (Ei(C4 lb) - Ei(C4)) - ln lb]
// on [1, lambda*), continued by C5 (lb - lambda*) + C6 ln(lb/lambda*) (Ei = std::expint).
// The fibre is computed from F and a0 (eq. 4.17 applied to the total F), so the
// model is path independent and hyperelastic.
// Small-strain moduli K = kappa, G = 2 (C1 + C2) (the matrix; the fibres stiffen
// only in tension). Wave speed c^2 = (K + 4G/3 + E_f) J / rho0 with the fibre
// tangent E_f = d(lb dW_f/dlb)/dlb (C3 C4 e^{C4(lb-1)} or C5) for lb > 1, 0 otherwise
// (it jumps at lb = 1: the fibres are bilinear).
// Failure (<failure_option> true: matrix failure when max - min eigenvalue of C
// exceeds <max_matrix_strain>, fibre failure when lb exceeds <max_fiber_strain>) is
// not implemented: MissingFeature. <useModifiedEOS> true: MissingFeature.
#include <string>

#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct TransIsoHyperParams {
  double kappa = 0;                    // <bulk_modulus> [Pa]
  double C1 = 0, C2 = 0;               // <c1>, <c2> Mooney-Rivlin [Pa]
  double C3 = 0;                       // <c3> exponential fibre stress scale [Pa]
  double C4 = 0;                       // <c4> fibre uncrimping rate [-] (> 0)
  double C5 = 0;                       // <c5> straightened-fibre modulus [Pa]
  double lambda_star = 1;              // <fiber_stretch> lambda* [-] (>= 1)
  Eigen::Vector3d a0 = Eigen::Vector3d::UnitX();  // <direction_of_symm>, normalized
  double C6() const;
  double shear_modulus() const { return 2.0 * (C1 + C2); }
};

// lb dW_f/dlb (Weiss), its derivative with respect to lb, and W_f.
double trans_iso_fibre_stress(double lb, const TransIsoHyperParams& p);
double trans_iso_fibre_energy(double lb, const TransIsoHyperParams& p);

// Reads and checks the trans_iso_hyper parameters (shared with visco_trans_iso_hyper);
// `type` names the model in MissingFeature messages.
TransIsoHyperParams read_trans_iso_hyper_params(const ModelParameters& params, const std::string& type);

SolidPointResult trans_iso_hyper_point(const Eigen::Matrix3d& F, double density0, const TransIsoHyperParams& p);

class TransIsoHyper final : public ConstitutiveModel {
 public:
  explicit TransIsoHyper(const TransIsoHyperParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "trans_iso_hyper"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.kappa; }
  double shear_modulus() const override { return p_.shear_modulus(); }
  bool hyperelastic() const override { return true; }

 private:
  TransIsoHyperParams p_;
};

}  // namespace tephra
