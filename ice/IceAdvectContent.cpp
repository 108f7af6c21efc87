// Advection of the temperature and the specific volume as contents (step 12,
// docs/algorithms/ice.md "Temperature and specific volume as contents").
//
// Uintah advects M T and M v (v = sp_vol = 1/rho_micro) as specific
// quantities riding on the mass fluxes, F = F_M psi_slab, each psi with its
// own limited gradient. At second order the product of two independently
// limited slab values, rho_slab v_slab, is not the volume fraction the slab
// carries: where rho changes by orders of magnitude between neighbours (the
// near-vacuum of Toro's test 2) linear slabs of rho and of v = theta/rho give
// rho_slab v_slab ~ (2 + r + 1/r)/4 for a neighbour ratio r, a face carrying
// several times its swept volume. theta = rho v then drifted to 2.5 next to
// the emptied cells (Toro 2, N = 100) and M v finally went negative (exit 4).
//
// Here the contents Q = M_L psi_L (psi = T: Q/V is rho T, proportional to the
// pressure of an ideal gas; psi = v: Q = theta_L V) are advected like the
// mass, as density-like quantities with their own limited slab values:
//   F_Q = phi Q_slab,  Q_new = Q + sum_in F_Q - sum_out F_Q,  psi_new = Q_new / M_new.
// Properties (tests: test_ice_riemann, test_ice_advection, test_ice_implicit):
//  - first order: F_Q = phi M_D psi_D = F_M psi_D, the compatible flux;
//  - uniform psi: Q = psi M_L, the limiter factor alpha is invariant under
//    scaling, so Q_slab = psi M_slab and psi stays uniform to round-off;
//  - a contact in pressure equilibrium (uniform p, theta; rho T = p/R
//    uniform) keeps T/v uniform exactly: both contents are uniform, so p
//    stays uniform (the compatible form has this too: T and v are
//    proportional there and get the same limiter);
//  - Q_slab lies within the donor's neighbour range as the mass's slab does,
//    so the contents stay positive wherever the mass does.
// One material only: its pressure comes from the advected v directly (p(1/v, T)),
// so a drifting theta = rho v is a wrong pressure; a mixture re-equilibrates
// sum theta = 1 every step, and there the contents of a trace material
// (M ~ 1e-13 of its neighbours at a block edge) have slab ratios Q_slab/M_slab
// outside the neighbours' psi range (measured: a trace material overheated
// and cut the time step by 25 % in test_ice_advection's block at second
// order), while the compatible psi_slab is a limited value of psi itself. So
// mixtures keep Uintah's compatible fluxes.
// A documented departure from Uintah (which weights the vertex values of the
// specific quantities with the mass centroids, mass_massVertex_ratio).
//
// Positivity of the mixture contents (T and v are positive): a second-order
// slab value psi_slab may exceed the donor's psi_D (up to its neighbours'
// maximum), so a donor that sends most of its mass out in one step can send
// more content than it holds, sum_out F_M psi_slab > M_L psi_L, and its
// psi_new = Q_new / M_new turns negative. This happens to a trace material
// (theta ~ 1e-13) inside an MPMICE solid, whose face fluxes the solids'
// volume fluxes scale up to half its mass per face (IceLagrangianFlux.cpp;
// guni2dRT.ups, step 5: v = -0.67 m^3/kg). Such a donor's outgoing faces
// carry its own value instead, F = F_M psi_D (first order). Then every cell
// keeps Q_new >= 0: a flagged donor sends psi_D sum_out F_M <= psi_D M_L (its
// mass outflow is at most its mass), an unflagged one at most M_L psi_L, and
// inflows are >= 0. A donor that does not overdraw keeps its bits.
// Session 17: the rule is now the local range of ice/AdvectionBounds.h
// (item 2): R_Q/R_M of the donor within its neighbours' psi range, which
// bounds the temperature of a trace (the BurnRate.ups 1.6e8 K) as well.
#include <algorithm>

