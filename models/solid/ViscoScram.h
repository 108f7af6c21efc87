#pragma once
// Vaango's ViscoSCRAM solid, type "visco_scram" (Bennett et al. 1998, "A
// constitutive model for the non-shock ignition and mechanical response of
// high explosives", JMPS 46; Hackett & Bennett, IJNME 49 (2000) 1191; Vaango
// class ViscoScram). Used for PBX 9501 in the MPMICE burn decks. The seeds
// describe it in one paragraph only (material-models chapter, "Material models
// for the explosive"); the equations below follow Bennett's paper as Vaango
// implements it (its equation numbers in brackets are the paper's).
//
// Stress = mean part + deviatoric part, sigma = p I + s (tension positive):
//
//   p_dot = K tr(d)                                   K = 2G(1+nu)/(3(1-2nu)), G = sum G_i
//   s = sum_i s_i   (5 Maxwell elements in parallel, tau_i = 1/RTau_i; RTau = 0: elastic)
//   s_i_dot = 2 G_i d' - s_i/tau_i
//             - (G_i/G) [ 3 c^2 c_dot/a^3 s + (2G d' - sum_j s_j/tau_j - 3 c^2 c_dot/a^3 s) (c/a)^3/(1+(c/a)^3) ]
//
// (the crack term: SCRAM's isotropic damage by penny cracks of mean radius c,
// a = CrackParameterA; with c/a -> 0 the elements are independent Maxwell
// elements, s_i(t) = 2 G_i eps_dot tau_i (1 - exp(-t/tau_i)) at a constant
// deviatoric strain rate eps_dot).
//
// Crack growth [24-31]: with the effective stress sigma_e = sqrt(s:s + 3 p^2 [p > 0])
// (the mean stress enters in tension only), K_I = sqrt(3 pi c / 2) sigma_e;
// crack-face friction in compression mu' = sqrt(45/(2(3 - 2 mu^2))) mu [31],
// K_0m = K_0 sqrt(1 + pi A B / K_0), A = -mu' p sqrt(c), B = 1 + A/K_0 [30],
// K' = K_0m sqrt(1 + 2/m) [28], K_1 = K' (1 + m/2)^(1/m) [29]:
//
//   c_dot = v_res (K_I / K_1)^m              K_I <  K'   (slow growth) [24]
//   c_dot = v_res (1 - (K_0m / K_I)^2)       K_I >= K'   (fast growth)
//
// v_res = min(CrackMaxGrowthRate, exp(b) eps_eff^a [x CrackGrowthRate in tension]),
// eps_eff = sqrt(3/2) |d'|, (a, b) = (0.90564746, -2.90178468) (Vaango's
// "baseline" PBX 9501 fit; 0 for eps_eff <= 1e-8). Over a step the stress in
// K_I and the branch are frozen at t_n (as Vaango), so c obeys dc/dt = g(c).
//
// Heating (Hackett & Bennett 2000): dT/dt = -Gamma T tr(d) + (W_ve + W_cr)/(rho c_v),
// W_ve = sum_i s_i:s_i/(2 G_i tau_i) (viscous dissipation, >= 0),
// W_cr = [ s:s 3 c^2 c_dot/a^3 + s:s_dot_cr (c/a)^3 ] / (2G) (crack work),
// s_dot_cr = (2G d - 3 c^2 c_dot/a^3 s - sum_j s_j/tau_j)/(1 + (c/a)^3), c_v = the
// material's <specific_heat> (Vaango ignores Beta and DCp_DTemperature too).
//
// Differences from Vaango, all consistent with the same ODEs:
//  * objectivity: the law is integrated in the unrotated frame of F = R U
//    (Green-Naghdi, as hypo_elastic): the element stresses are stored
//    unrotated, d_hat = sym(U_dot U^{-1}) by the midpoint rule, sigma = R_{n+1}
//    tau R_{n+1}^T. Vaango's default updates s_i with the spatial d and no
//    rotation (not objective); its <useObjectiveRate> rotates by R_{n+1} both
//    ways, which for this isotropic law gives the same result. Both settings
//    of the flag give the Green-Naghdi update here.
//  * the mean stress uses the logarithmic volume increment ln(J_{n+1}/J_n)
//    (Vaango: tr(d) dt), so p = K ln J exactly without thermal strain;
//  * the 5 elements and c are advanced by ONE classical RK4 of the coupled
//    system (Vaango offsets every element by the current element's stage
//    increment and freezes c_dot at t_n in the stress equation), sub-stepped
//    so that h RTau_max <= 1/4: stable for any dt (Vaango caps dt at 1 us
//    instead).
//
// Volumetric response for MPMICE (Vaango computePressEOSCM / computeRhoMicroCM,
// the "standard" EOS): p - p_ref = K/2 (rho/rho0 - rho0/rho), dp/drho =
// K/2 (1/rho0 + rho0/rho^2), c^2 = K/rho; rho = rho0 (x + sqrt(x^2 + 1)), x = (p - p_ref)/K.
// <useModifiedEOS> (p = p_ref (rho/rho0)^(K/p_ref) for rho < rho0) needs the
// ICE reference pressure: modified_eos() is true, the hooks give the standard
// branch and MPMICE adds the expansion branch (models/solid/ModifiedEos.h);
// modified_eos_pressure / modified_eos_density are both branches with p_ref.
//
// Parameters (Vaango names): PR, CrackParameterA, CrackPowerValue,
// CrackMaxGrowthRate, StressIntensityF, CrackFriction, InitialCrackRadius,
// CrackGrowthRate, G1..G5, RTau1..RTau5, Beta, Gamma, DCp_DTemperature
// required; CoeffThermalExpansion (0), use_time_temperature_equation (false;
// WLF shift a_T = exp(-C1 (T - T0)/(C2 + T - T0)), RTau_i / a_T, T0 = 298,
// C1 = 6.5, C2 = 120), useModifiedEOS, useObjectiveRate (false).
// <useJWLEOS> true (with A, B, R1, R2, om, Cv required; rho0 accepted and
// unused, as by Vaango, which takes the material's density): the MPMICE hooks
// are the JWL law of models/solid/ViscoScramJwl.h, in absolute pressure
// (AbsolutePressureEos.h); the gauge hooks are then not provided.
// MissingFeature: randomize_parameters = true, useJWLCEOS,
// useMurnahanEOS, useBirchMurnaghanEOS. Accepted and unused, as by Vaango's
// visco_scram: Chi, delH, Z, EoverR, dynamic_coeff_friction, volfracHE (the
// parameters of visco_scram_hotspot that the stock burn decks also give).
#include <array>

