#pragma once
// Vaango's linear isotropic hypoelastic solid, type "hypo_elastic" (Vaango
// class HypoElastic; VT §4.1):
//
//   sigma_dot = (K - 2G/3) tr(d) I + 2G d                        (VT eq. 4.2)
//
// made objective with the Green-Naghdi rate: the law is integrated for the
// unrotated stress tau = R^T sigma R with the unrotated rate of deformation
// d_hat = R^T d R, where F = R U (VT §4.1: unrotate with the decomposition at
// the start of the step, rotate back with the one at its end; inventory
// "Objectivity", eq. 4.1, 17.1-17.2). Since d_hat = sym(U_dot U^{-1}), the step
// uses the midpoint rule on the right stretch:
//
//   tau_n      = R_n^T sigma_n R_n
//   de         = sym( (U_{n+1} - U_n) ((U_n + U_{n+1})/2)^{-1} )   (~ d_hat dt, O(dt^3) error)
//   tau_{n+1}  = tau_n + (K - 2G/3) tr(de) I + 2G de
//   sigma_{n+1} = R_{n+1} tau_{n+1} R_{n+1}^T
//
// de depends on U_n and U_{n+1} only, so a superposed rigid rotation (F -> Q F)
// rotates the stress exactly (R -> Q R, U unchanged), and a pure rigid spin
// leaves tau unchanged. Vaango forms d from the grid velocity gradient
// instead; both are consistent with eq. 4.2 and differ by O(dt^2) per step.
// Coaxial stretching without rotation gives tau = C : ln U (the Hencky strain)
// in the limit dt -> 0: uniaxial stress reaches sigma_zz = E ln(lambda_z),
// E = 9KG/(3K + G).
//
// Wave speed (Vaango): c^2 = (K + 4G/3)/rho, rho = rho0/J.
// Stored energy per reference volume: the complementary energy of the current
// stress, W = J [ p^2/(2K) + s:s/(4G) ], p = tr(sigma)/3, s = dev(sigma)
// (Vaango sums the work rate sigma:d instead; W equals that integral for a
// proportional small-strain path).
// Parameters (Vaango names): <G>, <K> [Pa] required; <alpha> [1/K] (linear thermal
// expansion, default 0).
//
// Thermal strain (Vaango HypoElastic: D = sym(l) - alpha T_dot I, T_dot = (T - T_prev)/dt):
// the mechanical increment is de - alpha (T_{n+1} - T_n) I, T_n the temperature of the
// point's last update (history "lastTemperature", declared only when alpha != 0, set to the
// first temperature seen). So free heating with F = exp(alpha (T - T_0)) I is stress-free
// (to the midpoint rule's O(dt^3) per step), and constrained heating (F = I) gives the
// pressure sigma = -3 K alpha (T - T_0) I exactly. <DoThermalExpansion> false in <MPM> sets
// alpha = 0 (departure: Vaango's HypoElastic does not read that flag; its ElasticPlastic and
// ViscoScram do -- Tephra treats the flag as the switch it is named).
#include <string>
#include <utility>

#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct HypoElasticParams {
  double G = 0.0;  // shear modulus [Pa]
  double K = 0.0;  // bulk modulus [Pa]
  double alpha = 0.0;  // linear thermal expansion coefficient [1/K]
};

// The point function. Precondition: det F_old > 0 and det F_new > 0.
// thermal_strain: alpha (T_{n+1} - T_n), subtracted from the volumetric increment.
SolidPointResult hypo_elastic_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new,
                                    const Eigen::Matrix3d& stress_old, double density0,
                                    const HypoElasticParams& p, double thermal_strain = 0.0);

class HypoElastic final : public ConstitutiveModel {
 public:
  explicit HypoElastic(const HypoElasticParams& p, std::string type = "hypo_elastic")
      : p_(p), type_(std::move(type)) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  // Vaango's "hypo_elastic_mms" (VT ch. 2 list item 10, the hypoelastic solid
  // of the MMS decks): the seed gives it no equation of its own; Tephra uses
  // this law under that type name, the same parameters (G, K, alpha = 0).
  static ConstitutiveModelP create_mms(const ModelParameters& params);

  std::string type() const override { return type_; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  bool reads_velocity_gradient() const override { return false; }  // de from U_n, U_{n+1} (header)
  double bulk_modulus() const override { return p_.K; }
  double shear_modulus() const override { return p_.G; }
  // Vaango HypoElastic::computePressEOSCM: p = K (1 - rho0/rho), dp/drho = K rho0/rho^2,
  // c^2 = K/rho.
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  // Inverse (Vaango computeRhoMicroCM): rho = rho0 / (1 - p/K); +infinity for p >= K,
  // which no finite density reaches.
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

 private:
  static ConstitutiveModelP create_named(const ModelParameters& params, const std::string& type);
  HypoElasticParams p_;
  std::string type_;  // "hypo_elastic" or "hypo_elastic_mms"
};

}  // namespace tephra
