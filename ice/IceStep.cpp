// The phases of the explicit ICE step, in order. Equation numbers: Vaango
// theory manual (ch. 24, 26); "Uintah" marks what the manual leaves open and
// Uintah's explicit ICE (ICE.cc) fixes. See docs/algorithms/ice.md.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"
#include "core/sim/StepRedo.h"
#include "ice/Diffusion.h"
#include "ice/Equilibration.h"
#include "ice/Exchange.h"
#include "ice/AdvectionBounds.h"
#include "ice/IceAdvection.h"
#include "ice/IceBoundary.h"
#include "ice/IceComponent.h"
#include "ice/RowLoop.h"

namespace tephra {

namespace {

IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }

}  // namespace

// Step 1 (eq. 24.7): p_eq, theta_m, rho_micro_m, c_m in every cell including
// the extra cells (Uintah iterates the extra cells too), then the Pressure BC.
void IceComponent::compute_equilibration_pressure(int step) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    // One (j, k) row of cells at a time, in place: every cell field of the
    // patch has the same layout, so a row is a contiguous span of each and
    // the EOS is called once per material and row (no per-cell dispatch).
    const IndexRange box = g.patches[pi].cells_with_extra();
    const int i0 = box.lo[0];
    const std::size_t n = static_cast<std::size_t>(box.hi[0] - i0);
    std::vector<long long> failed(static_cast<std::size_t>(box.extent()[1]) * box.extent()[2], -1);
    for_each_row(box, [&](int j, int k) {
      thread_local std::vector<double> c2;
      thread_local std::vector<EquilibrationMaterial> em;
      if (c2.size() < nm * n) c2.resize(nm * n);
      em.resize(nm);
      double* press = &press_equil_CC_[pi](i0, j, k);
      const double* p_guess = &press_CC_[pi](i0, j, k);
      for (std::size_t c = 0; c < n; ++c) press[c] = p_guess[c];
      for (std::size_t m = 0; m < nm; ++m) {
        IceMaterialFields& f = mats_[m];
        double* rho_micro = &f.rho_micro_CC[pi](i0, j, k);
        const double* sp_vol = &f.sp_vol_CC[pi](i0, j, k);
        for (std::size_t c = 0; c < n; ++c) rho_micro[c] = 1.0 / sp_vol[c];
        em[m] = {setup_.materials[m].eos.get(), {&f.rho_CC[pi](i0, j, k), n}, {&f.temp_CC[pi](i0, j, k), n},
                 {rho_micro, n}, {&f.vol_frac_CC[pi](i0, j, k), n}, {c2.data() + m * n, n}, {}, {}};
        if (m < cell_gas_.size() && cell_gas_[m]) {  // SimpleRxn: gamma and cv of the cell's mixture
          const CellIdealGas& gas = *cell_gas_[m]->cell_ideal_gas();
          em[m].cell_gamma = {&(*gas.gamma)[pi](i0, j, k), n};
          em[m].cell_cv = {&(*gas.cv)[pi](i0, j, k), n};
        }
      }
      const EquilibrationResult r = equilibrate_pressure(em, {press, n}, setup_.max_iter_equilibration);
      if (!r.converged) {
        failed[static_cast<std::size_t>(k - box.lo[2]) * box.extent()[1] + (j - box.lo[1])] = i0 + r.failed_cell;
        return;
      }
      for (std::size_t m = 0; m < nm; ++m) {
        IceMaterialFields& f = mats_[m];
        const double* rho_micro = &f.rho_micro_CC[pi](i0, j, k);
        double* sp_vol = &f.sp_vol_CC[pi](i0, j, k);
        double* ss = &f.speedSound_CC[pi](i0, j, k);
        const double* c2m = c2.data() + m * n;
        for (std::size_t c = 0; c < n; ++c) {
          sp_vol[c] = 1.0 / rho_micro[c];
          ss[c] = std::sqrt(c2m[c]);
        }
      }
    });
    for (std::size_t row = 0; row < failed.size(); ++row) {
      if (failed[row] < 0) continue;
      const long long jr = static_cast<long long>(row) % box.extent()[1], kr = static_cast<long long>(row) / box.extent()[1];
      std::ostringstream os;
      os << "ICE equilibration pressure did not converge in " << setup_.max_iter_equilibration
         << " iterations at step " << step << " in cell (" << failed[row] << "," << box.lo[1] + jr << ","
         << box.lo[2] + kr << ")";
      // The materials' start-of-step state in that cell (the why).
      const IntVec3 c(int(failed[row]), int(box.lo[1] + jr), int(box.lo[2] + kr));
      for (std::size_t m = 0; m < nm; ++m)
        os << "; material " << m << ": rho_CC " << mats_[m].rho_CC[pi](c) << " kg/m^3, T " << mats_[m].temp_CC[pi](c)
           << " K, sp_vol " << mats_[m].sp_vol_CC[pi](c) << " m^3/kg";
      os << "; p guess " << press_CC_[pi](c) << " Pa";
      throw NumericalFailure(os.str());
    }
    apply_pressure_bc(pi, press_equil_CC_);
    if (setup_.lodi.enabled) lodi_pressure_bc(pi, press_equil_CC_);
  }
  CellHaloBatch batch;  // one message round for the 1 + 4 nm fields
  batch.add(press_equil_CC_);
  for (IceMaterialFields& f : mats_) batch.add(f.sp_vol_CC).add(f.vol_frac_CC).add(f.rho_micro_CC).add(f.speedSound_CC);
  halo_->exchange_now(batch);
}

