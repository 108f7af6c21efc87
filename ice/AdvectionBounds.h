#pragma once
// Bounds on what a donor cell sends out in one advection step (second order).
//
// 1. Mass. The second-order face flux F_f = phi_f w_f q_slab,f (IceAdvection.h;
//    w_f the MPMICE face weight chi L of IceLagrangianFlux.cpp, 1 in pure ICE)
//    uses a slab value that can reach 2 q_D (the limited slope lets the value
//    at the slab centroid rise to q_D + (q_D - q_min) <= 2 q_D). A pure-ICE
//    slab of width phi then carries at most what the linear reconstruction
//    holds there, but (a) the face form counts the corner of two outgoing
//    slabs twice, and (b) in MPMICE the weighted width phi w (w = chi L up to
//    1/(2 sum phi), a trace fluid inside a solid) is not the slab whose
//    centroid the slab value is taken at. A trace fluid next to a steep rise
//    (BurnRate.ups: product gas at theta ~ 1e-13 in the HMX cells beside the
//    gas) then sends q_D (sum w phi <= 1/2, slab 2 q_D): the cell keeps a
//    round-off residue of its mass, and T = (M cv T)/M of the remaining
//    round-off went to 1.6e8 K (docs/mpmice.md, "C10").
//    The bound: with F1_D = q_D sum_out phi_f w_f (the first-order outflow
//    with the same weights) and F_D = sum_out |F_f| (the actual outflow),
//    every donor keeps at least half of what first order leaves:
//        F_D <= A_D = (q_D + F1_D) / 2.
//    Where F_D > A_D, the second-order corrections of D's outgoing faces are
//    scaled by s_D = (A_D - F1_D) / (F_D - F1_D) in [0, 1):
//        F_f <- F1_f + s_D (F_f - F1_f),   F1_f = phi_f w_f q_D,
//    so that F_D = A_D exactly. Each face has one donor, so the flux stays
//    single-valued (conservation to round-off is untouched). In a smooth
//    flow F_D - F1_D = O(dx) F1_D while A_D - F1_D = (q_D - F1_D)/2 is O(1):
//    inactive, the scheme stays second order (test_ice_advection).
// 2. Specific quantities psi (temperature, specific volume) carried with the
//    mass, F_psi,f = F_f psi_slab,f (compatible fluxes). The donor keeps
//    R_M = M_D - sum_out F_f of mass and R_Q = M_D psi_D - sum_out F_psi,f of
//    content. If R_Q / R_M lies in [psi_lo, psi_hi], the range of psi over D
//    and its six face neighbours, the new psi of D, (R_Q + inflows)/(R_M +
//    inflows), is a mean of values in the neighbourhood's range (the inflow
//    slab values are limited values of the neighbours): a local maximum
//    principle. A donor outside it (R_Q < psi_lo R_M or > psi_hi R_M, or
//    R_M <= 0 with more content out than in) sends its own value through its
//    outgoing faces, F_psi,f = F_f psi_D, so that R_Q = psi_D R_M. In a 1-D
//    smooth flow R_Q/R_M = psi_D - phi dpsi/2, within the range: inactive.
//    This replaces the positivity rule R_Q >= 0 of session 15 (guni2dRT),
//    which it contains for psi_lo >= 0.
#include "core/grid/Grid.h"
#include "ice/IceFields.h"
#include "ice/RadialWeights.h"

namespace tephra {

// When item 1 cannot act (pure ICE, no weights): the slab value of the
// limited gradient (IceAdvection.cpp) is q_D + alpha g_d (1 - |phi|)/2 with
// alpha |g_d|/2 <= alpha sum_d |g_d|/2 <= q_D - q_min, so it is at most
// 2 q_D - q_min <= 2 q_D for nonnegative masses (q_min >= 0), and the actual
// outflow F_D = sum_out phi_f slab_f <= 2 q_D S_D with S_D = sum_out phi_f,
// while F1_D = q_D S_D and A_D = q_D (1 + S_D)/2. F_D > A_D needs
// 2 S_D > (1 + S_D)/2, i.e. S_D > 1/3. Where every cell has S_D <= 0.3
// (check_outflux returns the largest S_D) no donor is limited, and the pass
// can be skipped: the fluxes are the same bits. The margin 1/3 - 0.3 covers
// the round-off of the screen form of S_D and of the slab values (relative
// 1e-15) many times over.
constexpr double kOutflowBoundInactive = 0.3;

// limit(D) = s_D for every interior cell D whose outflow exceeds A_D, 1 for
// the others (extra cells and ghosts are set to 1: exchange the ghosts after).
// weight: w_f per face (null: 1). Returns whether any cell is limited.
// radial (axisymmetric, ice/RadialWeights.h): the donor's r-face outflows
// count with r_f/r_D, the share of D's volume they take.
bool outflow_limits(const Grid& g, const CellScalars& q, const FaceScalars& u, const FaceScalars* weight, double dt,
                    const FaceScalars& flux, CellScalars& limit, const RadialWeights* radial = nullptr);

// F_f <- F1_f + s_D (F_f - F1_f) on every face of the interior cells whose
// donor D has limit(D) < 1 (limit valid in the ghosts).
void limit_outflow(const Grid& g, const CellScalars& q, const FaceScalars& u, const FaceScalars* weight, double dt,
                   const CellScalars& limit, FaceScalars& flux);

// flag(D) = 1 for the interior donors outside the range of item 2, else 0.
// mass_flux: the mass fluxes F_f, psi_flux: the F_psi,f. Returns whether any.
// radial: the r-face outflows weighted by r_f/r_D as in outflow_limits.
bool flag_out_of_range_donors(const Grid& g, const CellScalars& psi, const CellScalars& mass,
                              const FaceScalars& mass_flux, const FaceScalars& psi_flux, CellScalars& flag,
                              const RadialWeights* radial = nullptr);

// F_psi,f = F_f psi_D on the faces of interior cells whose donor is flagged
// (flag valid in the ghosts).
void donor_value_fluxes(const Grid& g, const CellScalars& psi, const FaceScalars& mass_flux, const CellScalars& flag,
                        FaceScalars& psi_flux);

}  // namespace tephra