#include <Eigen/Core>

#include <optional>

#include "models/solid/AbsolutePressureEos.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/ViscoScramJwl.h"

namespace tephra {

struct ViscoScramParams {
  double nu = 0.3;                          // PR
  std::array<double, 5> G{};                // G1..G5 [Pa]
  std::array<double, 5> RTau{};             // RTau1..RTau5 = 1/tau_i [1/s]
  double crack_a = 1e-3;                    // CrackParameterA [m]
  double crack_m = 10.0;                    // CrackPowerValue
  double crack_vmax = 300.0;                // CrackMaxGrowthRate [m/s]
  double K0 = 500.0;                        // StressIntensityF [Pa m^1/2]
  double mu = 0.35;                         // CrackFriction
  double c0 = 3e-5;                         // InitialCrackRadius [m]
  double cdot0 = 12.0;                      // CrackGrowthRate (tension multiplier of v_res)
  double Gamma = 1.0;                       // Gruneisen coefficient of the volumetric heating
  double alpha = 0.0;                       // CoeffThermalExpansion [1/K]
  double specific_heat = 0.0;               // the material's <specific_heat> [J/(kg K)]
  bool time_temperature = false;            // use_time_temperature_equation
  double T0_wlf = 298.0, C1_wlf = 6.5, C2_wlf = 120.0;
  bool modified_eos = false;                // useModifiedEOS
  std::optional<ViscoScramJwl> jwl;         // useJWLEOS (MPMICE hooks only)

  double shear_modulus() const { return G[0] + G[1] + G[2] + G[3] + G[4]; }
  double bulk_modulus() const { return 2.0 * shear_modulus() * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)); }
};

// The crack-growth law with the stress frozen at the start of a step (as
// Vaango; K_0m too): dc/dt = rate(c). The branch follows K_I(c) within the
// step (Vaango freezes it at t_n); both branches give v_res/(1 + m/2) at
// K_I = K', so the rate is continuous and bounded by v_res, where the frozen
// slow branch, c_dot ~ c^(m/2), would blow up in finite time.
struct ViscoScramCrackLaw {
  double v_res = 0;    // [m/s]
  double sigma_e = 0;  // effective stress [Pa]
  double K_0m = 0, K_p = 0, K_1 = 0;  // [Pa m^1/2]
  double m = 10;
  double K_I(double c) const;   // sqrt(3 pi c/2) sigma_e [26-27]
  double rate(double c) const;  // [m/s]
};

// Builds the law at crack radius c for mean stress p (tension positive),
// deviatoric stress s and deviatoric rate of deformation d'.
ViscoScramCrackLaw visco_scram_crack_law(const ViscoScramParams& P, double c, double p,
                                         const Eigen::Matrix3d& s, const Eigen::Matrix3d& d_dev);

// The time derivatives of the element stresses (unrotated frame) at crack
// radius c with crack speed c_dot, under the deviatoric rate d'.
void visco_scram_element_rates(const ViscoScramParams& P, const std::array<double, 5>& RTau,
                               const Eigen::Matrix3d& d_dev, double c, double c_dot,
                               const std::array<Eigen::Matrix3d, 5>& s, std::array<Eigen::Matrix3d, 5>& rate);

class ViscoScram final : public ConstitutiveModel, public AbsolutePressureEos {
 public:
  explicit ViscoScram(const ViscoScramParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "visco_scram"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.bulk_modulus(); }
  double shear_modulus() const override { return p_.shear_modulus(); }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  bool modified_eos() const override { return p_.modified_eos; }
  // AbsolutePressureEos: the JWL hooks with <useJWLEOS> (ViscoScramJwl.h).
  bool uses_absolute_pressure_eos() const override { return p_.jwl.has_value(); }
  SolidEosPoint absolute_pressure_at_density(double rho, double density0, double T, double p_ref) const override;
  double density_at_absolute_pressure(double p, double density0, double T, double p_ref) const override;
  // Vaango's modified EOS below rho0 (absolute pressure p_ref (rho/rho0)^(K/p_ref)),
  // standard EOS above; returns the GAUGE pressure p - p_ref.
  SolidEosPoint modified_eos_pressure(double rho, double density0, double p_ref) const;
  double modified_eos_density(double p_gauge, double density0, double p_ref) const;
  const ViscoScramParams& params() const { return p_; }

  // History column indices.
  static constexpr int kCrackRadius = 5, kTemperaturePrev = 6, kVeHeat = 7, kCrHeat = 8, kVolHeat = 9;

 private:
  ViscoScramParams p_;
};

}  // namespace tephra