// Step 2 (eq. 26.1, Uintah's computeFaceCenteredVelocities): on the face
// between L and R along d,
//   u* = (rho_L u_L + rho_R u_R)/(rho_L + rho_R)
//        - dt * 2 v_L v_R/(v_L + v_R) * (p_R - p_L)/dx + g_d dt,
// with rho = rho_CC (bulk), v = sp_vol, p = p_eq. Then the boundary faces.
// press is p_eq (explicit) or the current implicit pressure iterate.
void IceComponent::compute_face_velocities(double dt, const CellScalars& press) {
  const Grid& g = setup_.grid;
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    IceMaterialFields& f = mats_[m];
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      const GridArray<double>& rho = f.rho_CC[pi];
      const GridArray<double>& v = f.sp_vol_CC[pi];
      const GridArray<Vec3>& u = f.vel_CC[pi];
      const GridArray<double>& p = press[pi];
      for (int d = 0; d < 3; ++d) {
        GridArray<double>& uf = f.vel_FC.at(d, pi);
        const IntVec3 e = IntVec3::Unit(d);
        const double gdt = setup_.gravity[d] * dt, inv_dx = 1.0 / g.dx[d];
        const IndexRange fr = faces_of(g.patches[pi], d);
        const int i0 = fr.lo[0], n = fr.hi[0] - i0;
        for_each_row(fr, [&](int j, int k) {
          const IntVec3 R(i0, j, k), L = R - e;
          const double *rhoL = row_ptr(rho, L), *rhoR = row_ptr(rho, R), *vL = row_ptr(v, L), *vR = row_ptr(v, R);
          const double *pL = row_ptr(p, L), *pR = row_ptr(p, R);
          const Vec3 *uL = row_ptr(u, L), *uR = row_ptr(u, R);
          double* out = row_ptr(uf, R);
          for (int c = 0; c < n; ++c) {
            const double term1 = (rhoL[c] * uL[c][d] + rhoR[c] * uR[c][d]) / (rhoL[c] + rhoR[c]);
            const double sp_vol_brack = 2.0 * vL[c] * vR[c] / (vL[c] + vR[c]);
            out[c] = term1 - dt * sp_vol_brack * (pR[c] - pL[c]) * inv_dx + gdt;
          }
        });
      }
      for (int face = 0; face < 6; ++face) {
        const GridFace gf = static_cast<GridFace>(face);
        apply_face_velocity_bc(g, g.patches[pi], gf, setup_.bcs[m][face][kBcVelocity], f.vel_FC.at(face_axis(gf), pi));
      }
    }
  }
}

// Step 2b (Uintah's addExchangeToFaceVelocities): the implicit momentum
// exchange of Exchange.h on every face, with theta_f = (theta_L + theta_R)/2
// and v_f = 2 v_L v_R/(v_L + v_R). One material: vel_FCME = vel_FC.
void IceComponent::add_exchange_to_face_velocities(double dt) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      if (nm == 1) {
        mats_[0].vel_FCME.at(d, pi) = mats_[0].vel_FC.at(d, pi);
        continue;
      }
      const IntVec3 e = IntVec3::Unit(d);
      const IndexRange fr = faces_of(g.patches[pi], d);
      const int i0 = fr.lo[0], n = fr.hi[0] - i0;
      for_each_row(fr, [&](int j, int k) {
        const IntVec3 R(i0, j, k), L = R - e;
        const double *thL[kMaxExchangeMaterials], *thR[kMaxExchangeMaterials], *svL[kMaxExchangeMaterials],
            *svR[kMaxExchangeMaterials], *uf[kMaxExchangeMaterials];
        double* out[kMaxExchangeMaterials];
        for (std::size_t m = 0; m < nm; ++m) {
          const IceMaterialFields& f = mats_[m];
          thL[m] = row_ptr(f.vol_frac_CC[pi], L);
          thR[m] = row_ptr(f.vol_frac_CC[pi], R);
          svL[m] = row_ptr(f.sp_vol_CC[pi], L);
          svR[m] = row_ptr(f.sp_vol_CC[pi], R);
          uf[m] = row_ptr(f.vel_FC.at(d, pi), R);
          out[m] = row_ptr(mats_[m].vel_FCME.at(d, pi), R);
        }
        for (int c = 0; c < n; ++c) {
          double theta[kMaxExchangeMaterials], sv[kMaxExchangeMaterials], u[kMaxExchangeMaterials];
          for (std::size_t m = 0; m < nm; ++m) {
            theta[m] = 0.5 * (thL[m][c] + thR[m][c]);
            const double vL = svL[m][c], vR = svR[m][c];
            sv[m] = 2.0 * vL * vR / (vL + vR);
            u[m] = uf[m][c];
          }
          solve_exchange(dt, {theta, nm}, {sv, nm}, {}, setup_.K, {u, nm});
          for (std::size_t m = 0; m < nm; ++m) out[m][c] = u[m];
        }
      });
    }
  if (nm == 1) return;
  for (std::size_t m = 0; m < nm; ++m)
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for (int face = 0; face < 6; ++face) {
        const GridFace gf = static_cast<GridFace>(face);
        apply_face_velocity_bc(g, g.patches[pi], gf, setup_.bcs[m][face][kBcVelocity],
                               mats_[m].vel_FCME.at(face_axis(gf), pi));
      }
}

