// MPMICE: the solids' volume fluxes from the particles and the fluids' share
// of each face (docs/mpmice.md "Volume fluxes"). A lagrangian (MPM) material
// is not advected by ICE; its cell mass is projected from the particles every
// step. The volume it moves through a face during the step therefore comes
// from the particles' motion (mpmice/SolidVolumeFlux.cpp fills
// lagrangian_mass_flux), not from a donor-cell flux of its projected volume
// fraction: with the donor-cell flux the solid's next projected theta_s and
// the fluids' advected theta_f disagree, and the difference is made up by
// compressing the fluid (the advect.ups pressure drift, the piston's
// swallowed air; measured in docs/mpmice.md).
//
// With F_s the solid's volume (in cell volumes) crossing a face of normal
// velocity u_s, the solid covers the face fraction
//   theta_s,face = F_s / (u_s dt / dx),   clamped to [0, 1],
// and a fluid m crosses through the rest of the face, in proportion to its
// share of the fluid volume of its donor cell D:
//   F_m = (u_m dt / dx) (1 - sum_s theta_s,face) theta_m,D / sum_fluids theta_D.
// The donor-cell flux is (u_m dt/dx) theta_m,D, so the fluid's flux (of mass,
// volume fraction, and the specific quantities carried with the mass) is the
// donor-cell flux times
//   chi = (1 - sum_s theta_s,face) / sum_fluids theta_D.
// Identity (the exact answer of MPMICE/advect.ups): with every material at the
// same u, sum_m F_m + sum_s F_s = u dt/dx on every face, so the volume
// fractions keep summing to 1 without a pressure change (delP = 0), and a
// uniform fluid state stays uniform while the solid moves through it.
#include <algorithm>
#include <cmath>

#include "core/grid/Loop.h"
#include "ice/AdvectionBounds.h"
#include "ice/FaceFluidShare.h"
#include "ice/IceComponent.h"
#include "ice/RadialWeights.h"

namespace tephra {

namespace {
IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }
}  // namespace

FaceScalars& IceComponent::lagrangian_mass_flux(std::size_t m) {
  if (lag_mass_flux_.size() != mats_.size()) lag_mass_flux_.resize(mats_.size());
  if (lag_mass_flux_[m].x.size() == 0) lag_mass_flux_[m] = FaceScalars(setup_.grid, 0);
  return lag_mass_flux_[m];
}

bool IceComponent::has_lagrangian_flux(std::size_t m) const {
  return m < lag_mass_flux_.size() && lag_mass_flux_[m].x.size() != 0;
}

// F_theta = F_M v_D / V, v_D the specific volume of the donor cell of the
// mass flux (the cell the mass leaves).
void IceComponent::lagrangian_volume_flux(std::size_t m, FaceScalars& flux) const {
  const Grid& g = setup_.grid;
  const double inv_V = 1.0 / g.cell_volume();
  const IceMaterialFields& f = mats_[m];
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      const GridArray<double>& FM = lag_mass_flux_[m].at(d, pi);
      GridArray<double>& out = flux.at(d, pi);
      const GridArray<double>& v = f.sp_vol_CC[pi];
      const IntVec3 e = IntVec3::Unit(d);
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const IntVec3 R(i, j, k);
        const double F = FM(R);
        out(R) = F * (F > 0 ? v(IntVec3(R - e)) : v(R)) * inv_V;
      });
    }
}

// theta_s,face of solid s on the face R of axis d (comment at the top):
// F_s / phi_s with F_s = F_M v_D / V, phi_s = u_s dt/dx (the solid's face
// velocity after exchange), clamped to [0, 1]. The face fraction of a flux
// against the face velocity is 0 (a round-off flux at the end of a row); a
// face whose solid face velocity is ~0 (the fluids locked to it hardly cross
// it) takes the mean of the two cells' solid fractions. Not continuous in
// phi_s (see freeze_solid_face_fractions).
IceComponent::SolidFaceFraction IceComponent::solid_face_fraction(std::size_t s, int d, std::size_t pi, const IntVec3& R,
                                                                  double dt) const {
  const IceMaterialFields& fs = mats_[s];
  const Grid& g = setup_.grid;
  const double FM = lag_mass_flux_[s].at(d, pi)(R);
  SolidFaceFraction out;
  if (FM == 0.0) return out;
  const IntVec3 L = R - IntVec3::Unit(d);
  const double inv_V = 1.0 / g.cell_volume(), dt_dx = dt / g.dx[d];
  const double Fv = FM * (FM > 0 ? fs.sp_vol_CC[pi](L) : fs.sp_vol_CC[pi](R)) * inv_V;
  out.phi = fs.vel_FCME.at(d, pi)(R) * dt_dx;  // signed
  if (std::abs(out.phi) <= 1e-14) {
    out.theta = std::clamp(0.5 * (fs.vol_frac_CC[pi](L) + fs.vol_frac_CC[pi](R)), 0.0, 1.0);
    return out;
  }
  out.theta = std::clamp(Fv / out.phi, 0.0, 1.0);
  return out;
}

