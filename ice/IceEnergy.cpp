// Total-energy conservation of the ICE step (docs/algorithms/ice.md "Total energy at
// shocks"). Uintah's ICE evolves the internal energy M c_v T with the work
// term V theta kappa p delP (eq. 26.7) and the momentum with the face
// pressures p* (eq. 26.5), and advects mass and momentum separately (step 10).
// Neither pair is consistent with a conserved total energy E = M (c_v T +
// |u|^2/2): the kinetic energy that the (upwind, limited) momentum advection
// removes at a shock and the mismatch between the cell-pressure work and the
// face-pressure work never reach the internal energy. The two corrections
// below return them, each as a difference of face fluxes, so that the sum
// over the cells of M (c_v T + |u|^2/2) changes only by the boundary fluxes
// (to round-off). Both are on with <CFD><ICE><conserveTotalEnergy> true (the
// default, a Tephra extension; false gives Uintah's equations).
//
// 1. Lagrangian phase (after the momentum and internal-energy sources, before
//    the exchange), per material m and cell c:
//      W_m = V sum_faces p*_f A_f(theta_m)            A_f = inflow of theta_m through face f
//                                                      with u*_m (the delP_Dilatate fluxes)
//      C_m = W_m - V theta_m kappa_m p_c delP - F_p . (u + u_L)/2
//    F_p = -dt V theta_m grad p* (the pressure impulse of the momentum
//    equation) and F_p . (u + u_L)/2 the part of 1/2 M (|u_L|^2 - |u|^2) that
//    F_p does (exact split for constant M). (Me)_L += C_m. Summed over the
//    materials of a cell, V theta kappa p delP sums to V p_c sum_f A_f and
//    theta sums to 1, so the cell's total energy changes by
//    V sum_f p*_f sum_m A_f,m: a face flux (p* times the swept volume),
//    conservative; in smooth flow C_m = O(dt dx).
// 2. Advection (DeBar 1974, "Fundamentals of the KRAKEN code"), per material
//    and cell, with the face fluxes of mass F and momentum F u_slab of step 10:
//      K_adv = 1/2 M_L |u_L|^2 + sum_f (+-) 1/2 F_f |u_slab,f|^2   (the advected kinetic energy)
//      D     = K_adv - 1/2 M_new |u_new|^2
//    and (M c_v T)_new += D. The kinetic-energy fluxes 1/2 F |u_slab|^2 are
//    face fluxes, so sum_c (K_new + D) = sum_c K_L + boundary fluxes. For
//    first-order (donor-cell) fluxes D >= 0 by convexity of |p|^2/M.
// Mixtures of ICE materials (below, "Mixtures"): the cell's corrections are
// computed from the material sums and split among the materials by mass, and
// the kinetic energy the momentum exchange removes is returned as heat.
// MPMICE runs keep Uintah's equations.
#include <cmath>
#include <stdexcept>

#include "core/grid/Loop.h"
#include "ice/IceAdvection.h"
#include "ice/Exchange.h"
#include "ice/IceComponent.h"
#include "ice/RowLoop.h"