// Step 4 (eq. 26.2-26.3, Uintah's explicit computeDelPressAndUpdatePressCC):
//   delP = sum_m A(theta_m) / sum_m theta_m kappa_m,   kappa_m = v_m / c_m^2,
// where A(theta_m) = sum of incoming minus outgoing fluxes of theta_m through
// the faces with u*_m (the advection operator of step 10, so that
// sum_m div(theta_m u_m) dt matches the advected volume), and
//   press_CC = p_eq + delP, then the Pressure BC.
void IceComponent::compute_delP_and_pressure(double dt) {
  const Grid& g = setup_.grid;
  sum_volume_flux_and_kappa(dt);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange cells = g.patches[pi].cells();
    const int i0 = cells.lo[0], n = cells.hi[0] - i0;
    for_each_row(cells, [&](int j, int k) {
      double* delP = row_ptr(delP_Dilatate_[pi], i0, j, k);
      double* press = row_ptr(press_CC_[pi], i0, j, k);
      const double* kappa = row_ptr(sum_kappa_[pi], i0, j, k);
      const double* p_eq = row_ptr(press_equil_CC_[pi], i0, j, k);
      for (int c = 0; c < n; ++c) {
        delP[c] /= kappa[c];
        press[c] = p_eq[c] + delP[c];
      }
      if (model_src_) {  // + delP_MassX (IceModelStep.cpp), clamped at 1e-12 Pa as Uintah
        double* delP_MassX = row_ptr(delP_MassX_[pi], i0, j, k);
        for (int c = 0; c < n; ++c) {
          delP_MassX[c] /= kappa[c];
          press[c] = std::max(1e-12, press[c] + delP_MassX[c]);
        }
      }
    });
    apply_pressure_bc(pi, press_CC_);
    if (setup_.lodi.enabled) lodi_pressure_bc(pi, press_CC_);
  }
  halo_->exchange(press_CC_);
}

// delP_Dilatate = sum_m A(theta_m) (net inflow of volume fraction with the
// face velocities vel_FCME) and sum_kappa = sum_m theta_m v_m / c_m^2.
void IceComponent::sum_volume_flux_and_kappa(double dt) {
  const Grid& g = setup_.grid;
  delP_Dilatate_.fill(0.0);
  sum_kappa_.fill(0.0);
  // One ICE material without source models: the equilibration set theta = 1
  // in every cell, so the limited slopes of theta are 0 and every slab value
  // is 1 + 0 = 1 exactly; the flux is phi itself (the bits density_fluxes gives).
  const bool unit_theta = mats_.size() == 1 && !model_src_ && !setup_.materials[0].lagrangian;
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    IceMaterialFields& f = mats_[m];
    if (unit_theta) {
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
        for (int d = 0; d < 3; ++d) {
          const IndexRange fr = faces_of(g.patches[pi], d);
          const int i0 = fr.lo[0], n = fr.hi[0] - i0;
          const double r = dt / g.dx[d];
          for_each_row(fr, [&](int j, int k) {
            const double* u = row_ptr(f.vel_FCME.at(d, pi), i0, j, k);
            double* F = row_ptr(flux_.at(d, pi), i0, j, k);
            for (int c = 0; c < n; ++c) {
              const double phi = u[c] * r;
              F[c] = phi == 0.0 ? 0.0 : phi;
            }
          });
        }
    } else if (has_lagrangian_flux(m)) {
      lagrangian_volume_flux(m, flux_);  // MPMICE solid: from the particles (IceLagrangianFlux.cpp)
    } else {
      density_fluxes(g, setup_.advection, f.vol_frac_CC, f.vel_FCME, dt, flux_);
      scale_fluid_flux(m, dt, flux_);  // MPMICE: the face area the solids leave
    }
    // delP += net inflow (flux_divergence), sum_kappa += theta v / c^2.
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      const IndexRange cells = g.patches[pi].cells();
      const int i0 = cells.lo[0], n = cells.hi[0] - i0;
      for_each_row(cells, [&](int j, int k) {
        const double* fx = row_ptr(flux_.at(0, pi), i0, j, k);
        const double *fy0 = row_ptr(flux_.at(1, pi), i0, j, k), *fy1 = row_ptr(flux_.at(1, pi), i0, j + 1, k);
        const double *fz0 = row_ptr(flux_.at(2, pi), i0, j, k), *fz1 = row_ptr(flux_.at(2, pi), i0, j, k + 1);
        const double* ss = row_ptr(f.speedSound_CC[pi], i0, j, k);
        const double* theta = row_ptr(f.vol_frac_CC[pi], i0, j, k);
        const double* v = row_ptr(f.sp_vol_CC[pi], i0, j, k);
        double* kappa = row_ptr(sum_kappa_[pi], i0, j, k);
        double* delP = row_ptr(delP_Dilatate_[pi], i0, j, k);
        const RadialWeights* rw = radial();  // axisymmetric: r-faces times r_f/r_i (ice/RadialWeights.h)
        const double* wlo = rw ? rw->lo_row(i0) : nullptr;
        const double* whi = rw ? rw->hi_row(i0) : nullptr;
        for (int c = 0; c < n; ++c) {
          const double dq = rw ? (wlo[c] * fx[c] - whi[c] * fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c])
                               : (fx[c] - fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c]);
          const double cs = ss[c];
          kappa[c] += theta[c] * v[c] / (cs * cs);
          delP[c] += dq;
        }
      });
    }
  }
}

