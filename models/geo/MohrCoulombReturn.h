#pragma once
// The classic Mohr-Coulomb surface (VT §19.3.1) and its perfectly plastic
// return in principal stresses, with a dilation angle (VT §19.5).
//
// Tension positive here (Tephra's convention; VT ch. 19 is compression
// positive), principal stresses ordered s1 >= s2 >= s3 (s1 the least
// compressive). With c the cohesion, phi the friction angle, eq. 19.5 reads
//   f_ij = (s_i - s_j) + (s_i + s_j) sin(phi) - 2 c cos(phi) <= 0,   i < j,
// the largest of which is f_13 (the "main plane"). Uniaxial compression
// strength: s1 = 0 gives |s3| = 2 c cos(phi)/(1 - sin(phi)); triaxial
// compression at lateral stress -sigma_conf: |s3| = 2c cos(phi)/(1 - sin phi)
// + sigma_conf (1 + sin phi)/(1 - sin phi).
// Plastic potential g_ij: the same with the dilation angle psi (eq. 19.29), so
// the flow vectors are n_13 = (1 + sin psi, 0, -(1 - sin psi)) etc.
//
// Return (backward Euler; exact for linear isotropic elasticity and perfect
// plasticity, since f and g are linear in principal space; de Souza Neto,
// Peric & Owen, "Computational methods for plasticity", 2008, §8.2.2):
//   1. main plane: s = s_tr - dg D n_13, dg = f_13(s_tr)/(a_13 . D n_13);
//      accepted when the order s1 >= s2 >= s3 survives;
//   2. otherwise the edge s1 = s2 (planes 13 and 23; triaxial compression) or
//      s2 = s3 (planes 13 and 12; triaxial extension): two multipliers from a
//      2x2 linear system, accepted when both are >= 0;
//   3. otherwise the apex s1 = s2 = s3 = c cot(phi) (phi > 0).
// D = (K - 2G/3) 1 1^T + 2G I is the elastic matrix in principal space.
// VT §19.7 instead bisects for the elastic fraction and projects along
// P = -C : dg/dsigma with Runge-Kutta substeps; for this linear perfectly
// plastic model the closed-form return above lands exactly on f = 0.
//
// The invariant form (eq. 19.9-19.10, compression positive):
//   f = R(theta) q - p sin(phi) - c cos(phi),
//   R(theta) = sin(theta + pi/3)/sqrt(3) - sin(phi) cos(theta + pi/3)/3,
//   cos(3 theta) = (3 sqrt(3)/2) J3/J2^(3/2)
// equals f_13/2 (test_model_mohr_coulomb). [ERRATUM] With this theta, triaxial
// compression (s1 > s2 = s3, compression positive) is at theta = 0, where
// M = sin(phi)/R(0) = 6 sin(phi)/(3 - sin(phi)) (M_o of eq. 19.18); theta = pi/3
// is triaxial extension, M = 6 sin(phi)/(3 + sin(phi)) (eq. 19.16). The text
// after eq. 19.17 has the two swapped.
#include <Eigen/Core>

namespace tephra {

struct MohrCoulombParams {
  double K = 0, G = 0;      // bulk and shear moduli [Pa]
  double c = 0;             // cohesion [Pa]
  double phi = 0, psi = 0;  // friction and dilation angles [rad]
};

// f_13 of the ordered principal stresses (tension positive).
double mohr_coulomb_f13(const MohrCoulombParams& m, const Eigen::Vector3d& s);

// Eq. 19.9 from the stress tensor, COMPRESSION positive (as the chapter).
double mohr_coulomb_yield_invariants(const MohrCoulombParams& m, const Eigen::Matrix3d& sigma_compression_positive);

enum class MohrCoulombRegion { elastic, main_plane, edge_compression, edge_extension, apex };

struct MohrCoulombReturnResult {
  Eigen::Vector3d s;  // ordered principal stresses after the return
  MohrCoulombRegion region = MohrCoulombRegion::elastic;
  double dgamma[2] = {0, 0};  // plastic multipliers (main plane, second plane of an edge)
};

// s_tr: ordered principal trial stresses (s_tr(0) >= s_tr(1) >= s_tr(2)).
MohrCoulombReturnResult mohr_coulomb_return(const MohrCoulombParams& m, const Eigen::Vector3d& s_tr);

}  // namespace tephra
