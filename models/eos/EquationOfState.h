#pragma once
// Equations of state for ICE materials (and later MPMICE solids) as point
// functions of the micro (pure-material) density rho and temperature T
// (DESIGN.md §2.1; Vaango theory manual eq. 24.4-24.5: caloric e(v, T) and
// thermal v(p, T) equations of state).
//
// The interface is batched: one virtual call per material per phase, the
// concrete loop inside (DESIGN.md §2.3). `at()` and `density_at()` are
// one-point conveniences for tests and setup code.
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "models/ModelParameters.h"

namespace tephra {

// The state an EOS returns at one (rho, T):
//   p        pressure
//   dp_drho  (dp/drho) at constant specific internal energy e
//   dp_de    (dp/de) at constant rho
//   c2       squared adiabatic sound speed, c^2 = dp/drho|_e + (p/rho^2) dp/de|_rho
struct EosState {
  double p = 0, dp_drho = 0, dp_de = 0, c2 = 0;
};

// Material constants ICE keeps outside the <EOS> element: <gamma> and
// <specific_heat> (cv) of the ICE material.
struct EosMaterialConstants {
  double gamma = 1.4;
  double cv = 717.5;
};

class EquationOfState {
 public:
  virtual ~EquationOfState() = default;
  virtual std::string type() const = 0;  // Vaango's <EOS type=...>

  // out[i] = state at (rho[i], T[i]). All spans have the same length.
  virtual void evaluate(std::span<const double> rho, std::span<const double> T, std::span<EosState> out) const = 0;
  // rho[i] such that p(rho[i], T[i]) = p[i] (the thermal EOS inverted).
  virtual void density(std::span<const double> p, std::span<const double> T, std::span<double> rho) const = 0;
  // beta[i] = (1/v) dv/dT at constant p (thermal expansivity, eq. 24.10).
  virtual void thermal_expansivity(std::span<const double> rho, std::span<const double> T,
                                   std::span<double> beta) const = 0;

  EosState at(double rho, double T) const {
    EosState s;
    evaluate({&rho, 1}, {&T, 1}, {&s, 1});
    return s;
  }
  double density_at(double p, double T) const {
    double r = 0;
    density({&p, 1}, {&T, 1}, {&r, 1});
    return r;
  }
  double thermal_expansivity_at(double rho, double T) const {
    double b = 0;
    thermal_expansivity({&rho, 1}, {&T, 1}, {&b, 1});
    return b;
  }
};

using EquationOfStateP = std::unique_ptr<EquationOfState>;

// Registry keyed by Vaango's EOS type names. Returns nullptr for a type that
// is not implemented (the caller decides between MissingFeature for a Vaango
// type and DeckError for an unknown one). `params` holds the children of
// <EOS>; every creator marks what it reads.
EquationOfStateP create_equation_of_state(const std::string& type, const ModelParameters& params,
                                          const EosMaterialConstants& constants);
std::vector<std::string> equation_of_state_types();         // implemented (all of Vaango's but KumariDass)
const std::vector<std::string>& vaango_equation_of_state_types();  // every ICE EOS type of Vaango's schema

}  // namespace tephra
