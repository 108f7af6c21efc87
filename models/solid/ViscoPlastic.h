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
// Thermal strain (Vaango ViscoPlastic: d <- d - alpha dT/dt I, <coeff_thermal_expansion>,
// default 1e-5 /K, 0 under <MPM><DoThermalExpansion>false): the mechanical rate is
// d - alpha (T_{n+1} - T_last)/dt I, T_last the point's temperature at its previous update
// (history lastTemperature, as hypo_elastic; only when alpha != 0).
// Outputs: plastic work per reference volume J tau:eps_dot^i dt; stored energy
// as hypo_elastic (complementary energy of the stress); heating (Vaango's, Taylor-Quinney 0.9
// fixed in its code)
//   dT/dt = 0.9 sigma_eq(sigma_{n+1}) Delta eps_eq / (dt rho c_p),   rho = rho0/J,
// Delta eps_eq = int eps_dot_eq dt over the step (history plasticStrain accumulates it),
// c_p the material's <specific_heat> (required, > 0).
// Failure (Vaango ViscoPlastic::updateFailedParticlesAndModifyStress, <check_failure>, default
// false): after a step with inelastic flow (Delta eps_eq > 0) of a point not yet failed, the
// measure m is the largest principal stress (<failure_by_stress>, default true), else the mean
// stress tr(sigma)/3 (<failure_by_pressure>), else the largest principal Eulerian (Almansi) strain
// (I - (F F^T)^-1)/2; the point fails (history localized = 1) when m > v_f, its failure
// variable (history varf): <failure_variable_mean> (default 1e30) with
// <failure_variable_distrib> constant, or |N(mean, <failure_variable_std>)| drawn once per point
// for any other distribution (seeded_normal(0, point index), MetalFailure.h; Vaango draws from
// its own generator, so the values differ point by point, not in distribution). At failure
// sigma <- 0 (<zero_stress_upon_failure>, Vaango's default true), else with <allow_no_tension>
// sigma <- 0 if tr(sigma)/3 > 0 else tr(sigma)/3 I, else unchanged; the step's changes of beta,
// R, K are discarded (Vaango's updateElastic). A failed point keeps the stress of its failure
// step from then on (Vaango copies the old stress of localized particles); Vaango also freezes F
// of a failed particle when zeroing its stress: Tephra's F belongs to the driver and keeps
// following the grid (the stress stays what it was set to). <remove_particles> adds Vaango's melt
// check (T_{n+1} + dT > the material's <melt_temp>): as in Vaango it only discards the step's
// changes of beta, R, K and does not flag the point.
// Model options of Vaango ViscoPlastic's constructor and explicit computeStressTensor:
//  - <tolerance> tol [1/s] (default 1e-10): components of the rate of deformation D with
//    |D_ij| < tol are taken as 0 (Vaango truncates the laboratory-frame D = sym(L) component by
//    component before rotating it to the material frame). Tephra's D is the step's unrotated rate
//    de/dt (midpoint rule on U, above) rotated to the laboratory frame with R_{n+1}, truncated
//    there and rotated back. When every component is below tol the point "just sits there"
//    (Vaango's words): no update, the internal variables, plastic strain and failure state keep
//    their values, no heating, no plastic work, and the step's thermal strain is not applied
//    (Vaango's pTempPrev moves on regardless; here lastTemperature moves on). Vaango then copies
//    the laboratory stress; Tephra keeps the unrotated stress, sigma_{n+1} = R_{n+1} R_n^T sigma_n
//    R_n R_{n+1}^T (objective; the same for a point that does not rotate). Vaango also skips the
//    update at D = 0 exactly with tol = 0; Tephra with <tolerance>0 updates every step (stress
//    relaxation and thermal stress at fixed F, as the SUVIC-I rate equations say).
//  - <initial_material_temperature> [K] (default 269.15): Vaango stores it as the plasticity
//    state's initial temperature, which SUVIC-I never reads (its shear modulus and melting
//    temperature are the constants, its temperature the flow model's <temperature>): read,
//    checked (> 0, finite), no effect.
//  - <use_polar_decomposition_RMB> (default true): read by Vaango and never consulted (its
//    explicit update always calls the RMB polar decomposition). The polar decomposition F = R U is
//    unique, so the choice of algorithm cannot change the result: read (a boolean), no effect.
// MPMICE hooks (Vaango ViscoPlastic::computePressEOSCM / computeRhoMicroCM): gauge pressure
// p = K/2 (rho/rho0 - rho0/rho), dp/drho = K/2 (1/rho0 + rho0/rho^2), c^2 = K/rho (Vaango's);
// rho(p) = rho0 (x + sqrt(x^2 + 1)), x = p/K; <useModifiedEOS> the shared expansion branch
// (models/solid/ModifiedEos.h).
// Parameter map (deck tag -> symbol): coeff_backstress_evol A1 [Pa];
// coeff_saturation_backstress b0 [Pa]; exponent_backstress n_b; ref_strainrate eps0 [1/s];
// normalizing_inelastic_strainrate A [1/s]; activation_energy Q [J/mol];
// universal_gas_constant R_g [J/(mol K)]; temperature T [K]; exponent_inelastic_strainrate N;
// coeff_yieldstress_saturation r0 [Pa]; exponent_yieldstress n_R; coeff_yieldstress_evol A3 [Pa];
// coeff_dragstress_evol A5 [Pa]; coeff_stress_saturation s0 [Pa]; intial_drag (Vaango's spelling, the only one its schema has) or
// initial_drag K_0 [Pa] (> 0);
// initial_yield R_0 [Pa]. exponent_backstress_evol, normalizing_backstress (static
// recovery, unused by Vaango), exponent_dragstress: read, not used. Defaults are Vaango's.
#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

