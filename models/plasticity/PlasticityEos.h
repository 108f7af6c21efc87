#pragma once
// Equation-of-state sub-models of the metal-plasticity models (VT ch. 6): the
// volumetric response p(J, T, e) with dp/dJ. p is the MEAN STRESS tr(σ)/3
// (tension positive), as in the manual's ch. 6. Distinct from models/eos
// (ICE's EOS of micro density).
#include <memory>
#include <string>
#include <vector>

#include "models/plasticity/SubModelTable.h"

namespace tephra {

struct EosInput {
  double J = 1.0;        // (elastic) volume ratio V/V_0 = ρ_0/ρ
  double energy = 0.0;   // internal energy per unit reference volume above the reference state E [J/m^3]
  double p_old = 0.0;    // mean stress at t_n (rate form default_hypo)
  double trace_d = 0.0;  // tr(d) of the step [1/s] (default_hypo)
  double dt = 0.0;       // step [s] (default_hypo)
};

struct EosResult {
  double p = 0.0;      // mean stress tr(σ)/3 [Pa]
  double dp_dJ = 0.0;  // ∂p/∂J at constant E [Pa]
};

class PlasticityEos {
 public:
  virtual ~PlasticityEos() = default;
  virtual std::string type() const = 0;
  virtual EosResult evaluate(const EosInput& in) const = 0;
  virtual double bulk_modulus() const = 0;  // K at the reference state [Pa]
  // The mean stress as a function of J alone (E = 0), for MPMICE's pressure hooks.
  // The rate form default_hypo integrates p_dot = K tr d from the reference state: p = K ln J.
  virtual EosResult at_volume_ratio(double J) const {
    EosInput in;
    in.J = J;
    return evaluate(in);
  }
};

// MPMICE's view of an EOS sub-model (Vaango computePressEOSCM / computeRhoMicroCM of the
// composed metal models): the gauge pressure p̄(ρ) = -(p(J) - p(1)), J = ρ0/ρ, positive in
// compression, dp̄/dρ = (dp/dJ) ρ0/ρ², c² = dp̄/dρ (bulk sound speed); and its inverse.
struct EosPressurePoint {
  double pressure = 0.0, dp_drho = 0.0, c2 = 0.0;
};
EosPressurePoint eos_pressure_at_density(const PlasticityEos& eos, double rho, double rho0);
// ρ with eos_pressure_at_density(ρ) = p_gauge: safeguarded Newton in ln J on the bracket where
// p̄ is monotone. Throws NumericalFailure when p_gauge is outside the EOS's range (e.g. a
// tension for `air`, whose pressure is zero in expansion).
double eos_density_at_pressure(const PlasticityEos& eos, double p_gauge, double rho0);

const std::vector<SubModelEntry<PlasticityEos>>& plasticity_eos_models();
std::unique_ptr<PlasticityEos> create_plasticity_eos(const std::string& key, const ModelParameters& p,
                                                     const SubModelContext& ctx = {});

}  // namespace tephra
