#pragma once
// Advection of the Lagrangian cell quantities through the faces (step 10 of
// the ICE step; Uintah's FirstOrderAdvector / SecondOrderAdvector in a face
// form). Each face with normal velocity u_f moves the slab of volume
// |u_f| dt A out of its upwind (donor) cell D, a fraction phi = |u_f| dt / dx
// of the cell. The flux of a density-like quantity q (mass per volume,
// volume fraction) is, in units of q times the cell volume,
//     F = phi * q_slab,    q_slab = q_D                       (first order)
//                          q_slab = q_D + s_D (1 - phi)/2 * dq_D   (second order)
// where s_D = +1 when the slab sits at the high side of D (u_f > 0), -1 else,
// and dq_D is D's limited difference along the face normal, Uintah's
// limited gradient (SecondOrderBase::limitedGradient): central differences
// g_k = (q_{D+k} - q_{D-k})/2 in the three directions scaled by one factor
//     alpha = min(1, (q_max - q_D)/(v_max - q_D), (q_min - q_D)/(v_min - q_D)) >= 0
// where q_max, q_min are the extremes of the six face neighbours and
// v_max, v_min = q_D +- sum_k |g_k|/2 the extreme values at D's corners
// (Barth-Jespersen; in 1-D the monotonized-central limiter min((a+b)/2, 2a, 2b)
// for a = q_D - q_{D-1}, b = q_{D+1} - q_D of one sign, else 0). The slab
// centroid is (1 - phi)/2 cells from D's centre. Extra cells get dq = 0. A specific quantity psi (velocity, c_v T, specific volume) moves
// with the mass: F_psi = F_mass * psi_slab, psi_slab built the same way from
// psi. These are compatible fluxes (VanderHeyden & Kashiwa; inventory ch. 24
// step 10): a uniform psi stays uniform to round-off whatever the density.
// Each face flux is computed once, so the update is conservative.
//
// Differences from Uintah (documented in docs/algorithms/ice.md): Uintah moves the
// specific quantities' vertex values with the mass-weighted centroids
// (mass_massVertex_ratio); here psi's slab value uses psi's own limited
// gradient at the geometric slab centroid.
#include "core/grid/Grid.h"
#include "ice/IceFields.h"
#include "ice/IceSetup.h"
#include "ice/RadialWeights.h"

namespace tephra {

// Throws NumericalFailure naming the cell when a cell would lose more than
// its content in one step (sum of outgoing phi > 1: the CFL bound, Uintah's
// "bullet proofing" of the outflux volumes). Returns the largest outflow
// fraction sum_out phi over the interior cells of g (its screen form,
// sum of max(0, -+u) dt/dx; 0 for no cells): bound_outflow skips its pass
// below kOutflowBoundInactive (ice/AdvectionBounds.h). Axisymmetric
// (radial != null): the r-face terms are weighted by r_f/r_i (ice/RadialWeights.h).
double check_outflux(const Grid& g, const FaceScalars& u, double dt, int step, const RadialWeights* radial = nullptr);

// flux.at(d, p)(face) = F (signed: positive along +d) for every face of the
// interior cells of every patch. q must hold valid values in the extra cells
// and ghosts (two layers for second order).
void density_fluxes(const Grid& g, AdvectionOrder order, const CellScalars& q, const FaceScalars& u, double dt,
                    FaceScalars& flux);

// Specific quantity psi carried by the mass fluxes `mass_flux`.
template <class T>
void specific_fluxes(const Grid& g, AdvectionOrder order, const PatchFields<CellField<T>>& psi,
                     const FaceScalars& u, const FaceScalars& mass_flux, double dt, FaceData<T>& flux);

// dq(c) = sum of incoming minus outgoing fluxes over the six faces of each
// interior cell c (in units of q times the cell volume). Axisymmetric
// (radial != null): the r-face fluxes weighted by r_f/r_i (ice/RadialWeights.h).
template <class T>
void flux_divergence(const Grid& g, const FaceData<T>& flux, PatchFields<CellField<T>>& dq,
                     const RadialWeights* radial = nullptr);

}  // namespace tephra