// Step 5 (eq. 26.4): p* = (p_L rho_R + p_R rho_L)/(rho_L + rho_R), rho = sum_m rho_CC_m.
void IceComponent::compute_face_pressure() {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange box = g.patches[pi].cells_with_extra();
    const int i0 = box.lo[0], n = box.hi[0] - i0;
    for_each_row(box, [&](int j, int k) {
      double* sum = row_ptr(sum_rho_CC_[pi], i0, j, k);
      for (int c = 0; c < n; ++c) sum[c] = 0;
      for (std::size_t m = 0; m < nm; ++m) {
        const double* rho = row_ptr(mats_[m].rho_CC[pi], i0, j, k);
        for (int c = 0; c < n; ++c) sum[c] += rho[c];
      }
    });
  }
  halo_->exchange(sum_rho_CC_);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const GridArray<double>& p = press_CC_[pi];
    const GridArray<double>& rho = sum_rho_CC_[pi];
    for (int d = 0; d < 3; ++d) {
      GridArray<double>& pf = press_FC_.at(d, pi);
      const IntVec3 e = IntVec3::Unit(d);
      const IndexRange fr = faces_of(g.patches[pi], d);
      const int i0 = fr.lo[0], n = fr.hi[0] - i0;
      for_each_row(fr, [&](int j, int k) {
        const IntVec3 R(i0, j, k), L = R - e;
        const double *pL = row_ptr(p, L), *pR = row_ptr(p, R), *rL = row_ptr(rho, L), *rR = row_ptr(rho, R);
        double* out = row_ptr(pf, R);
        for (int c = 0; c < n; ++c) out[c] = (pL[c] * rR[c] + pR[c] * rL[c]) / (rL[c] + rR[c]);
      });
    }
  }
}

