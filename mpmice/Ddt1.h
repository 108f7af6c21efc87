#pragma once
// The point functions of <Model type="DDT1"> (deflagration to detonation of
// an MPM explosive into an ICE product; Vaango's and Uintah's
// HEChem/DDT1.cc, read for the rules and parameter names; used by
// mpmice/Ddt1Model.cpp). Per cell holding reactant (theta_r > 1e-10), with
// p_c the cell's equilibration pressure:
//   * detonation (JWL++, Souers' rate law): p_c > <ThresholdPressureJWL> and
//     theta_r > <ThresholdVolFrac> (default 0.01):
//        F = rho_p/(rho_r + rho_p)  (product's share of the cell mass),
//        delF = G p_c^b (1 - F) dt  (0 once F >= 1),
//        dm = min(delF (M_r + M_p), M_r, 0.2 rho0 V)
//     (rho0 the MPM material's density; the 20 % cap is Vaango's, after
//     "JWL++: a simple reactive flow code package for detonation", p. 55);
//     heat released E0 dm;
//   * deflagration: <ThresholdPressureSB> < p_c < <ThresholdPressureJWL> and
//     no neighbour of the 3x3x3 block above ThresholdPressureJWL
//     ("detLocalTo"):
//       - conductive (surface) burning: an ignited surface cell
//         (mpmice/WsbSurfaceCell.h) whose gas pressure p (neighbour with the
//         largest product fraction) is >= ThresholdPressureSB:
//         dm = dt A m_WSB(p, T0, v_s), A the surface area of the corner masses;
//       - convective (crack) burning, with <useCrackModel>: the cell is
//         "cracked enough" (some reactant particle in it has a crack radius
//         above w(p_c) = sqrt(8e8/p_c^2.84), Vaango's threshold in SI units)
//         and some material of some neighbour is hotter than IgnitionTemp:
//         dm = dt A_c m_WSB(p, T0, v_s) with A_c = V/0.002 m (Vaango: the
//         burning area of a 2 mm cell, so that the mass burned does not
//         depend on the resolution);
//     both at most the cell's solid mass less V 1e-12 kg/m^3; heat Qc + Qg.
// Vaango reads <Gcrack>, <nCrack>, <CrackVolThreshold> but does not use them
// (its crack mass term is commented out); so does Tephra.
//
// <useInductionTime> (Uintah's DDT1::computeBurnLogic, read for the rule; the
// flame-spread law of S. F. Son, "Flame spread across surfaces of PBX 9501"):
// a deflagration cell must be exposed for an induction time before it burns.
//   * surface flame speed S_f(p) = Fb (p/PS)^Fc  (<PreexpoConst> Fb [m/s],
//     <PressureShift> PS [Pa], <ExponentialConst> Fc; p the gas pressure of
//     the WSB rule);
//   * tau_new = dx_mean A / S_f,  dx_mean = (dx + dy + dz)/3;
//   * A = (1 + IC)/2 + (1 - IC)/2 sin(2 theta - pi/2)  (<IgnitionConst> IC):
//     theta is the angle between the surface normal (corner-mass gradient)
//     and the direction to the hot cell, cos theta = |n.h|/|h|: IC for a
//     flame arriving along the normal (theta = 0), 1 along the surface;
//   * tau relaxes per step, tau = 0.2 tau_new + 0.8 tau_old (tau = tau_new in
//     the first step of the run, Uintah's sentinel delt_init + 1e-20); the
//     exposure time counts up by dt; the cell burns once count >= tau, and
//     keeps burning (tau and count carried) while it stays a burning cell. A
//     cell that stops being exposed restarts from tau_old = count = 0.
#include "core/base/Types.h"

namespace tephra {

enum class Ddt1Branch { None = 0, Detonating = 1, Conductive = 2, Convective = 3 };
// Uintah's codes of the "burning" label (typeofBurning): 1 warming up (exposed,
// induction time not reached), 2 conductive, 3 convective.
constexpr double kDdt1WarmingUp = 1, kDdt1Conductive = 2, kDdt1Convective = 3;

struct Ddt1InductionParams {
  double IC = 0;  // <IgnitionConst>
  double PS = 0;  // <PressureShift> [Pa]
  double Fb = 0;  // <PreexpoConst> [m/s]
  double Fc = 0;  // <ExponentialConst>
};

// Son's surface flame speed S_f = Fb (p/PS)^Fc [m/s].
double ddt1_flame_speed(const Ddt1InductionParams& prm, double p);
// The direction factor A(theta) = (1 + IC)/2 + (1 - IC)/2 sin(2 theta - pi/2).
double ddt1_induction_factor(double IC, double theta);
// theta = acos(min(|n.h|/(|n||h|), 1)) of the surface normal n and the
// direction h to the hot cell; NaN when n or h is zero (Uintah's 0/0).
double ddt1_induction_angle(const Vec3& n, const Vec3& h, double& cos_theta);
// tau_new = dx_mean A / S_f(p) [s].
double ddt1_induction_time(const Ddt1InductionParams& prm, double dx_mean, double A, double p);

struct Ddt1Thresholds {
  double jwl_pressure = 0;    // <ThresholdPressureJWL> [Pa]
  double sb_pressure = 0;     // <ThresholdPressureSB> [Pa]
  double volume_fraction = 0.01;  // <ThresholdVolFrac>
  bool crack_model = false;   // <useCrackModel>
};

// What decides a cell's branch.
struct Ddt1CellState {
  double p = 0;                   // the cell's equilibration pressure [Pa]
  double reactant_fraction = 0;   // theta_r
  bool detonation_next = false;   // a neighbour's pressure is above ThresholdPressureJWL
  bool ignited_surface = false;   // WsbSurface::ignited
  double gas_pressure = 0;        // WsbSurface::pressure [Pa]
  bool cracked = false;           // crackedEnough
  bool hot_neighbour = false;     // WsbSurface::hot_neighbour
};

Ddt1Branch ddt1_branch(const Ddt1Thresholds& t, const Ddt1CellState& s);

// The JWL++ branch in one cell: the reacted fraction F, the step's delF and
// the burned mass (formulas above). rho0: the MPM material's density.
struct Ddt1Detonation {
  double F = 0, delF = 0, mass = 0;
};
Ddt1Detonation ddt1_detonation(double G, double b, double p, double reactant_mass, double product_mass, double rho0,
                               double cell_volume, double dt);

// Vaango's crack width threshold w(p) = sqrt(8e8/p^2.84) [m], p in Pa.
double ddt1_crack_threshold(double p);

// The burning area Vaango gives a convectively burning cell: V/0.002 m [m^2].
double ddt1_convective_area(double cell_volume);

}  // namespace tephra
