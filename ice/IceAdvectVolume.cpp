// Advection of the specific volume (step 12, docs/ice.md "Specific volume
// as volume content").
//
// Uintah advects M v (v = sp_vol, 1/rho_micro) as a specific quantity riding
// on the mass fluxes, F_Mv = F_M v_slab, with v's own limited gradient. At
// second order the product of the two independently limited slab values,
// rho_slab v_slab, is not the volume fraction the slab carries: where rho and
// v change by orders of magnitude between neighbours (a near-vacuum,
// Toro's test 2) linear slabs of rho and of v = theta/rho give
// rho_slab v_slab ~ (2 + r + 1/r)/4 for a neighbour ratio r, i.e. a face
// carrying several times its swept volume. theta = rho v then drifts far from
// its equilibrium value (measured theta = 2.5 next to the emptied cells of
// Toro 2, N = 100) and the cell's M v finally goes negative (exit 4).
//
// Here the volume content Q = M_L v_L = theta_L V is advected like the mass,
// as a density-like quantity with its own limited slab values:
//   F_Q = phi Q_slab,   (M v)_new = Q + sum_in F_Q - sum_out F_Q,   v_new = (M v)_new / M_new.
// Properties (each checked by tests/verification/test_ice_riemann.cpp and
// test_ice_advection.cpp):
//  - first order: F_Q = phi M_D v_D = F_M v_D, identical to the compatible flux;
//  - uniform v: Q = v M_L, the limiter factor alpha is invariant under scaling,
//    so Q_slab = v M_slab and v stays uniform to round-off (compatibility);
//  - Q_slab lies within the donor's neighbour range like the mass's slab, so
//    the volume content stays positive wherever the mass does (one direction:
//    phi (1 + (1 - phi)) Q_D <= Q_D for the monotonized-central slope).
// A documented departure from Uintah (which weights v's vertex values with
// the mass centroids, mass_massVertex_ratio).
#include "core/grid/Loop.h"
#include "ice/IceAdvection.h"
#include "ice/IceComponent.h"

namespace tephra {

void IceComponent::advect_specific_volume(std::size_t m, double dt) {
  const Grid& g = setup_.grid;
  IceMaterialFields& f = mats_[m];
  CellScalars& Q = spv_L_[m];  // overwritten: v_L is not used after the advection
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    double* q = Q[pi].data();
    const double* mass = mass_L_[m][pi].data();
    const std::size_t n = Q[pi].size();
    for (std::size_t c = 0; c < n; ++c) q[c] *= mass[c];  // all storage: interior, extra cells, ghosts
  }
  density_fluxes(g, setup_.advection, Q, f.vel_FCME, dt, flux2_);
  flux_divergence(g, flux2_, dq_);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell(g.patches[pi].cells(), [&](int i, int j, int k) {
      f.sp_vol_CC[pi](i, j, k) = (Q[pi](i, j, k) + dq_[pi](i, j, k)) / mass_new_[pi](i, j, k);
    });
}

}  // namespace tephra
