#pragma once
// Pieces shared by the chapter-3 "fluid-like" special materials (water,
// murnaghanMPM, jwlpp_mpm; VT §3.3-3.5): an EOS pressure p(J) plus a Newtonian
// shear stress,
//   sigma = -p I + 2 mu eta,   eta = d - tr(d)/3 I,   d = sym(l)   (VT eqs. 3.6-3.7, 3.9-3.10, 3.12-3.13)
// and the stored energy of a pressure-only solid, W(J) = -int_1^J p(J') dJ',
// which makes sigma = (1/J) dW/dF F^T = W'(J) I = -p I (VT eq. 4.3).
#include <Eigen/Core>

namespace tephra {

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

}  // namespace tephra
