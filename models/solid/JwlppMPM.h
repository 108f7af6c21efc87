#pragma once
// Vaango's JWL++ reactive explosive, type "jwlpp_mpm" (VT §3.5, eqs. 3.12-3.17;
// Souers et al., "JWL++: a simple reactive flow code package for detonation",
// Propellants Explos. Pyrotech. 25 (2000) 54; Vaango class JWLppMPM). Explicit MPM.
//
//   sigma = -p I + 2 mu eta,  eta = dev(d), d = sym(l)                  (3.12-3.13)
//   df/dt = G (1 - f) p^b          (burn, only while p_n > p_ign)       (3.14)
//   p = (1 - f) p_m(J) + f p_jwl(J)                                     (3.15)
//   p_m = (J^{-n} - 1) / (n kappa)  (unreacted Murnaghan; kappa = <murnaghan_K>
//         is a COMPRESSIBILITY [1/Pa], the bulk modulus is 1/kappa)    (3.16)
//   p_jwl = A exp(-R1 J) + B exp(-R2 J) + C J^{-(1+omega)}  (products)  (3.17)
//
// f is the BURNED (product) fraction (VT's text calls it the reactant fraction:
// erratum in the inventory). History: p.progressF = f, p.progressdelF = its
// increment in the step (Vaango's labels).
//
// Burn update (Vaango JWLppMPM::computeUpdatedFractionAndPressure): when the
// pressure of the previous step p_n = -tr(sigma_n)/3 exceeds <ignition_pressure>
// and f_n < <max_burned_fraction>, the step is split into N = ceil(dt / dt_burn)
// substeps (dt_burn = <max_burn_timestep_size>, J interpolated geometrically),
// and each substep is integrated by backward Euler
//     f_{k+1} = f_k + dt_k G (1 - f_{k+1}) p_{k+1}^b,  p_{k+1} = (1 - f_{k+1}) p_m + f_{k+1} p_jwl
// (the default: Vaango's Newton iteration on (f, p); here the pair is reduced
// to one equation in f, bracketed in [f_k, 1] and solved by safeguarded Newton
// to round-off), or with <doFastStressCompute> by Vaango's two-stage scheme
//     f_{k+1} = (f_k + G p_k^b dt_k) / (1 + G p_k^b dt_k).
// f is capped at max_burned_fraction. Otherwise f is kept and p = eq. 3.15.
// Wave speed: c^2 = -dp/dJ J^2 / rho0 of eq. 3.15 at fixed f (for f = 0 this is
// Vaango's (1/(kappa rho0)) (rho/rho0)^{n-1}). Stored energy: 0 (as Vaango).
// Small-strain moduli K = 1/kappa, G = 0.
//
// MPMICE hooks: the UNREACTED Murnaghan EOS (f = 0; the hooks carry no history),
// in density form x = rho/rho0:  p = (x^n - 1)/(n kappa), dp/drho = x^{n-1}/(kappa rho0) = c^2,
// rho(p) = rho0 (1 + n kappa p)^{1/n}. Deviation: Vaango's JWLppMPM::computePressEOSCM
// evaluates a JWL product form with an uninitialized temperature term and its
// computeRhoMicroCM returns rho0 ("not yet implemented"); neither is reproducible.
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct JwlppParams {
  double ignition_pressure = 0.0;  // <ignition_pressure> [Pa]
  double viscosity = 0.0;          // <viscosity> mu [Pa s]
  double kappa = 0.0;              // <murnaghan_K> compressibility [1/Pa]
  double n = 0.0;                  // <murnaghan_n> [-]
  double A = 0, B = 0, C = 0;      // <jwl_A>, <jwl_B>, <jwl_C> [Pa]
  double R1 = 0, R2 = 0;           // <jwl_R1>, <jwl_R2> [-]
  double omega = 0;                // <jwl_om> [-]
  double G = 0;                    // <reaction_G> [1/(s Pa^b)]
  double b = 0;                    // <reaction_b> [-]
  double max_burn_timestep = 1e-12;  // <max_burn_timestep_size> [s] (Vaango default)
  double max_burned_fraction = 1.0;  // <max_burned_fraction> (Vaango default)
  bool fast_compute = false;         // <doFastStressCompute>
  double newton_tolerance = 1e-12;   // <tolerance_for_Newton_iterations>, on the f residual
  int newton_max_iterations = 60;    // <max_number_of_Newton_iterations>
};

double jwlpp_murnaghan_pressure(double J, const JwlppParams& p);  // eq. 3.16
double jwlpp_jwl_pressure(double J, const JwlppParams& p);        // eq. 3.17

// One burn update (the description above). Returns false when the solve fails.
bool jwlpp_burn_update(double J_old, double J_new, double f_old, double p_old, double dt, const JwlppParams& p,
                       double& f_new, double& p_new);

class JwlppMPM final : public ConstitutiveModel {
 public:
  explicit JwlppMPM(const JwlppParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "jwlpp_mpm"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return 1.0 / p_.kappa; }
  double shear_modulus() const override { return 0.0; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  const JwlppParams& params() const { return p_; }

 private:
  JwlppParams p_;
};

}  // namespace tephra