// The <viscoplastic_flow_model type="..."> keys visco_plastic accepts (`tephra --list
// viscoplastic_flow_model`): Vaango's suvic_i only.
inline std::vector<std::string> viscoplastic_flow_model_keys() { return {"suvic_i"}; }

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
// eq_strain (optional): int eps_dot_eq dt, the step's equivalent inelastic strain.
bool suvic_integrate(SuvicState& y, const Eigen::Matrix3d& d, double dt, double K_bulk, double G,
                     const SuvicParams& p, double& dissipation, double* eq_strain = nullptr);

// Vaango ViscoPlastic's model-level options (header comment above).
struct SuvicFailure {
  bool check = false;                          // <check_failure>
  double mean = 1e30, std = 0.0;               // <failure_variable_mean>, <failure_variable_std>
  bool random = false;                         // <failure_variable_distrib> other than "constant"
  bool by_stress = true, by_pressure = false;  // <failure_by_stress>, <failure_by_pressure>
  bool zero_stress = true, no_tension = false;  // <zero_stress_upon_failure>, <allow_no_tension>
  bool melt_check = false;                     // <remove_particles>
  double melt_temperature = 0.0;               // the material's <melt_temp> (melt_check only)
};

struct SuvicModel {
  double alpha = 1e-5;         // <coeff_thermal_expansion> [1/K]
  double specific_heat = 0.0;  // the material's <specific_heat> [J/(kg K)]
  double taylor_quinney = 0.9;  // Vaango's fixed coefficient
  bool use_modified_eos = false;
  double tolerance = 1e-10;               // <tolerance> [1/s] (header: the D truncation)
  double initial_temperature = 269.15;    // <initial_material_temperature> [K]: no effect (header)
  SuvicFailure failure;
};

// Vaango's <tolerance> (header): zeroes the components of the laboratory rate of deformation d
// with |d_ij| < tol; returns true when every component is below tol (the point is not updated).
bool suvic_truncate_rate(Eigen::Matrix3d& d, double tol);

// The failure measure of a point (header comment): largest principal stress, mean stress or
// largest principal Almansi strain of F.
double suvic_failure_measure(const SuvicFailure& f, const Eigen::Matrix3d& stress, const Eigen::Matrix3d& F);

class ViscoPlastic final : public ConstitutiveModel {
 public:
  ViscoPlastic(double K, double G, const SuvicParams& p, const SuvicModel& m = {}) : K_(K), G_(G), p_(p), m_(m) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "visco_plastic"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return K_; }
  double shear_modulus() const override { return G_; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  bool modified_eos() const override { return m_.use_modified_eos; }

 private:
  double K_, G_;
  SuvicParams p_;
  SuvicModel m_;
};

}  // namespace tephra