// The semi-implicit pressure (ImplicitPressure.cpp) holds the solids' face
// fractions fixed over its outer iterations, at their values for the face
// velocities of the first iterate (p = p_eq, the explicit step's): the sum
// over the solids of theta_s,face, at most 1, per face. Why: theta_s,face =
// F_s/phi_s is not a continuous function of p. Where the pressure gradient
// of an iterate turns a solid's face velocity phi_s against the particles'
// flux F_s (a solid barely moving, phi_s ~ 0), theta_s,face jumps between 1
// (F_s/phi_s -> +inf, clamped) and 0 (F_s/phi_s < 0), the fluid's share of
// the face between 0 and 1 - (the other solids), and the residual by the
// whole fluid flux of the face. SteadyBurn_2dRT step 12 (docs/mpmice.md):
// the HMX face velocity on a face next to the steel flips between -3.6e-12
// and +7.3e-9 (F_HMX = -1.4e-9) from one outer iteration to the next, the
// gas flux of the face between 0 and 3.4e-7 (tolerance 1.01e-7), and the
// outer iteration cycles. With theta_face fixed the residual is continuous
// and piecewise linear in the face velocities (donor switch, positivity
// limit), and its derivative is the matrix of ImplicitPressureMatrix.cpp.
// The explicit step evaluates theta_face once, at the same face velocities.
void IceComponent::freeze_solid_face_fractions(double dt) {
  const Grid& g = setup_.grid;
  std::vector<std::size_t> solids;
  for (std::size_t s = 0; s < mats_.size(); ++s)
    if (has_lagrangian_flux(s)) solids.push_back(s);
  if (lag_theta_face_.x.size() == 0) lag_theta_face_ = FaceScalars(g, 0);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      GridArray<double>& th = lag_theta_face_.at(d, pi);
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const IntVec3 R(i, j, k);
        double theta_face = 0;
        for (std::size_t s : solids) theta_face += solid_face_fraction(s, d, pi, R, dt).theta;
        th(R) = std::min(theta_face, 1.0);
      });
    }
  lag_theta_frozen_ = true;
}

double IceComponent::solids_face_fraction(int d, std::size_t pi, const IntVec3& R, double dt) const {
  if (lag_theta_frozen_) return lag_theta_face_.at(d, pi)(R);
  double theta_face = 0;
  for (std::size_t s = 0; s < mats_.size(); ++s)
    if (has_lagrangian_flux(s)) theta_face += solid_face_fraction(s, d, pi, R, dt).theta;
  return std::min(theta_face, 1.0);
}

