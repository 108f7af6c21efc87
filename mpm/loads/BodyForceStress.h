#pragma once
// <MPM><initialize_stress_using_body_force>true with a material's
// <constitutive_model><initialize_with_body_force>true and
// <surface_reference_point>[xs, ys, zs]: the particles start in the stress
// state that balances the body force (Vaango's
// SerialMPM::initializeStressAndDefGradFromBodyForce, which calls the
// constitutive model's initializeStressAndDefGradFromBodyForce; in Vaango
// only Arenisca3 and the arena models implement it, Tephra offers it for
// hypo_elastic and the hyperelastic models).
//
// With the body-force acceleration b (gravity; Vaango subtracts the
// centrifugal term when rotating, Tephra's rotating frame with this option
// is MissingFeature), density rho0 and the surface point x_s, each particle
// at x takes the diagonal stress (Vaango's formula; zero shear, body force
// along the coordinate axes)
//     sigma_ii = -rho0 b_i (x_i - x_s,i),   sigma_ij = 0 (i != j),        (1)
// so that div sigma + rho0 b = 0 exactly (d sigma_ii / dx_i = -rho0 b_i).
// For gravity (0, 0, -g) and a surface at z_s: sigma_zz = -rho0 g (z_s - z),
// compression below the surface, sigma_xx = sigma_yy = 0 (a laterally free
// column in uniaxial stress; a confined K0 state would need lateral walls
// that (1) does not know about). The deformation gradient is the linear
// elastic strain of that stress (Vaango's, small strain):
//     F = I + eps,  eps = sigma / (2G) + (1/(9K) - 1/(6G)) tr(sigma) I,      (2)
// K, G the model's small-strain moduli, and the volume V = det(F) V0
// (Tephra's invariant V = J V0). A hyperelastic model then recomputes its
// stress from F, equal to (1) up to O(eps^2); hypo_elastic keeps (1).
//
// Particles above the surface (x_i - x_s,i of the sign that would give
// tension, i.e. -b_i (x_i - x_s,i) > 0) get tension from (1) as in Vaango;
// the deck chooses x_s at the free surface.
#include "core/base/Types.h"
#include "mpm/Particles.h"

namespace tephra {

// Eq. (1).
Mat3 body_force_stress(double rho0, const Vec3& b, const Vec3& x, const Vec3& surface_point);

// Eq. (2).
Mat3 small_strain_deformation_gradient(const Mat3& sigma, double bulk_modulus, double shear_modulus);

// Sets stress, F and volume of every particle of `p` by (1), (2).
void initialize_stress_from_body_force(double rho0, const Vec3& b, const Vec3& surface_point, double bulk_modulus,
                                       double shear_modulus, Particles& p);

}  // namespace tephra
