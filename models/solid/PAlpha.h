#pragma once
// Vaango's "p_alpha" (VT ch. 2 list item 21, "p-alpha porous model"; Vaango
// class P_Alpha): a pressure-only porous solid that compacts along a crush
// curve to the fully dense solid, which then follows a Mie-Grueneisen EOS.
// The seed has no equations for this model; the law below is the one of
// Vaango's P_Alpha (read for the facts; Herrmann's p-alpha form with the
// quadratic crush curve of Carroll & Holt).
//
// Distension alpha = rho_S / rho = alpha_0 J, alpha_0 = rho_S / rho_0 (rho_0 the
// material's <density>). Elastic limit: rho_P = rho_0 / (1 - P_e/K_0),
// alpha_P = rho_S / rho_P = alpha_0 (1 - P_e/K_0). Pressure p (compression +),
// sigma = -p I, with alpha_min the smallest distension reached (history):
//   loading (alpha <= alpha_min), 1 <= alpha < alpha_0:
//     alpha > alpha_P:      p = K_0 (1 - rho_0/rho) = K_0 (1 - J)          elastic, c = sqrt(K_0/rho)
//     1 < alpha <= alpha_P: p = P_s - (P_s - P_e) sqrt((alpha - 1)/(alpha_P - 1))   crush curve,
//                           c = c_s + (c_e - c_s)(alpha - 1)/(alpha_0 - 1),  c_s = sqrt(K_s/rho_S), c_e = sqrt(K_0/rho_0)
//   unloading (alpha > alpha_min), 1 <= alpha < alpha_0:
//     alpha_min >= alpha_P (never crushed): the elastic branch
//     otherwise: p = p_crush(alpha) + (alpha - alpha_min) / a',
//       a' = min( (alpha^2/K_s)(1 - 1/h^2), -1/K_s ),  h = 1 + (c_e - c_s)(alpha - 1)/(c_s (alpha_0 - 1))
//   fully dense (alpha < 1 or alpha_min < 1): Mie-Grueneisen about rho_S,
//     zeta = rho/rho_S - 1, E = c_v (T - T_1) rho_S,
//     p = P_s + Gamma_0 E + rho_S C_0^2 (1/zeta + 1 - Gamma_0/2) / (1/zeta - (S_alpha - 1))^2
//     (T_1: the temperature when the solid became dense, history "tempAlpha1")
//   alpha > alpha_0 or p < 0: p = K_u (1 - rho_max/rho), rho_max = min(rho_S, rho_S/alpha_min)
// Heating (Vaango pdTdt): crushing, dT/dt = -p (J_{n+1}/J_n - 1)/(rho c_v dt);
// dense, dT/dt = -T Gamma_0 rho_S tr(l) / rho. Plastic work per reference volume
// during crushing: -p (J_{n+1} - J_n). energy_density: the elastic branch's
// K_0 (1 - J)^2 / 2, 0 elsewhere (not tracked).
// Differs from Vaango at alpha = alpha_0 only: the sound speed there is the elastic
// sqrt(K_0/rho_0) (Vaango: c_s). Vaango's special cases kept as it has them: the elastic branch uses K_0
// (1 - rho_0/rho) with rho_0 the porous density; the unloading law evaluates
// the crush pressure at the current alpha. The MPMICE hooks are not provided
// (Vaango has none either).
// Parameters: <Ps>, <Pe>, <rhoS>, <K0>, <Ks>, <Ku> (default 0.1 K0), <T_0>, <C_0>,
// <Gamma_0>, <S_alpha>; <alpha0> optional (Vaango ignores it and uses rhoS/density;
// Tephra checks it against that). Needs the material's <density> and <specific_heat>.
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct PAlphaParams {
  double Ps = 0, Pe = 0, rhoS = 0, K0 = 0, Ks = 0, Ku = 0;  // [Pa], [Pa], [kg/m^3], [Pa], [Pa], [Pa]
  double T0 = 0, C0 = 0, Gamma0 = 0, S_alpha = 0;           // [K], [m/s], [-], [-]
  double rho0 = 0;  // the porous reference density (material <density>) [kg/m^3]
  double cv = 0;    // material <specific_heat> [J/(kg K)]
  double alpha0() const { return rhoS / rho0; }
  double alphaP() const { return alpha0() * (1.0 - Pe / K0); }
};

struct PAlphaPoint {
  double pressure = 0, sound_speed = 0;
  bool crushing = false;  // on the crush curve, loading
};

// Pressure at distension alpha with alpha_min_old (before this step) and alpha_min_new,
// temperature T and the densification temperature T1.
PAlphaPoint p_alpha_pressure(double alpha, double alpha_min_old, double alpha_min_new, double T, double T1,
                             const PAlphaParams& p);
// The crush curve p(alpha) on [1, alpha_P].
double p_alpha_crush_curve(double alpha, const PAlphaParams& p);

class PAlpha final : public ConstitutiveModel {
 public:
  explicit PAlpha(const PAlphaParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "p_alpha"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.K0; }
  double shear_modulus() const override { return 0.0; }

 private:
  PAlphaParams p_;
};

}  // namespace tephra
