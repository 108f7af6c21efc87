#pragma once
// The point state the metal-plasticity sub-models read (Vaango theory manual
// ch. 5-15; Vaango's PlasticityState). One plain struct for every family, so a
// composed model (elastic_plastic, elastic_plastic_hp) fills it once per point
// and hands it to EOS, shear, flow, melt, Cp and damage models in turn.
//
// Sign conventions (inventory §0): stress is tension positive; `pressure` here
// is the thermodynamic pressure p̄ = -tr(σ)/3, POSITIVE IN COMPRESSION (the p̄
// of eq. 7.6, 7.9, 10.12, 13.2). EOS models return the mean stress tr(σ)/3
// (tension positive) as the manual's ch. 6 does.
namespace tephra {

struct PlasticState {
  double eps_p = 0.0;        // equivalent plastic strain ε_p [-]
  double eps_p_rate = 0.0;   // equivalent plastic strain rate ε̇_p [1/s]
  double temperature = 0.0;  // T [K]
  double melt_temperature = 0.0;  // T_m at this state [K] (from the melting model)
  double density = 0.0;      // current mass density ρ [kg/m^3]
  double density0 = 0.0;     // reference mass density ρ0 [kg/m^3]
  double pressure = 0.0;     // p̄ = -tr(σ)/3, positive in compression [Pa]
  double shear_modulus = 0.0;  // μ(p, T) at this state (from the shear model) [Pa]
  double porosity = 0.0;     // void volume fraction φ [-]
  double sigma_e = 0.0;      // MTS evolving structure stress σ_e (eq. 10.19) [Pa]

  double eta() const { return density / density0; }  // compression η = ρ/ρ0
};

// Values a sub-model may take from its enclosing <constitutive_model> or
// <material> when its own element leaves them out (Vaango passes them as the
// material's "initial data"): <bulk_modulus>, <shear_modulus>, <melt_temp>,
// <specific_heat>, <room_temp>, <density>. 0 = not given.
struct SubModelContext {
  double bulk_modulus = 0.0;
  double shear_modulus = 0.0;
  double melt_temperature = 0.0;
  double specific_heat = 0.0;
  double room_temperature = 0.0;
  double density0 = 0.0;
};

}  // namespace tephra