namespace tephra {

// Correction 1, first part, before the Lagrangian values (one material):
// work_corr_[0] = V sum_f p*_f A_f(theta) - V theta kappa p_c delP.
// A_f(theta) are the volume-fraction fluxes that sum_volume_flux_and_kappa
// left in flux_ for delP_Dilatate: its last call (explicit increment, or the
// converged outer iteration of the implicit solve) used the final face
// velocities, and nothing writes flux_ before the Lagrangian phase, so they
// are reused instead of recomputed (a full limited-flux pass per step).
void IceComponent::face_pressure_work(double /*dt*/) {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  if (mats_.size() != 1) throw std::logic_error("face_pressure_work: one ICE material only (IceEnergy.cpp)");
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const IceMaterialFields& f = mats_[m];
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      const IndexRange cells = g.patches[pi].cells();
      const int i0 = cells.lo[0], n = cells.hi[0] - i0;
      for_each_row(cells, [&](int j, int k) {
        // Face rows: the low faces of the row's cells (pf*0, A*0) and the high faces (pf*1, A*1).
        const double* pfx = row_ptr(press_FC_.at(0, pi), i0, j, k);
        const double* Ax = row_ptr(flux_.at(0, pi), i0, j, k);
        const double *pfy0 = row_ptr(press_FC_.at(1, pi), i0, j, k), *pfy1 = row_ptr(press_FC_.at(1, pi), i0, j + 1, k);
        const double *Ay0 = row_ptr(flux_.at(1, pi), i0, j, k), *Ay1 = row_ptr(flux_.at(1, pi), i0, j + 1, k);
        const double *pfz0 = row_ptr(press_FC_.at(2, pi), i0, j, k), *pfz1 = row_ptr(press_FC_.at(2, pi), i0, j, k + 1);
        const double *Az0 = row_ptr(flux_.at(2, pi), i0, j, k), *Az1 = row_ptr(flux_.at(2, pi), i0, j, k + 1);
        const double* speed = row_ptr(f.speedSound_CC[pi], i0, j, k);
        const double* sp_vol = row_ptr(f.sp_vol_CC[pi], i0, j, k);
        const double* vol_frac = row_ptr(f.vol_frac_CC[pi], i0, j, k);
        const double* press = row_ptr(press_CC_[pi], i0, j, k);
        const double* delP = row_ptr(delP_Dilatate_[pi], i0, j, k);
        double* corr = row_ptr(work_corr_[m][pi], i0, j, k);
        const RadialWeights* rw = radial();  // axisymmetric: r-faces times r_f/r_i (ice/RadialWeights.h)
        const double* wlo = rw ? rw->lo_row(i0) : nullptr;
        const double* whi = rw ? rw->hi_row(i0) : nullptr;
        for (int c = 0; c < n; ++c) {
          double work = 0;  // inflow through the low face minus outflow through the high face, x, y, z
          if (rw)
            work += wlo[c] * (pfx[c] * Ax[c]) - whi[c] * (pfx[c + 1] * Ax[c + 1]);
          else
            work += pfx[c] * Ax[c] - pfx[c + 1] * Ax[c + 1];
          work += pfy0[c] * Ay0[c] - pfy1[c] * Ay1[c];
          work += pfz0[c] * Az0[c] - pfz1[c] * Az1[c];
          const double ss = speed[c];
          const double kappa = sp_vol[c] / (ss * ss);
          const double cell_work = V * vol_frac[c] * kappa * press[c] * delP[c];
          corr[c] = V * work - cell_work;
        }
      });
    }
  }
}

// Correction 1, second part, for material m on patch pi once its Lagrangian
// momentum and internal energy are known: (Me)_L += work_corr_ - F_p . u_mid,
// temp_L_ = (Me)_L / (M_L c_v).
void IceComponent::add_face_pressure_work(std::size_t m, std::size_t pi, double dt) {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  IceMaterialFields& f = mats_[m];
  const IndexRange cells = g.patches[pi].cells();
  const int i0 = cells.lo[0], n = cells.hi[0] - i0;
  const double dx[3] = {g.dx[0], g.dx[1], g.dx[2]};
  for_each_row(cells, [&](int j, int k) {
    const double* pfx = row_ptr(press_FC_.at(0, pi), i0, j, k);
    const double *pfy0 = row_ptr(press_FC_.at(1, pi), i0, j, k), *pfy1 = row_ptr(press_FC_.at(1, pi), i0, j + 1, k);
    const double *pfz0 = row_ptr(press_FC_.at(2, pi), i0, j, k), *pfz1 = row_ptr(press_FC_.at(2, pi), i0, j, k + 1);
    const double* rho = row_ptr(f.rho_CC[pi], i0, j, k);
    const double* vol_frac = row_ptr(f.vol_frac_CC[pi], i0, j, k);
    const Vec3* vel = row_ptr(f.vel_CC[pi], i0, j, k);
    const Vec3* mom_L = row_ptr(f.mom_L_CC[pi], i0, j, k);
    const double* corr = row_ptr(work_corr_[m][pi], i0, j, k);
    const double* mass_L = row_ptr(mass_L_[m][pi], i0, j, k);
    const double* cv = row_ptr(cv_CC_[m][pi], i0, j, k);
    double* int_eng_L = row_ptr(f.int_eng_L_CC[pi], i0, j, k);
    double* temp_L = row_ptr(temp_L_[m][pi], i0, j, k);
    for (int c = 0; c < n; ++c) {
      Vec3 grad_p;
      grad_p[0] = (pfx[c + 1] - pfx[c]) / dx[0];
      grad_p[1] = (pfy1[c] - pfy0[c]) / dx[1];
      grad_p[2] = (pfz1[c] - pfz0[c]) / dx[2];
      const double mass = rho[c] * V;
      const Vec3 impulse = -dt * V * vol_frac[c] * grad_p;
      const Vec3 u_mid = 0.5 * (vel[c] + mom_L[c] / mass);
      int_eng_L[c] += corr[c] - impulse.dot(u_mid);
      temp_L[c] = int_eng_L[c] / (mass_L[c] * cv[c]);
    }
  });
}

