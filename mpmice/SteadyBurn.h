#pragma once
// The Ward-Son-Brewster (WSB) steady burn rate of a solid propellant
// (<Model type="Steady_Burn">, and the burn branch of DDT1; Vaango theory
// manual ch. 25-26; M. J. Ward, S. F. Son, M. Q. Brewster, Combust. Flame 114
// (1998) 556; the constants and the constant groups as Uintah's
// Steady_Burn.cc names them, read for the equations):
//   condensed phase:  m^2 = C1 Ts^2 exp(-Ec/(R Ts)) / (Ts - C2)
//                     C1 = Ac R kc/(Ec Cp vc),  C2 = T0 + Qc/(2 Cp)
//   gas phase:        Ts = C4 + C5/(sqrt(m^2 + C3) + m)^2
//                     C3 = 4 kg Bg W^2 p^2/(Cp R^2),  C4 = T0 + Qc/Cp,  C5 = Qg C3/Cp
// m [kg/(m^2 s)] the mass flux through the burning surface, Ts the surface
// temperature, T0 the bulk temperature of the solid, vc = 1/rho_c its
// specific volume, p the gas pressure. Ts solves Ts = F(Ts) := C4 +
// C5/(sqrt(m(Ts)^2 + C3) + m(Ts))^2: g(Ts) = Ts - F(Ts) < 0 at Ts = C4
// (F > C4) and g > 0 for Ts large (F is bounded), so the root is bracketed
// and found by bisection to 1e-12 relative (Uintah iterates a
// bisection-Newton scheme on the same g).
namespace tephra {

struct WsbParams {
  double R = 8.314;     // <IdealGasConst> [J/(mol K)]
  double Ac = 0;        // <PreExpCondPh> [1/s]
  double Ec = 0;        // <ActEnergyCondPh> [J/mol]
  double Bg = 0;        // <PreExpGasPh> [m^3/(kg s K^2)]
  double Qc = 0;        // <CondPhaseHeat> [J/kg]
  double Qg = 0;        // <GasPhaseHeat> [J/kg]
  double kg = 0;        // <HeatConductGasPh> [W/(m K)]
  double kc = 0;        // <HeatConductCondPh> [W/(m K)]
  double Cp = 0;        // <SpecificHeatBoth> [J/(kg K)]
  double W = 0;         // <MoleWeightGasPh> [kg/mol]
};

struct WsbState {
  double mass_flux = 0;            // m [kg/(m^2 s)]
  double surface_temperature = 0;  // Ts [K]
};

// The WSB mass flux and surface temperature at pressure p [Pa], bulk
// temperature T0 [K] and condensed specific volume vc [m^3/kg].
WsbState wsb_burn_rate(const WsbParams& prm, double p, double T0, double vc);

// The residual Ts - F(Ts) at Ts (for tests).
double wsb_residual(const WsbParams& prm, double p, double T0, double vc, double Ts);

}  // namespace tephra
