// The matrix of the implicit pressure correction (ImplicitPressure.cpp):
//   (sum_m theta_m kappa_m + sum_faces a_f) dp_C - sum_faces a_f dp_nb = -R(p),
// a_f = -d(net volume flux through the face)/d(dp_R - dp_L), per face.
//
// Face velocity response (Uintah: ScalarExch::vel_FC_exchange computes
// sp_vol_FC for the implicit solve; ICE::setupMatrix sums vol_frac_FC *
// sp_vol_FC over the materials). A correction dp changes every material's
// face velocity before exchange by -dt v_f grad dp (eq. 26.1, v_f =
// 2 v_L v_R/(v_L + v_R)); the face exchange is linear, u^ME = E^-1 u* with E
// the exchange matrix of ice/Exchange.h (theta_f = (theta_L + theta_R)/2), so
//   du^ME_m = -dt svFC_m grad dp,   svFC = E^-1 v_f   (exact, the same E),
// i.e. the exchange is in the matrix. Without it a stiff exchange (K ~ 1e10
// to 1e15 in the MPMICE decks, the fluid locked to a solid) makes the matrix
// believe the fluid answers with its own v_f, while it answers with about
// 1/rho_mixture: the outer iteration then crawls (session 14: the block at
// 5 m/s did not converge in 10 outer iterations).
//
// ICE alone: a_f = sum_m theta_f,m svFC_m dt^2/dx^2, theta_f = (theta_L +
// theta_R)/2 (the donor-cell value is the exact derivative; the mean keeps
// the matrix symmetric and fixed over the outer iterations).
//
// MPMICE (a solid with particle volume fluxes, IceLagrangianFlux.cpp): the
// solid's flux F_s comes from the particles' motion and does not change with
// p, so the solid has no a_f of its own. A fluid m crosses through the face
// area the solids leave,
//   F_m = phi_m theta_m,slab chi L_D,  chi = (1 - theta_face) / sum_fluids theta_D,
// phi_m = u^ME_m dt/dx, theta_m,slab the advected value of the donor's
// volume fraction (theta_m,D at first order, the limited slab value at second
// order), L_D <= 1 the positivity limit of the donor cell (scale_fluid_flux).
// theta_face (the solids' face fractions) is held fixed over the outer
// iterations (freeze_solid_face_fractions: F_s/phi_s jumps where phi_s
// changes sign, the SteadyBurn_2dRT cycle), so F_m is linear in phi_m with
// the slope s_m = F_m/phi_m (fluid_face_shares; at phi_m = 0 the first-order
// value theta_m,R chi L_R of the donor R) and
//   a_f = sum_fluids s_m svFC_m dt^2/dx^2.
// Left out of the derivative (measured against finite differences by
// IceComponent::implicit_jacobian_row, ImplicitPressureCheck.cpp): the
// switch of the donor cell where phi_m changes sign (F_m is continuous
// there), the slab value's own dependence on phi_m (O(phi) at second order)
// and the limit's L_D (its total outflow is fixed where it is active). The
// outer iterations carry the exact residual, so these change only how fast it
// converges, not the answer.
// Session 15 used a_f = r_m [(1 - theta_face) svFC_m + sum_s theta_s,face
// (phi_m/phi_s) svFC_s] with theta_face recomputed at every iterate: the
// derivative of a residual that jumps (above), and first-order shares where
// the flux is second order (2x the Jacobian in trace-gas cells).
#include <algorithm>
#include <cmath>

#include "core/grid/Loop.h"
#include "ice/Exchange.h"
#include "ice/IceAdvection.h"
#include "ice/IceComponent.h"

