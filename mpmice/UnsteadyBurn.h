#pragma once
// The unsteady WSB burn rate of <Model type="Unsteady_Burn"> (the equations
// and parameter names of Uintah's HEChem/Unsteady_Burn.cc, read for the
// facts; the steady part is the WSB rate of mpmice/SteadyBurn.h).
//
// The burning surface carries two state variables, the surface temperature
// Ts and the temperature gradient beta = dT/dx at the surface inside the
// condensed phase. In steady burning at mass flux m* (WSB, surface
// temperature Ts*) the condensed-phase profile is T - T0 = (Ts* - T0)
// exp(m* Cp x/kc), so
//   beta* = (Ts* - T0) m* Cp / kc.
// Out of steady state both lag their steady values with the condensed
// phase's thermal relaxation time tau_c = kc/(Cp vc m*^2) (= alpha/r^2,
// alpha = kc/(rho_c Cp), r = m* vc the linear rate), scaled by
// <CondUnsteadyCoef> Nc (beta) and Nc <GasUnsteadyCoef> Ng (Ts), one
// forward-Euler step per time step:
//   n = Nc tau_c/dt:      beta <- beta + (beta* - beta)/n     (beta* if n <= 1)
//   n_T = Ng n:           Ts   <- Ts   + (Ts* - Ts)/n_T       (Ts* if n_T <= 1)
// so at constant p and T0 (constant m*) beta_k - beta* = (1 - 1/n)^k
// (beta_0 - beta*), the discrete form of exp(-t/(Nc tau_c)).
// The mass flux follows from the unsteady condensed-phase surface balance
// (Lengelle's relation with the conducted flux kc beta in place of
// m Cp (Ts - T0)):  m^2 (kc beta/m - Qc/2) = Ac R kc Ts^2 exp(-Ec/(R Ts))/(Ec vc),
// i.e. m^2 - b m + c = 0 with b = 2 kc beta/Qc,
// c = 2 Ac R kc Ts^2 exp(-Ec/(R Ts))/(Ec Qc vc); the smaller root
//   m = 2c/(b + sqrt(b^2 - 4c))
// (at beta*, Ts* it is m*: the other root c/m* exceeds m* because
// Ts* > T0 + Qc/Cp). b^2 < 4c has no solution: a NumericalFailure (Uintah:
// "Timestep is too large to correctly compute the unsteady burn rate").
// <BurnrateModCoef> Bm: m <- m* (m/m*)^Bm.
// A fresh surface (no history: beta = kInitBeta or Ts = kInitTs, Uintah's
// INIT_BETA/INIT_TS) burns at the steady rate and starts from beta*, Ts*.
#include "mpmice/SteadyBurn.h"

namespace tephra {

constexpr double kUnsteadyInitTs = 300.0;    // [K] Uintah's INIT_TS: "no history"
constexpr double kUnsteadyInitBeta = 1e12;   // [K/m] Uintah's INIT_BETA: "no history"

struct UnsteadyBurnParams {
  WsbParams wsb;
  double Bm = 1;  // <BurnrateModCoef>
  double Nc = 1;  // <CondUnsteadyCoef>
  double Ng = 1;  // <GasUnsteadyCoef>
};

struct UnsteadyBurnState {
  double Ts = kUnsteadyInitTs;      // surface temperature [K]
  double beta = kUnsteadyInitBeta;  // surface temperature gradient [K/m]
  bool has_history() const { return beta < kUnsteadyInitBeta && Ts > kUnsteadyInitTs; }
};

struct UnsteadyBurnRate {
  double mass_flux = 0;    // m [kg/(m^2 s)] of this step
  double steady_flux = 0;  // m* (WSB) at this step's p, T0, vc
};

// One step of length dt at pressure p [Pa], bulk temperature T0 [K],
// condensed specific volume vc [m^3/kg]: updates s (beta, Ts) and returns
// the step's mass flux. Throws NumericalFailure where b^2 < 4c.
UnsteadyBurnRate unsteady_burn_rate(const UnsteadyBurnParams& prm, double p, double T0, double vc, double dt,
                                    UnsteadyBurnState& s);

// The steady surface gradient beta* = (Ts - T0) m Cp/kc.
double steady_surface_gradient(const WsbParams& q, const WsbState& w, double T0);

// The smaller root of m^2 - b m + c = 0 (b, c above) at beta, Ts.
double unsteady_condensed_flux(const WsbParams& q, double beta, double Ts, double vc);

}  // namespace tephra