// Steps 7-9 (eq. 26.5-26.14 without reactions, viscosity or conduction):
//   mass_L = rho_CC V
//   mom_L  = mass u + dt (-V theta grad p* + mass g)         grad p* from the face pressures
//   eint_L = mass cv T + V theta kappa p delP                (= -dt V f_theta p sum div(theta u), eq. 26.7)
//   exchange of u and T (Exchange.h), Tdot = (T_L^ME - T)/dt
//   sp_vol_L = mass v - V theta kappa delP
//              + dt V (theta beta Tdot - f_theta sum_s theta_s beta_s Tdot_s)   (eq. 26.13, Uintah)
// The extra cells get mass rho_CC V and the BCs of the Lagrangian u, T, v.
void IceComponent::lagrangian_values_and_exchange(double dt) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  const double V = g.cell_volume();
  // Total-energy corrections (IceEnergy.cpp): one material, or a mixture of
  // ICE materials with the cell's correction split by mass (docs/algorithms/ice.md).
  const EnergyCorrection energy = energy_correction();
  if (energy == EnergyCorrection::Single) face_pressure_work(dt);
  if (energy == EnergyCorrection::Mixture) mixture_face_pressure_work(dt);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& patch = g.patches[pi];
    const IndexRange with_extra = patch.cells_with_extra(), cells = patch.cells();
    const int ie = with_extra.lo[0], ne = with_extra.hi[0] - ie, i0 = cells.lo[0], n = cells.hi[0] - i0;
    // Momentum and energy sources, Lagrangian values.
    for (std::size_t m = 0; m < nm; ++m) {
      IceMaterialFields& f = mats_[m];
      // c_v per cell: the constant <specific_heat>, or <SpecificHeatModel> c_v(T^n)
      // at the start of the step (Uintah evaluates cv from temp_CC and keeps it for the step).
      const IceSpecificHeat* cv_model = setup_.materials[m].cv_model.get();
      const Vec3 gravity = setup_.materials[m].lagrangian ? Vec3::Zero() : setup_.gravity;
      const double cv_const = setup_.materials[m].cv;
      for_each_row(with_extra, [&](int j, int k) {
        const double* rho = row_ptr(f.rho_CC[pi], ie, j, k);
        const double* temp = row_ptr(f.temp_CC[pi], ie, j, k);
        double* mass = row_ptr(mass_L_[m][pi], ie, j, k);
        double* cv = row_ptr(cv_CC_[m][pi], ie, j, k);
        for (int c = 0; c < ne; ++c) mass[c] = rho[c] * V;
        if (cv_model)
          for (int c = 0; c < ne; ++c) cv[c] = cv_model->cv(temp[c]);
        else
          for (int c = 0; c < ne; ++c) cv[c] = cv_const;
      });
      fill_cell_gas_cv(m, pi);
      compute_diffusion_sources(m, pi);
      const IceModelSources* ms = model_src_.get();
      const double min_mass = setup_.materials[m].tiny_rho * setup_.materials[m].sources[0].density * V;
      const double dx[3] = {g.dx[0], g.dx[1], g.dx[2]};
      for_each_row(cells, [&](int j, int k) {
        const double* pfx = row_ptr(press_FC_.at(0, pi), i0, j, k);
        const double *pfy0 = row_ptr(press_FC_.at(1, pi), i0, j, k), *pfy1 = row_ptr(press_FC_.at(1, pi), i0, j + 1, k);
        const double *pfz0 = row_ptr(press_FC_.at(2, pi), i0, j, k), *pfz1 = row_ptr(press_FC_.at(2, pi), i0, j, k + 1);
        double* mass_row = row_ptr(mass_L_[m][pi], i0, j, k);
        const double* vol_frac = row_ptr(f.vol_frac_CC[pi], i0, j, k);
        const double* speed = row_ptr(f.speedSound_CC[pi], i0, j, k);
        const double* sp_vol = row_ptr(f.sp_vol_CC[pi], i0, j, k);
        const double* cv_row = row_ptr(cv_CC_[m][pi], i0, j, k);
        const double* temp = row_ptr(f.temp_CC[pi], i0, j, k);
        const double* press = row_ptr(press_CC_[pi], i0, j, k);
        const double* delP = row_ptr(delP_Dilatate_[pi], i0, j, k);
        const double* heat = row_ptr(heat_[pi], i0, j, k);
        const Vec3* visc = row_ptr(visc_force_[pi], i0, j, k);
        const Vec3* vel = row_ptr(f.vel_CC[pi], i0, j, k);
        Vec3* mom_source = row_ptr(f.mom_source_CC[pi], i0, j, k);
        Vec3* mom_L_row = row_ptr(f.mom_L_CC[pi], i0, j, k);
        double* int_eng_L = row_ptr(f.int_eng_L_CC[pi], i0, j, k);
        Vec3* vel_L = row_ptr(vel_L_[m][pi], i0, j, k);
        double* temp_L = row_ptr(temp_L_[m][pi], i0, j, k);
        for (int c = 0; c < n; ++c) {
          const double mass = mass_row[c];
          const double theta = vol_frac[c];
          Vec3 grad_p;
          grad_p[0] = (pfx[c + 1] - pfx[c]) / dx[0];
          grad_p[1] = (pfy1[c] - pfy0[c]) / dx[1];
          grad_p[2] = (pfz1[c] - pfz0[c]) / dx[2];
          // Viscous force and conduction (Diffusion.h): dt V div(theta tau), dt V div(theta k grad T).
          // A lagrangian (MPM) material gets gravity on the MPM grid instead.
          const Vec3 source = dt * (-V * theta * grad_p + mass * gravity + V * visc[c]);
          mom_source[c] = source;
          Vec3 mom_L = mass * vel[c] + source;
          const double ss = speed[c];
          const double kappa = sp_vol[c] / (ss * ss);
          const double cv = cv_row[c];
          double eint_L = mass * cv * temp[c] + V * theta * kappa * press[c] * delP[c] + dt * V * heat[c];
          double mass_L = mass;
          if (ms) {
            // Model sources (Uintah computeLagrangianValues): M_L = max(M + S_M, tiny_rho V),
            // (Mu)_L += S_mom, (Me)_L = max((Me)_L + S_E, M_min cv T).
            const IntVec3 cell(i0 + c, j, k);
            mass_L = std::max(mass + ms->mass[m][pi](cell), min_mass);
            mom_L += ms->momentum[m][pi](cell);
            eint_L = std::max(eint_L + ms->energy[m][pi](cell), min_mass * cv * temp[c]);
            mass_row[c] = mass_L;
          }
          mom_L_row[c] = mom_L;
          int_eng_L[c] = eint_L;
          vel_L[c] = mom_L / mass_L;
          temp_L[c] = eint_L / (mass_L * cv);
        }
      });
      if (energy == EnergyCorrection::Single) add_face_pressure_work(m, pi, dt);  // IceEnergy.cpp
    }
    if (energy == EnergyCorrection::Mixture) add_mixture_face_pressure_work(pi, dt);  // IceEnergy.cpp
    // Momentum and heat exchange, cell by cell.
    if (nm > 1) {
      for_each_row(cells, [&](int j, int k) {
        const double *cv_m[kMaxExchangeMaterials], *theta_m[kMaxExchangeMaterials], *sv_m[kMaxExchangeMaterials];
        Vec3* vel_m[kMaxExchangeMaterials];
        double* temp_m[kMaxExchangeMaterials];
        for (std::size_t m = 0; m < nm; ++m) {
          cv_m[m] = row_ptr(cv_CC_[m][pi], i0, j, k);
          theta_m[m] = row_ptr(mats_[m].vol_frac_CC[pi], i0, j, k);
          sv_m[m] = row_ptr(mats_[m].sp_vol_CC[pi], i0, j, k);
          vel_m[m] = row_ptr(vel_L_[m][pi], i0, j, k);
          temp_m[m] = row_ptr(temp_L_[m][pi], i0, j, k);
        }
        const double* H = setup_.H.data();
        double H_cell[kMaxExchangeMaterials * kMaxExchangeMaterials], mass_cell[kMaxExchangeMaterials];
        for (int c = 0; c < n; ++c) {
          double inv_cv[kMaxExchangeMaterials];
          for (std::size_t m = 0; m < nm; ++m) inv_cv[m] = 1.0 / cv_m[m][c];
          if (setup_.variable_heat_exchange) {  // <heatExchangeCoeff> variable (Exchange.h)
            for (std::size_t m = 0; m < nm; ++m) mass_cell[m] = mass_L_[m][pi](i0 + c, j, k);
            variable_heat_coefficients({mass_cell, nm}, H_cell);
            H = H_cell;
          }
          double theta[kMaxExchangeMaterials], sv[kMaxExchangeMaterials], ux[kMaxExchangeMaterials],
              uy[kMaxExchangeMaterials], uz[kMaxExchangeMaterials], T[kMaxExchangeMaterials];
          for (std::size_t m = 0; m < nm; ++m) {
            theta[m] = theta_m[m][c];
            sv[m] = sv_m[m][c];
            const Vec3& u = vel_m[m][c];
            ux[m] = u[0];
            uy[m] = u[1];
            uz[m] = u[2];
            T[m] = temp_m[m][c];
          }
          solve_exchange3(dt, {theta, nm}, {sv, nm}, setup_.K, {ux, nm}, {uy, nm}, {uz, nm});
          solve_exchange(dt, {theta, nm}, {sv, nm}, {inv_cv, nm}, {H, nm * nm}, {T, nm});
          for (std::size_t m = 0; m < nm; ++m) {
            vel_m[m][c] = Vec3(ux[m], uy[m], uz[m]);
            temp_m[m][c] = T[m];
          }
        }
      });
      if (energy == EnergyCorrection::Mixture) add_exchange_kinetic_energy_loss(pi);  // IceEnergy.cpp
    }
    // Specific volume (eq. 26.13). beta from the EOS, one call per material.
    // One material: f_theta = theta kappa / theta kappa = 1 exactly, so the
    // thermal term therm - f_theta therm is exactly 0 and beta is not needed.
    if (beta_.size() < nm) beta_.resize(nm);
    if (nm > 1)
      for (std::size_t m = 0; m < nm; ++m) {
        const IceMaterialFields& f = mats_[m];
        const std::size_t size = f.rho_micro_CC[pi].size();
        beta_[m].resize(size);
        setup_.materials[m].eos->thermal_expansivity({f.rho_micro_CC[pi].data(), size}, {f.temp_CC[pi].data(), size},
                                                     beta_[m]);
      }
    const std::vector<std::vector<double>>& beta_tdot = beta_;
    if (nm == 1) {
      IceMaterialFields& f = mats_[0];
      const double tiny_v = setup_.materials[0].tiny_rho * setup_.materials[0].sources[0].density * V;
      const double* model_spv = nullptr;
      for_each_row(cells, [&](int j, int k) {
        const double* speed = row_ptr(f.speedSound_CC[pi], i0, j, k);
        const double* vol_frac = row_ptr(f.vol_frac_CC[pi], i0, j, k);
        const double* sp_vol = row_ptr(f.sp_vol_CC[pi], i0, j, k);
        const double* rho = row_ptr(f.rho_CC[pi], i0, j, k);
        const double* delP = row_ptr(delP_Dilatate_[pi], i0, j, k);
        const double* mass_L = row_ptr(mass_L_[0][pi], i0, j, k);
        const double* src = model_src_ ? row_ptr(model_src_->sp_vol[0][pi], i0, j, k) : model_spv;
        double* spv_L = row_ptr(spv_L_[0][pi], i0, j, k);
        for (int c = 0; c < n; ++c) {
          const double ss = speed[c];
          const double theta_kappa = vol_frac[c] * sp_vol[c] / (ss * ss);
          const double mass = rho[c] * V;
          double sp_vol_L = mass * sp_vol[c] - V * theta_kappa * delP[c];
          if (src) sp_vol_L += src[c];
          if (setup_.clamp_sp_vol) sp_vol_L = std::max(sp_vol_L, tiny_v * sp_vol[c]);
          spv_L[c] = sp_vol_L / mass_L[c];
        }
      });
    } else for_each_row(cells, [&](int j, int k) {
      const std::size_t off0 = press_CC_[pi].offset(i0, j, k);
      for (int c = 0; c < n; ++c) {
      const IntVec3 cell(i0 + c, j, k);
      const std::size_t off = off0 + c;
      double sum_theta_kappa = 0, sum_therm = 0;
      double theta_kappa[kMaxExchangeMaterials], therm[kMaxExchangeMaterials];
      for (std::size_t m = 0; m < nm; ++m) {
        const IceMaterialFields& f = mats_[m];
        const double ss = f.speedSound_CC[pi].data()[off];
        theta_kappa[m] = f.vol_frac_CC[pi].data()[off] * f.sp_vol_CC[pi].data()[off] / (ss * ss);
        const double tdot = (temp_L_[m][pi].data()[off] - f.temp_CC[pi].data()[off]) / dt;
        therm[m] = f.vol_frac_CC[pi].data()[off] * beta_tdot[m][off] * tdot;
        sum_theta_kappa += theta_kappa[m];
        sum_therm += therm[m];
      }
      for (std::size_t m = 0; m < nm; ++m) {
        const IceMaterialFields& f = mats_[m];
        const double mass = f.rho_CC[pi].data()[off] * V;  // before the model mass source
        const double f_theta = theta_kappa[m] / sum_theta_kappa;
        const double sp_vol = f.sp_vol_CC[pi].data()[off];
        double sp_vol_L = mass * sp_vol - V * theta_kappa[m] * delP_Dilatate_[pi].data()[off] +
                          dt * V * (therm[m] - f_theta * sum_therm);
        if (model_src_) sp_vol_L += model_src_->sp_vol[m][pi](cell);  // Uintah modelVol_src
        // <ClampSpecificVolume> (Uintah): M v_L >= tiny_rho V v.
        if (setup_.clamp_sp_vol)
          sp_vol_L = std::max(sp_vol_L, setup_.materials[m].tiny_rho * setup_.materials[m].sources[0].density * V *
                                            sp_vol);
        spv_L_[m][pi].data()[off] = sp_vol_L / mass_L_[m][pi].data()[off];
      }
      }
    });
  }
  // Uintah's recomputeTimeStep: a non-positive M v_L cannot be advected; with
  // the step-restart machinery active (implicit, or source models) the step is
  // redone with dt/2, else the end-of-step state check stops the run.
  if (redoes_failed_steps()) {
    std::string why;  // the first bad cell of this rank; every rank restarts if any has one
    for (std::size_t m = 0; m < nm && why.empty(); ++m) {
      // An MPMICE solid's v_L is not advected (the particles carry the solid;
      // a cell whose solid burns away has M v_L -> 0).
      if (setup_.materials[m].lagrangian) continue;
      for (std::size_t pi = 0; pi < g.patches.size() && why.empty(); ++pi)
        for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
          const double v = spv_L_[m][pi](i, j, k);
          if (!why.empty() || (v > 0 && std::isfinite(v))) return;
          std::ostringstream os;
          os << "Lagrangian specific volume " << v << " of material " << m << " in cell (" << i << "," << j << ","
             << k << ")";
          why = os.str();
        });
    }
    if (redo_check_hook_) redo_check_hook_(time_, dt);
    if (layout_.any(!why.empty())) {
      if (why.empty()) why = "a bad Lagrangian specific volume on another MPI rank";
      // ICE alone and MPMICE (the whole coupled step) redo the step with dt/2.
      throw StepRedoRequest{why};
    }
  }
  // Boundary values of the Lagrangian state; output copies. Material m's
  // ghosts travel while material m + 1's boundary values are computed.
  std::vector<CellHaloBatch> in_flight(nm);
  for (std::size_t m = 0; m < nm; ++m) {
    IceMaterialFields& f = mats_[m];
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      const Patch& p = g.patches[pi];
      for (int face = 0; face < 6; ++face) {
        const GridFace gf = static_cast<GridFace>(face);
        const auto& bc = setup_.bcs[m][face];
        apply_vector_bc(g, p, gf, bc[kBcVelocity], vel_L_[m][pi]);
        apply_scalar_bc(g, p, gf, bc[kBcTemperature], temp_L_[m][pi]);
        if (bc[kBcSpecificVol].kind == BCKind::ComputeFromDensity) {
          for_each_boundary_cell(g, p, gf, [&](const IntVec3& e, const IntVec3&) {
            spv_L_[m][pi](e) = f.vol_frac_CC[pi](e) / f.rho_CC[pi](e);
          });
        } else {
          apply_scalar_bc(g, p, gf, bc[kBcSpecificVol], spv_L_[m][pi]);
        }
      }
      if (setup_.lodi.enabled) lodi_lagrangian_bc(m, pi);
      const IndexRange with_extra = p.cells_with_extra();
      const int ie = with_extra.lo[0], ne = with_extra.hi[0] - ie;
      for_each_row(with_extra, [&](int j, int k) {
        const double* mass = row_ptr(mass_L_[m][pi], ie, j, k);
        const Vec3* vel = row_ptr(vel_L_[m][pi], ie, j, k);
        const double* cv = row_ptr(cv_CC_[m][pi], ie, j, k);
        const double* temp = row_ptr(temp_L_[m][pi], ie, j, k);
        Vec3* mom = row_ptr(f.mom_L_ME_CC[pi], ie, j, k);
        double* eng = row_ptr(f.eng_L_ME_CC[pi], ie, j, k);
        for (int c = 0; c < ne; ++c) {
          mom[c] = mass[c] * vel[c];
          eng[c] = mass[c] * cv[c] * temp[c];
        }
      });
    }
    in_flight[m].add(mass_L_[m]).add(vel_L_[m]).add(temp_L_[m]).add(spv_L_[m]);
    halo_->begin_exchange(in_flight[m]);
  }
  for (CellHaloBatch& b : in_flight) halo_->finish_exchange(b);
}