// Correction 2 for material m, after the advection of mass (flux_, mass_new_),
// momentum (flux_v_, vel_CC) and temperature (temp_CC): adds D/(M_new c_v)
// to temp_CC (one material) or to work_corr_[0] (a mixture: split by mass in
// add_mixture_advected_kinetic_energy_loss). Uses flux2_ as scratch.
void IceComponent::add_advected_kinetic_energy_loss(std::size_t m) {
  const Grid& g = setup_.grid;
  const bool mixture = energy_correction() == EnergyCorrection::Mixture;
  IceMaterialFields& f = mats_[m];
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      const GridArray<double>& F = flux_.at(d, pi);
      const GridArray<Vec3>& Fu = flux_v_.at(d, pi);
      GridArray<double>& K = flux2_.at(d, pi);
      const IndexRange faces{g.patches[pi].lo, g.patches[pi].hi + IntVec3::Unit(d)};
      const int i0 = faces.lo[0], n = faces.hi[0] - i0;
      for_each_row(faces, [&](int j, int k) {
        const double* mf = row_ptr(F, i0, j, k);
        const Vec3* mu = row_ptr(Fu, i0, j, k);
        double* ke = row_ptr(K, i0, j, k);
        // 1/2 F |u_slab|^2 = 1/2 |F u_slab|^2 / F (F and F u_slab carry the sign of the face velocity).
        for (int c = 0; c < n; ++c) ke[c] = mf[c] == 0.0 ? 0.0 : 0.5 * mu[c].squaredNorm() / mf[c];
      });
    }
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange cells = g.patches[pi].cells();
    const int i0 = cells.lo[0], n = cells.hi[0] - i0;
    for_each_row(cells, [&](int j, int k) {
      // The divergence of the kinetic-energy fluxes (flux_divergence) in the row loop.
      const double* fx = row_ptr(flux2_.at(0, pi), i0, j, k);
      const double *fy0 = row_ptr(flux2_.at(1, pi), i0, j, k), *fy1 = row_ptr(flux2_.at(1, pi), i0, j + 1, k);
      const double *fz0 = row_ptr(flux2_.at(2, pi), i0, j, k), *fz1 = row_ptr(flux2_.at(2, pi), i0, j, k + 1);
      const double* mass_L = row_ptr(mass_L_[m][pi], i0, j, k);
      const double* mass_new = row_ptr(mass_new_[pi], i0, j, k);
      const Vec3* vel_L = row_ptr(vel_L_[m][pi], i0, j, k);
      const Vec3* vel = row_ptr(f.vel_CC[pi], i0, j, k);
      const double* cv = row_ptr(cv_CC_[m][pi], i0, j, k);
      double* temp = row_ptr(f.temp_CC[pi], i0, j, k);
      double* corr = mixture ? row_ptr(work_corr_[0][pi], i0, j, k) : nullptr;
      const RadialWeights* rw = radial();  // axisymmetric: r-faces times r_f/r_i (ice/RadialWeights.h)
      const double* wlo = rw ? rw->lo_row(i0) : nullptr;
      const double* whi = rw ? rw->hi_row(i0) : nullptr;
      for (int c = 0; c < n; ++c) {
        const double dq = rw ? (wlo[c] * fx[c] - whi[c] * fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c])
                             : (fx[c] - fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c]);
        const double m_L = mass_L[c], m_new = mass_new[c];
        const double ke_adv = 0.5 * m_L * vel_L[c].squaredNorm() + dq;
        const double loss = ke_adv - 0.5 * m_new * vel[c].squaredNorm();
        if (mixture) corr[c] += loss;  // split among the materials afterwards
        else temp[c] += loss / (m_new * cv[c]);
      }
    });
  }
}