#include "core/grid/Loop.h"
#include "ice/AdvectionBounds.h"
#include "ice/IceAdvection.h"
#include "ice/IceComponent.h"
#include "ice/RowLoop.h"

namespace tephra {
namespace {

// out = (base + net inflow of the face fluxes F) / mass_new over the interior
// cells, one row at a time; the net inflow is flux_divergence's expression
// (x, then y, then z differences), so the bits are those of
// flux_divergence followed by a cell loop.
template <class Base>
void update_from_fluxes(const Grid& g, const FaceScalars& F, Base&& base, const CellScalars& mass_new,
                        CellScalars& out, const RadialWeights* rw) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange cells = g.patches[pi].cells();
    const int i0 = cells.lo[0], n = cells.hi[0] - i0;
    for_each_row(cells, [&](int j, int k) {
      const double* fx = row_ptr(F.at(0, pi), i0, j, k);
      const double *fy0 = row_ptr(F.at(1, pi), i0, j, k), *fy1 = row_ptr(F.at(1, pi), i0, j + 1, k);
      const double *fz0 = row_ptr(F.at(2, pi), i0, j, k), *fz1 = row_ptr(F.at(2, pi), i0, j, k + 1);
      const double* m_new = row_ptr(mass_new[pi], i0, j, k);
      double* o = row_ptr(out[pi], i0, j, k);
      const double* wlo = rw ? rw->lo_row(i0) : nullptr;  // axisymmetric: r-faces times r_f/r_i
      const double* whi = rw ? rw->hi_row(i0) : nullptr;
      for (int c = 0; c < n; ++c) {
        const double dq = rw ? (wlo[c] * fx[c] - whi[c] * fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c])
                             : (fx[c] - fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c]);
        o[c] = (base(pi, i0 + c, j, k) + dq) / m_new[c];
      }
    });
  }
}

}  // namespace

// The range rule of ice/AdvectionBounds.h item 2 (it contains the
// positivity rule above): donors whose remaining content over remaining mass
// leaves the range of psi over the cell and its face neighbours (flagged in
// `flag`, a cell scratch with ghosts, exchanged so that both patches of a
// shared face agree) send F_M psi_D through their outgoing faces.
void IceComponent::keep_contents_nonnegative(std::size_t m, const CellScalars& psi_L, CellScalars& flag) {
  const Grid& g = setup_.grid;
  const bool any = flag_out_of_range_donors(g, psi_L, mass_L_[m], flux_, flux2_, flag, radial());
  if (!layout_.any(any)) return;
  halo_->exchange(flag);
  donor_value_fluxes(g, psi_L, flux_, flag, flux2_);
}

void IceComponent::advect_content(std::size_t m, const CellScalars& psi_L, CellScalars& out, double dt) {
  const Grid& g = setup_.grid;
  if (mats_.size() > 1) {  // compatible fluxes F_M psi_slab (flux_ holds m's mass fluxes)
    specific_fluxes(g, setup_.advection, psi_L, mats_[m].vel_FCME, flux_, dt, flux2_);
    keep_contents_nonnegative(m, psi_L, content_);  // content_: scratch for the donor flags
    const CellScalars& mass_L = mass_L_[m];
    update_from_fluxes(g, flux2_, [&](std::size_t pi, int i, int j, int k) {
      return mass_L[pi](i, j, k) * psi_L[pi](i, j, k);
    }, mass_new_, out, radial());
    return;
  }
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    double* q = content_[pi].data();
    const double* psi = psi_L[pi].data();
    const double* mass = mass_L_[m][pi].data();
    const std::size_t n = content_[pi].size();
    for (std::size_t c = 0; c < n; ++c) q[c] = mass[c] * psi[c];  // all storage: interior, extra cells, ghosts
  }
  density_fluxes(g, setup_.advection, content_, mats_[m].vel_FCME, dt, flux2_);
  update_from_fluxes(g, flux2_, [&](std::size_t pi, int i, int j, int k) { return content_[pi](i, j, k); },
                     mass_new_, out, radial());
}

}  // namespace tephra