// Viscous force div(theta tau) and conduction div(theta k grad T) of material
// m on patch pi (Diffusion.h), into visc_force_ and heat_. The extra cells of
// a Dirichlet velocity or temperature are mirrored about the wall value
// (q_e = 2 q_wall - q_inner) so that the wall sits on the boundary face;
// Uintah puts the Dirichlet value in the extra cell itself (the wall half a
// cell outside the domain), which makes the Rayleigh problem first order.
void IceComponent::compute_diffusion_sources(std::size_t m, std::size_t pi) {
  const Grid& g = setup_.grid;
  const Patch& patch = g.patches[pi];
  const IceMaterialSpec& spec = setup_.materials[m];
  const IceMaterialFields& f = mats_[m];
  // Inviscid, non-conducting material: the zeros of the last call stand
  // (no refill of two whole fields per material and step).
  if (diffusion_zero_.size() != g.patches.size()) diffusion_zero_.assign(g.patches.size(), 0);
  const bool none = spec.dynamic_viscosity == 0.0 && spec.thermal_conductivity == 0.0;
  if (none && diffusion_zero_[pi]) return;
  visc_force_[pi].fill(Vec3::Zero());
  heat_[pi].fill(0.0);
  diffusion_zero_[pi] = none;
  if (spec.dynamic_viscosity != 0.0) {
    vel_bc_[pi] = f.vel_CC[pi];
    for (int face = 0; face < 6; ++face) {
      const IceFaceBc& bc = setup_.bcs[m][face][kBcVelocity];
      if (bc.kind != BCKind::Dirichlet) continue;
      for_each_boundary_cell(g, patch, static_cast<GridFace>(face), [&](const IntVec3& e, const IntVec3& in) {
        vel_bc_[pi](e) = 2.0 * bc.vector - vel_bc_[pi](in);
      }, vel_bc_[pi].ghost_width());
    }
    add_viscous_force(g, patch, vel_bc_[pi], f.vol_frac_CC[pi], spec.dynamic_viscosity, visc_force_[pi]);
  }
  if (spec.thermal_conductivity != 0.0) {
    temp_bc_[pi] = f.temp_CC[pi];
    for (int face = 0; face < 6; ++face) {
      const IceFaceBc& bc = setup_.bcs[m][face][kBcTemperature];
      if (bc.kind != BCKind::Dirichlet) continue;
      for_each_boundary_cell(g, patch, static_cast<GridFace>(face), [&](const IntVec3& e, const IntVec3& in) {
        temp_bc_[pi](e) = 2.0 * bc.scalar - temp_bc_[pi](in);
      }, temp_bc_[pi].ghost_width());
    }
    add_heat_conduction(g, patch, temp_bc_[pi], f.vol_frac_CC[pi], spec.thermal_conductivity, heat_[pi]);
  }
}

