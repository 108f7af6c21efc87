#pragma once
// Pieces shared by the chapter-3 "fluid-like" special materials (water,
// murnaghanMPM, jwlpp_mpm; VT §3.3-3.5): an EOS pressure p(J) plus a Newtonian
// shear stress,
//   sigma = -p I + 2 mu eta,   eta = d - tr(d)/3 I,   d = sym(l)   (VT eqs. 3.6-3.7, 3.9-3.10, 3.12-3.13)
// and the stored energy of a pressure-only solid, W(J) = -int_1^J p(J') dJ',
// which makes sigma = (1/J) dW/dF F^T = W'(J) I = -p I (VT eq. 4.3).
#include <Eigen/Core>

namespace tephra {

struct SolidUpdateInput;
struct SolidUpdateOutput;
struct SolidEosPoint;

// 2 mu dev(sym(l)) (VT eq. 3.6 with 3.7): the viscous, trace-free part.
inline Eigen::Matrix3d viscous_shear_stress(const Eigen::Matrix3d& L, double mu) {
  const Eigen::Matrix3d d = 0.5 * (L + L.transpose());
  return (2.0 * mu) * (d - (d.trace() / 3.0) * Eigen::Matrix3d::Identity());
}

// Power-law pressure  p(J) = a (J^{-g} - 1)  (water with a = kappa, g = gamma, VT eq. 3.8;
// Murnaghan with a = K/K', g = K', VT eq. 3.11; ideal gas with a = p_ref, VT eq. 3.4).
// Its energy W(J) = -int_1^J p = a [ (J^{1-g} - 1)/(g - 1) + (J - 1) ]  (g != 1),
//                               = a [ -ln J + (J - 1) ]                   (g == 1).
double power_law_energy(double J, double a, double g);

// p(J) = a (J^{-g} - 1), exact 0 at J = 1.
double power_law_pressure(double J, double a, double g);

// The point update of a power-law fluid (water: a = kappa, g = gamma; Murnaghan:
// a = K/K', g = K'): sigma = -p(J) I + 2 mu eta, W = power_law_energy, the
// P-wave speed c^2 = J dp/dJ... = g a J^{-g} / rho (rho = rho0/J), the viscous
// dissipation J (tau : d) dt as plastic work, no heating (Vaango: pdTdt = 0).
// Returns the first rejected point (det F <= 0 or a non-finite stress) or -1.
long update_power_law_fluid(const SolidUpdateInput& in, const SolidUpdateOutput& out, double a, double g,
                            double mu);

// MPMICE hooks of the same law at x = rho/rho0 = 1/J: p = a (x^g - 1),
// dp/drho = a g x^{g-1}/rho0 (= c^2), and its inverse rho = rho0 (1 + p/a)^{1/g}
// (NaN for p <= -a: no density gives that tension).
SolidEosPoint power_law_eos_point(double rho, double density0, double a, double g);
double power_law_density(double p_gauge, double density0, double a, double g);

}  // namespace tephra
