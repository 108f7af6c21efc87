#pragma once
// Vaango's compressible Mooney-Rivlin solid, type "comp_mooney_rivlin" (Vaango
// class CompMooneyRivlin; VT §4.2.2):
//
//   W = C1 (I1 - 3) + C2 (I2 - 3) + C3 (1/I3^2 - 1) + C4 (I3 - 1)^2       (VT eq. 4.10)
//   C3 = (C1 + 2 C2)/2,  C4 = [C1 (5 nu - 2) + C2 (11 nu - 5)] / (2 (1 - 2 nu))   (eq. 4.11)
//   sigma = (2/J) [ (C1 + C2 I1) B - C2 B^2 ] + 2 J W3 I,
//           W3 = dW/dI3 = -2 C3 / I3^3 + 2 C4 (I3 - 1)                  (eq. 4.12, 4.6)
//
// with B = F F^T, I1 = tr B, I2 = [(tr B)^2 - tr(B^2)]/2, I3 = J^2. Erratum of
// eq. 4.12 (inventory): the J^2[...] term multiplies I. C3 makes sigma(I) = 0.
// W is per unit reference volume (Vaango sums W V0 as StrainEnergy).
// Small-strain limit (derived from d^2W/dlambda_i dlambda_j at lambda = 1):
// shear modulus G = 2 (C1 + C2), Lame lambda = 2 G nu / (1 - 2 nu), so nu is
// Poisson's ratio and K = 2 G (1 + nu) / (3 (1 - 2 nu)).
// Wave speed, VT eq. 4.7 with rho J = rho0: c^2 = max_i d^2W/dlambda_i^2 / rho0,
//   d^2W/dlambda_i^2 = 2 C1 + 2 C2 (I1 - lambda_i^2) + [20 C3 / I3^2 + 4 C4 I3 (3 I3 - 1)] / lambda_i^2,
// which is (K + 4G/3)/rho0 at F = I. (Vaango's code uses another expression
// that differs from its own initial estimate when C2 != 0.) C4 < 0 (nu below
// about 2/5) makes W non-convex in volumetric tension: where every
// d^2W/dlambda_i^2 <= 0 there is no real wave speed and update() rejects the
// point (NumericalFailure naming the particle). Vaango's decks use nu = 0.49.
// Parameters (Vaango names): <he_constant_1> C1, <he_constant_2> C2 [Pa], <he_PR> nu.
#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct CompMooneyRivlinParams {
  double C1 = 0.0;  // [Pa]
  double C2 = 0.0;  // [Pa]
  double nu = 0.0;  // Poisson's ratio, -1 < nu < 1/2
  double C3() const { return 0.5 * C1 + C2; }
  double C4() const { return 0.5 * (C1 * (5.0 * nu - 2.0) + C2 * (11.0 * nu - 5.0)) / (1.0 - 2.0 * nu); }
  double shear_modulus() const { return 2.0 * (C1 + C2); }
  double bulk_modulus() const { return 2.0 * shear_modulus() * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)); }
};

// The point function. Precondition: det F > 0.
SolidPointResult comp_mooney_rivlin_point(const Eigen::Matrix3d& F, double density0,
                                          const CompMooneyRivlinParams& p);

class CompMooneyRivlin final : public ConstitutiveModel {
 public:
  explicit CompMooneyRivlin(const CompMooneyRivlinParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "comp_mooney_rivlin"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.bulk_modulus(); }
  double shear_modulus() const override { return p_.shear_modulus(); }
  bool hyperelastic() const override { return true; }
  // MPMICE hooks (Vaango has none for this model; added by Tephra): the pressure of
  // the hydrostatic state F = J^{1/3} I, J = rho0/rho, where eq. 4.10 reduces to
  //   W(J) = 3 C1 (J^{2/3} - 1) + 3 C2 (J^{4/3} - 1) + C3 (J^{-4} - 1) + C4 (J^2 - 1)^2,
  //   p = -W'(J) = -[2 C1 J^{-1/3} + 4 C2 J^{1/3} - 4 C3 J^{-5} + 4 C4 J (J^2 - 1)],
  //   dp/drho = W''(J) J^2 / rho0,  W'' = -2/3 C1 J^{-4/3} + 4/3 C2 J^{-2/3} + 20 C3 J^{-6} + 4 C4 (3 J^2 - 1)
  // (W''(1) = K of the header), c^2 = dp/drho. The inverse solves p(rho) = p_gauge by
  // safeguarded Newton; NaN where p(rho) is not monotone (W'' <= 0, C4 < 0 in tension).
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

 private:
  CompMooneyRivlinParams p_;
};

}  // namespace tephra