// Step 10-11: advection with the face velocities after exchange, then the
// primitive variables rho = M/V, u = (Mu)/M, T = (M cv T)/(M cv), v = (Mv)/M
// and the boundary conditions.
void IceComponent::advect_and_advance(double dt, int step) {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  const EnergyCorrection energy = energy_correction();
  if (energy == EnergyCorrection::Mixture) work_corr_[0].fill(0.0);  // sum over materials of D (IceEnergy.cpp)
  // Material m's new state's ghosts travel while material m + 1 is advected.
  std::vector<CellHaloBatch> in_flight(mats_.size());
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    if (setup_.materials[m].lagrangian) continue;  // MPMICE solid: the particles carry it (mpmice/)
    IceMaterialFields& f = mats_[m];
    const double largest_outflow = check_outflux(g, f.vel_FCME, dt, step, radial());  // the largest sum_out phi
    // Mass first; its face fluxes carry the specific quantities.
    density_fluxes(g, setup_.advection, mass_L_[m], f.vel_FCME, dt, flux_);
    const bool weighted = scale_fluid_flux(m, dt, flux_);  // MPMICE: the face area the solids leave (IceLagrangianFlux.cpp)
    if (setup_.advection != AdvectionOrder::First)  // no donor sends more than (q + first-order outflow)/2
      bound_outflow(m, dt, weighted ? &lag_weight_ : nullptr, largest_outflow);  // ice/AdvectionBounds.h
    specific_fluxes(g, setup_.advection, vel_L_[m], f.vel_FCME, flux_, dt, flux_v_);
    // The net inflows (flux_divergence) of mass and momentum, summed in the row loop.
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      const IndexRange cells = g.patches[pi].cells();
      const int i0 = cells.lo[0], n = cells.hi[0] - i0;
      for_each_row(cells, [&](int j, int k) {
        const double* fx = row_ptr(flux_.at(0, pi), i0, j, k);
        const double *fy0 = row_ptr(flux_.at(1, pi), i0, j, k), *fy1 = row_ptr(flux_.at(1, pi), i0, j + 1, k);
        const double *fz0 = row_ptr(flux_.at(2, pi), i0, j, k), *fz1 = row_ptr(flux_.at(2, pi), i0, j, k + 1);
        const Vec3* vx = row_ptr(flux_v_.at(0, pi), i0, j, k);
        const Vec3 *vy0 = row_ptr(flux_v_.at(1, pi), i0, j, k), *vy1 = row_ptr(flux_v_.at(1, pi), i0, j + 1, k);
        const Vec3 *vz0 = row_ptr(flux_v_.at(2, pi), i0, j, k), *vz1 = row_ptr(flux_v_.at(2, pi), i0, j, k + 1);
        const double* mass_L_row = row_ptr(mass_L_[m][pi], i0, j, k);
        const Vec3* vel_L = row_ptr(vel_L_[m][pi], i0, j, k);
        double* mass_new = row_ptr(mass_new_[pi], i0, j, k);
        double* rho = row_ptr(f.rho_CC[pi], i0, j, k);
        Vec3* vel = row_ptr(f.vel_CC[pi], i0, j, k);
        const RadialWeights* rw = radial();  // axisymmetric: r-faces times r_f/r_i (ice/RadialWeights.h)
        const double* wlo = rw ? rw->lo_row(i0) : nullptr;
        const double* whi = rw ? rw->hi_row(i0) : nullptr;
        for (int c = 0; c < n; ++c) {
          const double dq = rw ? (wlo[c] * fx[c] - whi[c] * fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c])
                               : (fx[c] - fx[c + 1]) + (fy0[c] - fy1[c]) + (fz0[c] - fz1[c]);
          const Vec3 dqv = rw ? Vec3((wlo[c] * vx[c] - whi[c] * vx[c + 1]) + (vy0[c] - vy1[c]) + (vz0[c] - vz1[c]))
                              : Vec3((vx[c] - vx[c + 1]) + (vy0[c] - vy1[c]) + (vz0[c] - vz1[c]));
          const double mass_L = mass_L_row[c];
          const double mass = mass_L + dq;
          mass_new[c] = mass;
          rho[c] = mass / V;
          vel[c] = (mass_L * vel_L[c] + dqv) / mass;
        }
      });
    }
    // Model scalars first (a per-cell ideal gas needs its new cv below).
    if (model_src_) advect_model_scalars(m, dt);
    IceModel* gas = m < cell_gas_.size() ? cell_gas_[m] : nullptr;
    if (gas) {
      // Per-cell cv (SimpleRxn): the content is the energy M cv_L T_L, and
      // T = (M cv T)_new / (M_new cv_new), cv_new from the advected mixture
      // fraction (Uintah's computeSpecificHeat after advection).
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
        double* t = temp_L_[m][pi].data();
        const double* cv = cv_CC_[m][pi].data();
        for (std::size_t c = 0; c < temp_L_[m][pi].size(); ++c) t[c] *= cv[c];
      }
      gas->update_cell_properties();
    }
    // Temperature and specific volume, advected as the contents M T and M v (IceAdvectContent.cpp).
    advect_content(m, temp_L_[m], f.temp_CC, dt);
    if (gas) {
      const CellScalars& cv_new = *gas->cell_ideal_gas()->cv;
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
        for_each_cell(g.patches[pi].cells(), [&](int i, int j, int k) { f.temp_CC[pi](i, j, k) /= cv_new[pi](i, j, k); });
    }
    advect_content(m, spv_L_[m], f.sp_vol_CC, dt);
    if (energy != EnergyCorrection::None) add_advected_kinetic_energy_loss(m);  // IceEnergy.cpp
    apply_state_bcs(m, &in_flight[m]);
  }
  for (CellHaloBatch& b : in_flight)
    if (b.in_flight) halo_->finish_exchange(b);
  if (energy == EnergyCorrection::Mixture) add_mixture_advected_kinetic_energy_loss();  // IceEnergy.cpp
}

}  // namespace tephra