// ---- Mixtures of ICE materials -------------------------------------------
// With several materials the cell's correction is computed from the
// material sums and split by mass: material m gets the fraction
// M_m / sum_n M_n of it. Each piece below changes the cell's total energy
// sum_m M_m (c_v,m T_m + |u_m|^2/2) by a face flux only (or not at all), so
// sum over the cells is conserved to round-off in a closed box:
//  a. Lagrangian phase: C = V sum_f p*_f sum_m A_f,m - sum_m V theta_m kappa_m p delP
//                          - sum_m F_p,m . (u_m + u_L,m)/2,
//     the same identity as for one material, summed over m (sum_m theta_m
//     kappa_m delP = sum_m A_m).
//  b. Momentum exchange (Exchange.h): conserves sum_m M_m u_m and dissipates
//     kinetic energy, L = sum_m (|M u_L|^2/(2 M) - M |u_L^ME|^2/2) >= 0; L is
//     returned as heat (Uintah does not). The heat exchange conserves
//     sum_m M_m c_v,m T_m (M_m c_v,m beta_mn = dt V theta_m theta_n H_mn symmetric).
//  c. Advection: D = sum_m D_m, DeBar's correction of each material's own
//     mass and momentum fluxes.
// The earlier per-material split (each material keeping its own C_m and D_m)
// gave trace materials (theta ~ 1e-6) corrections far beyond their internal
// energy (negative temperatures in a two-material block advection and in
// LightTime.ups); by mass, a trace material gets a trace of the correction.
// MPMICE runs (a lagrangian material) keep Uintah's equations: the solid's
// energy lives on the particles.
IceComponent::EnergyCorrection IceComponent::energy_correction() const {
  if (!setup_.conserve_total_energy) return EnergyCorrection::None;
  if (mats_.size() == 1) return EnergyCorrection::Single;
  for (const IceMaterialSpec& spec : setup_.materials)
    if (spec.lagrangian) return EnergyCorrection::None;
  return EnergyCorrection::Mixture;
}

// a, first part: work_corr_[0] = V sum_f p*_f sum_m A_f,m - sum_m V theta_m kappa_m p delP.
// The volume-fraction fluxes of every material are recomputed (flux_ holds
// only the last material's after sum_volume_flux_and_kappa); their sum goes to flux2_.
void IceComponent::mixture_face_pressure_work(double dt) {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  for (int d = 0; d < 3; ++d)
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) flux2_.at(d, pi).fill(0.0);
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    density_fluxes(g, setup_.advection, mats_[m].vol_frac_CC, mats_[m].vel_FCME, dt, flux_);
    for (int d = 0; d < 3; ++d)
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
        double* a = flux2_.at(d, pi).data();
        const double* b = flux_.at(d, pi).data();
        const std::size_t n = flux2_.at(d, pi).size();
        for (std::size_t c = 0; c < n; ++c) a[c] += b[c];
      }
  }
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      double work = 0;
      const RadialWeights* rw = radial();  // axisymmetric: r-faces times r_f/r_i (ice/RadialWeights.h)
      for (int d = 0; d < 3; ++d) {
        const IntVec3 hi(c + IntVec3::Unit(d));
        const GridArray<double>& pf = press_FC_.at(d, pi);
        const GridArray<double>& A = flux2_.at(d, pi);
        if (rw && d == 0)
          work += *rw->lo_row(i) * (pf(c) * A(c)) - *rw->hi_row(i) * (pf(hi) * A(hi));
        else
          work += pf(c) * A(c) - pf(hi) * A(hi);
      }
      double cell_work = 0;
      for (const IceMaterialFields& f : mats_) {
        const double ss = f.speedSound_CC[pi](c);
        cell_work += V * f.vol_frac_CC[pi](c) * f.sp_vol_CC[pi](c) / (ss * ss) * press_CC_[pi](c) * delP_Dilatate_[pi](c);
      }
      work_corr_[0][pi](c) = V * work - cell_work;
    });
}

