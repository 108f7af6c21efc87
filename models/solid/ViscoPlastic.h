#pragma once
// Vaango's "visco_plastic" with <viscoplastic_flow_model type="suvic_i">
// (VT §10.8, eqs. 10.29-10.38; Vaango classes ViscoPlastic + SuvicI): the
// SUVIC-I unified viscoplastic law for ice on a hypoelastic solid.
//
// Elasticity (default_hypo EOS, Green-Naghdi unrotated frame as hypo_elastic,
// HypoElastic.h; the step's unrotated strain increment de = d dt by the
// midpoint rule on the right stretch U):
//   tau_dot = (K - 2G/3) tr(d) I + 2G (d - eps_dot^i)                  (VT eq. 4.2 with inelastic strain)
// Inelastic flow (no yield surface: an overstress law):
//   X_ae = sqrt(3/2 (s - beta):(s - beta)),   s = dev(tau)             (10.30)
//   eps_dot_eq = A exp(-Q/(R_g T)) <(X_ae - R)/K>^N                   (10.29, 10.32)
//   eps_dot^i = eps_dot_eq n,   n = 3/2 (s - beta)/X_ae                (10.31)
// Internal variables (static recovery terms ignored, as Vaango):
//   beta_dot = 2/3 A1 eps_dot^i - (A1/beta_sat) eps_dot_eq beta        (10.33)
//   R_dot    = A3 eps_dot_eq (1 - R/R_sat)   while R < R_sat, else 0   (10.34, Vaango's cap)
//   K_dot    = A5 eps_dot_eq (1 - K/K_sat)   while K < K_sat, else 0   (10.35, Vaango's cap)
// Saturation values at the current rate (10.36-10.38):
//   sigma_sat = s0 (eps_dot_eq/eps0)^{1/N},  beta_sat = b0 (eps_dot_eq/eps0)^{1/n_b},
//   R_sat = r0 (eps_dot_eq/eps0)^{1/n_R},
//   K_sat = (sigma_sat - beta_sat - R_sat) / (eps_dot_eq/(A exp(-Q/(R_g T))))^{1/N}
// ERRATUM (VT eq. 10.38): printed as [eps_dot/(A e^{-Q/RT})] (X_sat - R_sat); the
// inverse of eq. 10.32 at saturation, X_sat - R_sat = K_sat (eps_dot/(A e^{-Q/RT}))^{1/N},
// gives the quotient with the 1/N power (what Vaango's SuvicI evaluates, with
// X_sat = sigma_sat - beta_sat). The grain size d_g of 10.34-10.35 is absorbed in A3, A5.
// T is the model's <temperature> parameter (Vaango: the particle temperature is not used).
//
// Integration: the step's ODE system (d constant over the step) is integrated
// with Heun's method (2nd order) in adaptive substeps h <= 0.05 / lambda,
// lambda = 3G N eps_dot_eq / (X_ae - R) + A1 eps_dot_eq / beta_sat (the stiffness of
// the overstress law), a substep being cut until h lambda <= 0.1 at both its ends
// (so an elastic predictor cannot jump deep into fast flow); more than 100000
// substeps in one step is a failure.
// Vaango integrates with a theta-linearized rate form
// (<integration_parameter_theta>); that parameter is read and not used.
// Outputs: plastic work per reference volume J tau:eps_dot^i dt; stored energy
// as hypo_elastic (complementary energy of the stress); heating 0.
// Parameter map (deck tag -> symbol): coeff_backstress_evol A1 [Pa];
// coeff_saturation_backstress b0 [Pa]; exponent_backstress n_b; ref_strainrate eps0 [1/s];
// normalizing_inelastic_strainrate A [1/s]; activation_energy Q [J/mol];
// universal_gas_constant R_g [J/(mol K)]; temperature T [K]; exponent_inelastic_strainrate N;
// coeff_yieldstress_saturation r0 [Pa]; exponent_yieldstress n_R; coeff_yieldstress_evol A3 [Pa];
// coeff_dragstress_evol A5 [Pa]; coeff_stress_saturation s0 [Pa]; initial_drag K_0 [Pa] (> 0);
// initial_yield R_0 [Pa]. exponent_backstress_evol, normalizing_backstress (static
// recovery, unused by Vaango), exponent_dragstress: read, not used. Defaults are Vaango's.
#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct SuvicParams {
  double A1 = 75e6, b0 = 0.1e6, n_b = 4.0, eps0 = 7.794e-8, A = 5e9, Q = 67500.0, Rg = 8.3144, T = 269.15;
  double N = 4.0, r0 = 0.8e6, n_R = 4.0, A3 = 1600e6, A5 = 95e6, s0 = 1.0e6, K0 = 0.05e6, R0 = 0.0;
  double prefactor() const;  // A exp(-Q/(R_g T)) [1/s]
};

struct SuvicState {
  Eigen::Matrix3d tau;   // unrotated stress [Pa]
  Eigen::Matrix3d beta;  // unrotated deviatoric backstress [Pa]
  double R = 0, K = 0;   // yield and drag stress [Pa]
};

// The rates of the SUVIC-I system (10.29-10.35) at state y under the unrotated rate of
// deformation d, with elastic moduli K_bulk, G. Returns eps_dot_eq (0 below R);
// *power (optional) = tau : eps_dot^i [W/m^3].
double suvic_rates(const SuvicState& y, const Eigen::Matrix3d& d, double K_bulk, double G, const SuvicParams& p,
                   SuvicState& rate, double* power = nullptr);

// Integrates the system over dt (adaptive Heun substeps); returns false on failure.
// dissipation: int tau:eps_dot^i dt [J/m^3 current].
bool suvic_integrate(SuvicState& y, const Eigen::Matrix3d& d, double dt, double K_bulk, double G,
                     const SuvicParams& p, double& dissipation);

class ViscoPlastic final : public ConstitutiveModel {
 public:
  ViscoPlastic(double K, double G, const SuvicParams& p) : K_(K), G_(G), p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "visco_plastic"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return K_; }
  double shear_modulus() const override { return G_; }

 private:
  double K_, G_;
  SuvicParams p_;
};

}  // namespace tephra
