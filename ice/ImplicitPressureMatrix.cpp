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
//   F_m = phi_m (1 - sum_s theta_s,face) r_m,   r_m = theta_m,D / sum_fluids theta_D,
//   theta_s,face = F_s / phi_s  (clamped to [0, 1]),  phi = u^ME dt/dx,
// and both phi_m and phi_s change with dp (the solid's face velocity is the
// one the exchange locks the fluid to). Differentiating (F_s fixed):
//   dF_m = r_m [ (1 - theta_face) dphi_m + sum_s theta_s,face (phi_m/phi_s) dphi_s ],
// the second sum over the solids whose theta_s,face = F_s/phi_s is strictly
// inside (0, 1). With the fluid locked to the solid (phi_m = phi_s, svFC_m
// = svFC_s) the bracket is the full face, dphi_m: in a cell the solid fills
// (theta_gas ~ 1e-4) the fluid still answers with the whole face, which the
// ICE matrix (theta_f ~ 1e-4) underestimated by 1e4 (session 14: the
// 2-cycle at step 10 of SteadyBurn_2dRT). Terms of the derivative left out:
// the switch of the donor cell D and of the clamps, and the positivity limit of
// scale_fluid_flux (a factor <= 1 on the flux, only in cells with a trace of
// fluid; leaving it out overestimates a_f, which slows the outer iteration
// but cannot make it oscillate); a negative (phi_m/phi_s) (the fluid crossing
// against the solid) is dropped (keeps the matrix an M-matrix). The outer
// iterations carry the exact residual, so these only change how fast it
// converges, not the answer.
#include <algorithm>
#include <cmath>

#include "core/grid/Loop.h"
#include "ice/Exchange.h"
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
  // MPMICE: the solids' face fractions (the same for every fluid).
  bool coupled = false;
  double theta_face = 0;
  SolidFaceFraction sf[kMaxExchangeMaterials];
  for (std::size_t s = 0; s < nm; ++s)
    if (has_lagrangian_flux(s)) {
      coupled = true;
      sf[s] = solid_face_fraction(s, d, pi, R, dt);
      theta_face += sf[s].theta;
    }
  const bool face_closed = theta_face >= 1.0;  // the solids cover the face: no fluid crosses
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
    if (setup_.materials[m].lagrangian || face_closed) continue;
    const IceMaterialFields& f = mats_[m];
    const double um = f.vel_FCME.at(d, pi)(R);
    const IntVec3 D = um > 0 ? L : R;  // donor cell, as scale_fluid_flux
    double fluid = 0;
    for (std::size_t q = 0; q < nm; ++q)
      if (!setup_.materials[q].lagrangian) fluid += mats_[q].vol_frac_CC[pi](D);
    const double r = f.vol_frac_CC[pi](D) / fluid;
    double bracket = (1.0 - theta_face) * svFC[m];
    const double phi_m = um * dt / g.dx[d];
    for (std::size_t s = 0; s < nm; ++s)
      if (sf[s].varies) bracket += sf[s].theta * std::max(0.0, phi_m / sf[s].phi) * svFC[s];
    a += r * bracket;
  }
  return a * r2;
}

// Stencil of every interior cell from the face coefficients; boundary faces as
// in the comment of ImplicitPressure.cpp (Dirichlet pressure: a_f on the
// diagonal only; Neumann: a_f drops out).
void IceComponent::assemble_pressure_matrix(double dt) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
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