namespace tephra {

double IceComponent::pressure_face_coefficient(int d, std::size_t pi, const IntVec3& R, double dt, bool boundary,
                                               int face) const {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  const IntVec3 L = R - IntVec3::Unit(d);
  const double r2 = dt * dt / (g.dx[d] * g.dx[d]);
  double theta[kMaxExchangeMaterials], sv[kMaxExchangeMaterials], svFC[kMaxExchangeMaterials];
  for (std::size_t m = 0; m < nm; ++m) {
    const IceMaterialFields& f = mats_[m];
    theta[m] = 0.5 * (f.vol_frac_CC[pi](L) + f.vol_frac_CC[pi](R));
    const double vL = f.sp_vol_CC[pi](L), vR = f.sp_vol_CC[pi](R);
    sv[m] = 2.0 * vL * vR / (vL + vR);
    svFC[m] = sv[m];
  }
  if (nm > 1) solve_exchange(dt, {theta, nm}, {sv, nm}, {}, setup_.K, {svFC, nm});
  const bool coupled = !imp_share_.empty();  // MPMICE: fluid_face_shares ran for this iterate
  double a = 0;
  for (std::size_t m = 0; m < nm; ++m) {
    if (boundary) {
      const BCKind vk = setup_.bcs[m][face][kBcVelocity].kind;
      if (vk == BCKind::Dirichlet || vk == BCKind::Symmetry) continue;  // face velocity fixed
    }
    if (!coupled) {
      a += theta[m] * svFC[m];
      continue;
    }
    if (setup_.materials[m].lagrangian) continue;  // the particles' flux: no response to p
    a += std::max(0.0, imp_share_[m].at(d, pi)(R)) * svFC[m];
  }
  return a * r2;
}

// s_m = F_m/phi_m of every fluid on every face at the current iterate (the
// comment at the top): the fluid's volume flux as sum_volume_flux_and_kappa
// computes it (density_fluxes, scale_fluid_flux) divided by phi_m.
void IceComponent::fluid_face_shares(double dt) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  imp_share_.resize(nm);
  for (std::size_t m = 0; m < nm; ++m) {
    if (setup_.materials[m].lagrangian) continue;
    IceMaterialFields& f = mats_[m];
    FaceScalars& share = imp_share_[m];
    if (share.x.size() == 0) share = FaceScalars(g, 0);
    density_fluxes(g, setup_.advection, f.vol_frac_CC, f.vel_FCME, dt, share);
    scale_fluid_flux(m, dt, share);  // also leaves fluid m's chi and limit in lag_chi_, lag_limit_
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for (int d = 0; d < 3; ++d) {
        const double dt_dx = dt / g.dx[d];
        GridArray<double>& s = share.at(d, pi);
        const GridArray<double>& u = f.vel_FCME.at(d, pi);
        const GridArray<double>& chi = lag_chi_.at(d, pi);
        const IndexRange faces{g.patches[pi].lo, g.patches[pi].hi + IntVec3::Unit(d)};
        for_each_cell(faces, [&](int i, int j, int k) {
          const IntVec3 R(i, j, k);
          const double phi = u(R) * dt_dx;
          s(R) = phi != 0.0 ? s(R) / phi : f.vol_frac_CC[pi](R) * chi(R) * lag_limit_[pi](R);
        });
      }
  }
}

// Stencil of every interior cell from the face coefficients; boundary faces as
// in the comment of ImplicitPressure.cpp (Dirichlet pressure: a_f on the
// diagonal only; Neumann: a_f drops out).
void IceComponent::assemble_pressure_matrix(double dt) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  bool coupled = false;
  for (std::size_t m = 0; m < nm; ++m) coupled = coupled || has_lagrangian_flux(m);
  if (coupled) fluid_face_shares(dt);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& patch = g.patches[pi];
    for_each_cell(patch.cells(), [&](int i, int j, int k) {
      const IntVec3 C(i, j, k);
      double centre = 0;
      for (std::size_t m = 0; m < nm; ++m) {
        const IceMaterialFields& f = mats_[m];
        const double c = f.speedSound_CC[pi](C);
        centre += f.vol_frac_CC[pi](C) * f.sp_vol_CC[pi](C) / (c * c);
      }
      for (int d = 0; d < 3; ++d) {
        for (int side = 0; side < 2; ++side) {
          const IntVec3 N = side == 0 ? IntVec3(C - IntVec3::Unit(d)) : IntVec3(C + IntVec3::Unit(d));
          const IntVec3 R = side == 0 ? C : N;  // the face between C and N
          const int entry = 1 + 2 * d + side;   // kWest, kEast, ...
          const bool boundary = !g.periodic[d] && (N[d] < 0 || N[d] >= g.cells[d]);
          const int face = 2 * d + side;  // GridFace order x-, x+, y-, ...
          const double a = pressure_face_coefficient(d, pi, R, dt, boundary, face);
          if (boundary) {
            stencil_[entry][pi](C) = 0.0;
            if (setup_.bcs[0][face][kBcPressure].kind == BCKind::Dirichlet) centre += a;
          } else {
            stencil_[entry][pi](C) = -a;
            centre += a;
          }
        }
      }
      stencil_[kCenter][pi](C) = centre;
    });
  }
}

}  // namespace tephra
