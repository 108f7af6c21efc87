#pragma once
// Viscous stress and heat conduction of one ICE material (Uintah's ICE adds
// both to the Lagrangian momentum and energy: computeTauX/Y/Z and the
// conductive heat flux; the theory manual leaves the discretisation open,
// inventory ch. 24 "gaps"). Newtonian fluid, Stokes' hypothesis:
//   tau = mu (grad u + grad u^T) - (2/3) mu (div u) I,   q = -k grad T,
// with the effective coefficients theta mu, theta k of the material in a cell.
// Face-centred fluxes, cell divergence (conservative):
//   on the d-face between L = c - e_d and R = c:
//     du_a/dx_d = (u_a(R) - u_a(L))/dx_d,
//     du_a/dx_b (b != d) = mean over L and R of the central differences,
//     traction t_a = mu_f (du_a/dx_d + du_d/dx_a) - (2/3) mu_f div u delta_ad,
//     mu_f = (theta_L mu + theta_R mu)/2,
//     heat flux -q_d = k_f (T(R) - T(L))/dx_d, k_f = 2 k_L k_R/(k_L + k_R) (Uintah's harmonic mean);
//   force(c)  = sum_d (t(c + e_d) - t(c))/dx_d        (= div tau),
//   heat(c)   = sum_d (-q_d(c + e_d) + q_d(c))/dx_d   (= div k grad T).
// Both second order on a uniform grid. The caller supplies the extra cells:
// for a Dirichlet wall the value mirrored so that the face carries the wall
// value (u_e = 2 U - u_inner), see IceComponent::lagrangian_values_and_exchange.
#include "core/grid/Fields.h"

namespace tephra {

// force[c] += V-free divergence of tau over the interior cells of patch p.
void add_viscous_force(const Grid& g, const Patch& p, const GridArray<Vec3>& u, const GridArray<double>& theta,
                       double mu, GridArray<Vec3>& force);
// heat[c] += div(theta k grad T) over the interior cells of patch p.
void add_heat_conduction(const Grid& g, const Patch& p, const GridArray<double>& T, const GridArray<double>& theta,
                         double k, GridArray<double>& heat);

}  // namespace tephra