// a, second part, once every material's Lagrangian momentum and internal
// energy of patch pi are known (before the exchange).
void IceComponent::add_mixture_face_pressure_work(std::size_t pi, double dt) {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  const std::size_t nm = mats_.size();
  const IndexRange cells = g.patches[pi].cells();
  const int i0 = cells.lo[0], n = cells.hi[0] - i0;
  // Row kernel: the cell fields share one offset per row; the face pressures
  // of the low and high faces along d come from their own rows.
  for_each_row(cells, [&](int j, int k) {
    const std::size_t off0 = press_CC_[pi].offset(i0, j, k);
    const double* pf_lo[3];
    const double* pf_hi[3];
    for (int d = 0; d < 3; ++d) {
      const IntVec3 lo(i0, j, k), hi(lo + IntVec3::Unit(d));
      pf_lo[d] = row_ptr(press_FC_.at(d, pi), lo);
      pf_hi[d] = row_ptr(press_FC_.at(d, pi), hi);
    }
    // int_eng_L_CC has no ghost layer (its own row pointer).
    double* int_eng_L[kMaxExchangeMaterials];
    for (std::size_t m = 0; m < nm; ++m) int_eng_L[m] = row_ptr(mats_[m].int_eng_L_CC[pi], i0, j, k);
    for (int c = 0; c < n; ++c) {
      const std::size_t off = off0 + c;
      Vec3 grad_p;
      for (int d = 0; d < 3; ++d) grad_p[d] = (pf_hi[d][c] - pf_lo[d][c]) / g.dx[d];
      double corr = work_corr_[0][pi].data()[off], mass_sum = 0;
      for (std::size_t m = 0; m < nm; ++m) {
        const IceMaterialFields& f = mats_[m];
        // u_L = (Mu)_L / M_L before the exchange (vel_L_): with a model mass source the
        // pre-source mass of a trace product would turn its momentum source into a huge velocity.
        const Vec3 impulse = -dt * V * f.vol_frac_CC[pi].data()[off] * grad_p;
        corr -= impulse.dot(0.5 * (f.vel_CC[pi].data()[off] + vel_L_[m][pi].data()[off]));
        mass_sum += mass_L_[m][pi].data()[off];
      }
      for (std::size_t m = 0; m < nm; ++m) {
        const double mass_L = mass_L_[m][pi].data()[off];
        double& eng = int_eng_L[m][c];
        eng += corr * (mass_L / mass_sum);
        temp_L_[m][pi].data()[off] = eng / (mass_L * cv_CC_[m][pi].data()[off]);
      }
    }
  });
}

// b: the kinetic energy the momentum exchange removed, as heat, split by mass.
// mom_L_CC is the Lagrangian momentum before the exchange, vel_L_ the velocity after it.
void IceComponent::add_exchange_kinetic_energy_loss(std::size_t pi) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  const IndexRange cells = g.patches[pi].cells();
  const int i0 = cells.lo[0], n = cells.hi[0] - i0;
  // Row kernel: one offset per row, shared by the cell fields (same layout).
  for_each_row(cells, [&](int j, int k) {
    const std::size_t off0 = press_CC_[pi].offset(i0, j, k);
    // mom_L_CC has no ghost layer (its own row pointer).
    const Vec3* mom_L[kMaxExchangeMaterials];
    for (std::size_t m = 0; m < nm; ++m) mom_L[m] = row_ptr(mats_[m].mom_L_CC[pi], i0, j, k);
    for (int c = 0; c < n; ++c) {
      const std::size_t off = off0 + c;
      double loss = 0, mass_sum = 0;
      for (std::size_t m = 0; m < nm; ++m) {
        const double mass_L = mass_L_[m][pi].data()[off];
        loss += 0.5 * (mom_L[m][c].squaredNorm() / mass_L -
                       mass_L * vel_L_[m][pi].data()[off].squaredNorm());
        mass_sum += mass_L;
      }
      for (std::size_t m = 0; m < nm; ++m) temp_L_[m][pi].data()[off] += loss / (mass_sum * cv_CC_[m][pi].data()[off]);
    }
  });
}

// c: D = sum_m D_m (accumulated in work_corr_[0] by add_advected_kinetic_energy_loss),
// material m gets M_m/sum M of it: T_m += D/(sum_n M_n c_v,m); then the state BCs again.
void IceComponent::add_mixture_advected_kinetic_energy_loss() {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  const std::size_t nm = mats_.size();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange cells = g.patches[pi].cells();
    const int i0 = cells.lo[0], n = cells.hi[0] - i0;
    for_each_row(cells, [&](int j, int k) {
      const std::size_t off0 = press_CC_[pi].offset(i0, j, k);
      for (int c = 0; c < n; ++c) {
        const std::size_t off = off0 + c;
        double mass_sum = 0;
        for (const IceMaterialFields& f : mats_) mass_sum += f.rho_CC[pi].data()[off] * V;
        const double D = work_corr_[0][pi].data()[off];
        for (std::size_t m = 0; m < nm; ++m) mats_[m].temp_CC[pi].data()[off] += D / (mass_sum * cv_CC_[m][pi].data()[off]);
      }
    });
  }
  for (std::size_t m = 0; m < mats_.size(); ++m) apply_state_bcs(m);
}

}  // namespace tephra