// flux *= chi (above) on every face, for fluid m, with a positivity limit:
// where the scaled outflow of a donor cell, sum_out phi chi (in units of its
// content), exceeds max(1/2, sum_out phi) its outgoing chi are scaled down to
// that bound. chi > 1 (a fluid leaving through more face area than its share
// of the donor cell) cannot then empty a cell in one step; the bound is far
// from active in a smooth flow (sum_out phi ~ the CFL number) and acts in
// cells where a trace of fluid sits inside a solid (theta_f ~ tiny_rho), whose
// chi = (1 - theta_s,face)/theta_f is round-off over round-off.
bool IceComponent::scale_fluid_flux(std::size_t m, double dt, FaceScalars& flux) {
  if (setup_.materials[m].lagrangian) return false;
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  std::vector<std::size_t> solids;
  for (std::size_t s = 0; s < nm; ++s)
    if (has_lagrangian_flux(s)) solids.push_back(s);
  if (solids.empty()) return false;
  if (lag_chi_.x.size() == 0) {
    lag_chi_ = FaceScalars(g, 0);
    lag_weight_ = FaceScalars(g, 0);
    lag_limit_ = CellScalars(g, 2);
  }
  const FaceScalars& u = mats_[m].vel_FCME;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      const IntVec3 e = IntVec3::Unit(d);
      GridArray<double>& chi = lag_chi_.at(d, pi);
      const GridArray<double>& um = u.at(d, pi);
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const IntVec3 R(i, j, k), L = R - e;
        const double theta_face = solids_face_fraction(d, pi, R, dt);
        double fluid_L = 0, fluid_R = 0;
        for (std::size_t q = 0; q < nm; ++q)
          if (!setup_.materials[q].lagrangian) {
            fluid_L += mats_[q].vol_frac_CC[pi](L);
            fluid_R += mats_[q].vol_frac_CC[pi](R);
          }
        const double fluid = um(R) > 0 ? fluid_L : fluid_R;  // the donor's fluid fraction
        // The fluids' share of the face, 1 - theta_s,face, at most the larger
        // fluid fraction of the two cells (face_fluid_share, comment above).
        chi(R) = face_fluid_share(theta_face, fluid_L, fluid_R) / fluid;
      });
    }
  // The positivity limit of each interior donor cell (1 where inactive).
  // Outflows in units of the donor's content: axisymmetric, an r-face's
  // flux enters the donor's balance times r_f / r_i (ice/RadialWeights.h),
  // 2 at the outer face of the axis cell. Without that weight the limit let
  // the axis cell send sum phi chi L = 1/2 through that face, i.e. all of
  // its content: the trace gas of a steel-filled axis cell of the cookoff
  // deck went to M = -4e-37 and T = -3e13 K (docs/mpmice.md "Session 27:
  // the axis trace gas").
  const RadialWeights* rw = radial();
  lag_limit_.fill(1.0);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      double out = 0, out_scaled = 0;
      for (int d = 0; d < 3; ++d) {
        const IntVec3 hi = c + IntVec3::Unit(d);
        const double a_lo = rw && d == 0 ? rw->lo_row(i)[0] : 1.0, a_hi = rw && d == 0 ? rw->hi_row(i)[0] : 1.0;
        const double phi_lo = -u.at(d, pi)(c) * dt / g.dx[d] * a_lo, phi_hi = u.at(d, pi)(hi) * dt / g.dx[d] * a_hi;
        if (phi_lo > 0) out += phi_lo, out_scaled += phi_lo * lag_chi_.at(d, pi)(c);
        if (phi_hi > 0) out += phi_hi, out_scaled += phi_hi * lag_chi_.at(d, pi)(hi);
      }
      const double bound = std::max(0.5, out);
      if (out_scaled > bound) lag_limit_[pi](c) = bound / out_scaled;
    });
  halo_->exchange(lag_limit_);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      const IntVec3 e = IntVec3::Unit(d);
      GridArray<double>& F = flux.at(d, pi);
      GridArray<double>& w = lag_weight_.at(d, pi);
      const GridArray<double>& chi = lag_chi_.at(d, pi);
      const GridArray<double>& um = u.at(d, pi);
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const IntVec3 R(i, j, k);
        const IntVec3 D = um(R) > 0 ? IntVec3(R - e) : R;
        w(R) = chi(R) * lag_limit_[pi](D);
        F(R) *= w(R);
      });
    }
  return true;
}

// ice/AdvectionBounds.h item 1 on the mass fluxes flux_ of fluid m (after
// scale_fluid_flux: weight = its chi L, or null in pure ICE): a donor keeps
// at least half of what its first-order outflow leaves. In MPMICE this is
// the cell of a trace fluid inside a solid, whose weighted outflow
// sum phi chi L reaches 1/2 of its content (the limit above) and whose
// second-order slab value reaches twice its content.
// largest_outflow: this rank's largest sum_out phi (check_outflux). Without
// weights and below kOutflowBoundInactive no donor can be limited
// (AdvectionBounds.h), so the pass is skipped; every rank still takes part
// in the layout_.any below.
void IceComponent::bound_outflow(std::size_t m, double dt, const FaceScalars* weight, double largest_outflow) {
  const Grid& g = setup_.grid;
  if (outflow_limit_.size() == 0) outflow_limit_ = CellScalars(g, 2);
  const bool may_act = weight != nullptr || !(largest_outflow <= kOutflowBoundInactive);
  const bool any =
      may_act && outflow_limits(g, mass_L_[m], mats_[m].vel_FCME, weight, dt, flux_, outflow_limit_, radial());
  if (!layout_.any(any)) return;
  halo_->exchange(outflow_limit_);
  limit_outflow(g, mass_L_[m], mats_[m].vel_FCME, weight, dt, outflow_limit_, flux_);
}

}  // namespace tephra
