// The explicit ICE step: construction, initial state, time step and the
// phase list. The phases themselves are in IceStep.cpp.
#include "ice/IceComponent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/base/PhaseTimers.h"
#include "core/grid/Loop.h"
#include "ice/Equilibration.h"
#include "ice/IceBoundary.h"
#include "ice/RowLoop.h"

namespace tephra {

namespace {
// Ghost layers of the cell fields: the second-order slope of a donor cell
// needs its neighbour, two cells from the face.
constexpr int kGhosts = 2;
}  // namespace

IceComponent::IceComponent(IceSetup setup) : setup_(std::move(setup)) {
  if (setup_.axisymmetric) radial_ = make_radial_weights(setup_.grid);
}

// Initial state from the <geom_object>s (Uintah's ICEMaterial::initializeCells,
// with mixing made explicit): each cell, extra cells included, is sampled at
// res0 x res1 x res2 sub-cell centres; a point belongs to the first source of
// the material that contains it. With f_s the fraction of points of source s
// (density rho_s, temperature T_s, velocity u_s, <volumeFraction> v_s, 1 when
// absent) and f = sum v_s f_s:
//   rho_CC = sum v_s f_s rho_s,
//   u, T   = mass-weighted averages over the sources,
//   rho_micro = rho_CC / f.
// Where f = 0 the material is absent: rho_CC = tiny_rho rho_s with the state
// of the last source that covers the cell (Uintah's IveBeenHere rule: a
// <volumeFraction>0 piece still sets rho_micro, T and u there), source 0's
// state where no source covers it.
// Uintah's rule for v_s (ICEMaterial::initializeCells, several materials):
// theta = v_s count_s/total replaces the fraction earlier pieces gave the
// cell, theta += count_s/total without it. Identical to the above when the
// material's pieces do not overlap, except that Uintah's replacement also
// zeroes, in the cells a volumeFraction piece does not cover, what earlier
// pieces gave them; Tephra keeps it (a deck relying on that fails Uintah's
// MPMICE sum-to-one check anyway).
// The pressure then follows from rho and T through the EOS (the
// equilibration below; the decks' <pressure> values are not used, as in
// Uintah, decks README "quirks").
void IceComponent::initialize() {
  lay_out_patches();
  const Grid& g = setup_.grid;
  const std::size_t nm = setup_.materials.size();
  mats_.clear();
  for (std::size_t m = 0; m < nm; ++m) mats_.emplace_back(g, kGhosts);
  press_CC_ = CellScalars(g, kGhosts);
  press_equil_CC_ = CellScalars(g, kGhosts);
  delP_Dilatate_ = CellScalars(g, kGhosts);
  sum_rho_CC_ = CellScalars(g, kGhosts);
  press_FC_ = FaceScalars(g, 0);
  mass_L_.assign(nm, CellScalars(g, kGhosts));
  temp_L_.assign(nm, CellScalars(g, kGhosts));
  if (setup_.conserve_total_energy) work_corr_.assign(nm, CellScalars(g, kGhosts));
  spv_L_.assign(nm, CellScalars(g, kGhosts));
  cv_CC_.assign(nm, CellScalars(g, kGhosts));
  vel_L_.assign(nm, CellVectors(g, kGhosts));
  flux_ = FaceScalars(g, 0);
  flux2_ = FaceScalars(g, 0);
  mass_new_ = CellScalars(g, kGhosts);
  content_ = CellScalars(g, kGhosts);
  flux_v_ = FaceData<Vec3>(g, 0);
  dq_ = CellScalars(g, kGhosts);
  sum_kappa_ = CellScalars(g, kGhosts);
  dqv_ = CellVectors(g, kGhosts);
  visc_force_ = CellVectors(g, kGhosts);
  vel_bc_ = CellVectors(g, kGhosts);
  heat_ = CellScalars(g, kGhosts);
  temp_bc_ = CellScalars(g, kGhosts);
  if (setup_.implicit.enabled) {
    pressure_solver_ = std::make_unique<PressureSolver>(g, setup_.implicit.hypre, layout_.distributed);
    for (CellScalars& a : stencil_) a = CellScalars(g, kGhosts);
    rhs_ = CellScalars(g, kGhosts);
    delta_p_ = CellScalars(g, kGhosts);
  }

  for (std::size_t m = 0; m < nm; ++m) {
    const IceMaterialSpec& spec = setup_.materials[m];
    IceMaterialFields& f = mats_[m];
    if (spec.lagrangian) {  // MPMICE solid: state from the particles (lagrangian_fill_ below)
      f.vol_frac_CC.fill(0.0);
      f.vel_CC.fill(Vec3::Zero());
      f.mom_source_CC.fill(Vec3::Zero());
      f.mom_L_ME_CC.fill(Vec3::Zero());  // checkpointed with its ghosts: no undefined entries
      f.mom_L_CC.fill(Vec3::Zero());     // written with its extra cells, which no step sets
      continue;
    }
    // Ghost entries outside the domain stay at harmless values.
    f.rho_CC.fill(spec.sources[0].density);
    f.temp_CC.fill(spec.sources[0].temperature);
    f.sp_vol_CC.fill(1.0 / spec.sources[0].density);
    f.rho_micro_CC.fill(spec.sources[0].density);
    f.vol_frac_CC.fill(1.0);
    f.vel_CC.fill(Vec3::Zero());
    f.mom_source_CC.fill(Vec3::Zero());
    f.mom_L_ME_CC.fill(Vec3::Zero());  // checkpointed with its ghosts: no undefined entries
    f.mom_L_CC.fill(Vec3::Zero());     // written with its extra cells, which no step sets
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      for_each_cell(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
        std::vector<int> count(spec.sources.size(), 0);
        const IntVec3 res = spec.sources[0].res;
        int total = 0;
        for (int c = 0; c < res[2]; ++c)
          for (int b = 0; b < res[1]; ++b)
            for (int a = 0; a < res[0]; ++a) {
              const Vec3 x = g.lower + Vec3((i + (a + 0.5) / res[0]) * g.dx[0], (j + (b + 0.5) / res[1]) * g.dx[1],
                                            (k + (c + 0.5) / res[2]) * g.dx[2]);
              ++total;
              for (std::size_t s = 0; s < spec.sources.size(); ++s)
                if (spec.sources[s].piece->inside(x)) {
                  ++count[s];
                  break;
                }
            }
        double frac = 0, mass = 0, energy = 0;
        Vec3 mom = Vec3::Zero();
        std::size_t last_covering = 0;  // source 0 where no source covers the cell
        for (std::size_t s = 0; s < spec.sources.size(); ++s) {
          if (count[s] > 0) last_covering = s;
          const IceSource& src = spec.sources[s];
          const double fs = src.volume_fraction * double(count[s]) / total;
          frac += fs;
          mass += fs * src.density;
          mom += fs * src.density * src.velocity;
          energy += fs * src.density * src.temperature;
        }
        if (frac > 0) {
          f.rho_CC[pi](i, j, k) = mass;
          f.vel_CC[pi](i, j, k) = mom / mass;
          f.temp_CC[pi](i, j, k) = energy / mass;
          f.sp_vol_CC[pi](i, j, k) = frac / mass;
        } else {
          const IceSource& sc = spec.sources[last_covering];
          f.rho_CC[pi](i, j, k) = spec.tiny_rho * sc.density;
          f.vel_CC[pi](i, j, k) = sc.velocity;
          f.temp_CC[pi](i, j, k) = sc.temperature;
          f.sp_vol_CC[pi](i, j, k) = 1.0 / sc.density;
        }
      });
    }
  }
  press_CC_.fill(setup_.reference_pressure);
  press_equil_CC_.fill(setup_.reference_pressure);
  delP_Dilatate_.fill(0.0);
  for (const IceMaterialSpec& spec : setup_.materials)
    if (spec.lagrangian && !lagrangian_fill_)
      throw std::logic_error("IceComponent: a lagrangian (MPM) material needs set_lagrangian_state_fill()");
  if (lagrangian_fill_) {
    lagrangian_fill_(*this);
    fluids_fill_volume_left_by_solids();
  }
  set_up_cell_ideal_gas();
  compute_equilibration_pressure(0);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    press_CC_[pi] = press_equil_CC_[pi];
  for (std::size_t m = 0; m < nm; ++m) apply_state_bcs(m);
  allocate_model_storage();
  check_state(0, "initialization");
}

// Models that make a material a per-cell ideal gas (SimpleRxn) are
// initialised here, before the first equilibration, so that the initial
// mixture density and the cell gamma and cv enter it (allocate_model_storage
// initialises them again, which recomputes the same fields).
void IceComponent::set_up_cell_ideal_gas() {
  cell_gas_.assign(mats_.size(), nullptr);
  for (const IceModelP& model : setup_.models)
    if (const CellIdealGas* gas = model->cell_ideal_gas()) {
      cell_gas_[gas->material] = model.get();  // parse_ice_models allows one per material
      model->initialize(setup_.grid, mats_);
      model->initialize_state(mats_);
    }
}

void IceComponent::fill_cell_gas_cv(std::size_t m, std::size_t pi) {
  if (m < cell_gas_.size() && cell_gas_[m]) cv_CC_[m][pi] = (*cell_gas_[m]->cell_ideal_gas()->cv)[pi];
}

// MPMICE initial state: the solids' cell volume fraction theta_s = sum over
// the lagrangian materials of rho_CC_s sp_vol_s comes from the particles
// projected to the nodes and averaged to the cells, which smears a solid
// surface over the cells next to it; the fluids' fractions from their
// geom_objects do not see that smearing, and the two would not sum to 1 (a
// pressure jump at the surface at t = 0). So each fluid keeps its micro state
// (rho_micro = 1/sp_vol, T, u) and its share f_m / sum f of the fluid
// geometry, and fills the volume the solids leave:
//   theta_m = f_m (1 - theta_s) / sum_f f,   rho_CC_m = theta_m / sp_vol_m.
// A cell the fluid geometry leaves empty (sum f = 0, e.g. a <volumeFraction>
// 0 piece under the solid) is filled by the first fluid material in the micro
// state initialize() gave it there. (Departure from Uintah, which keeps the
// geometric fractions; docs/mpmice.md.)
void IceComponent::exchange_cell_state(std::size_t m) {
  IceMaterialFields& f = mats_[m];
  CellHaloBatch batch;
  batch.add(f.rho_CC).add(f.vel_CC).add(f.temp_CC).add(f.sp_vol_CC);
  halo_->exchange_now(batch);
}

void IceComponent::fluids_fill_volume_left_by_solids() {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  std::size_t first_fluid = nm;
  for (std::size_t m = 0; m < nm; ++m)
    if (!setup_.materials[m].lagrangian) {
      first_fluid = m;
      break;
    }
  if (first_fluid == nm) return;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      double theta_s = 0, sum_f = 0;
      for (std::size_t m = 0; m < nm; ++m) {
        const double frac = mats_[m].rho_CC[pi](c) * mats_[m].sp_vol_CC[pi](c);
        (setup_.materials[m].lagrangian ? theta_s : sum_f) += frac;
      }
      const double left = std::max(0.0, 1.0 - theta_s);
      const double tiny = 1e-12;
      if (sum_f > tiny) {
        for (std::size_t m = 0; m < nm; ++m)
          if (!setup_.materials[m].lagrangian) {
            const IceMaterialSpec& spec = setup_.materials[m];
            const double frac = mats_[m].rho_CC[pi](c) * mats_[m].sp_vol_CC[pi](c);
            const double theta = frac * left / sum_f;
            mats_[m].rho_CC[pi](c) = std::max(theta / mats_[m].sp_vol_CC[pi](c), spec.tiny_rho * spec.sources[0].density);
          }
      } else {
        IceMaterialFields& f = mats_[first_fluid];
        const double rho_micro = 1.0 / f.sp_vol_CC[pi](c);
        f.rho_CC[pi](c) = std::max(left * rho_micro, setup_.materials[first_fluid].tiny_rho * rho_micro);
      }
    });
}

namespace {
// min over the cells of r of value(i, j, k), threaded over the rows of r
// (a minimum does not depend on the order of the comparisons).
template <class Value>
double row_minimum(const IndexRange& r, Value&& value) {
  if (r.empty()) return std::numeric_limits<double>::infinity();
  const int ny = r.hi[1] - r.lo[1];
  std::vector<double> row_min(static_cast<std::size_t>(ny) * (r.hi[2] - r.lo[2]), std::numeric_limits<double>::infinity());
  for_each_row(r, [&](int j, int k) {
    double m = std::numeric_limits<double>::infinity();
    for (int i = r.lo[0]; i < r.hi[0]; ++i) m = std::min(m, value(i, j, k));
    row_min[static_cast<std::size_t>(k - r.lo[2]) * ny + (j - r.lo[1])] = m;
  });
  double m = std::numeric_limits<double>::infinity();
  for (double v : row_min) m = std::min(m, v);
  return m;
}
}  // namespace

// Uintah's ICE time step (computeStableTimestep), knob = knob_for_speedSound:
//   aggressive:   dt = cfl * min over materials, interior cells, directions d
//                 of dx_d / (knob c + |u_d|);
//   conservative: dt = cfl * V / sum over the six faces of the outflow volume
//                 per unit time, A_d max(0, +-u_char), with the characteristic
//                 velocity u_char = (u_C + u_nb)/2 +- (knob max(c_L, c_R)
//                 + |u_R - u_L| + sqrt(sum_d dx_d |g_d|) + D/|dx|) on the
//                 high (+) and low (-) face along each direction. Uintah adds
//                 max(k v/cp, mu)/|dx| (a dynamic viscosity, not a speed);
//                 Tephra uses the kinematic D = max(k v/cv, mu v).
// Implicit ICE (Uintah) uses the same formulas with knob 0.5 by default; decks
// set 0 so that the step follows the flow speed alone.
double IceComponent::stable_timestep() const {
  const Grid& g = setup_.grid;
  double dt = std::numeric_limits<double>::infinity();
  const double knob = setup_.delt_knob;
  if (setup_.delt_scheme == DeltScheme::Aggressive) {
    for (const IceMaterialFields& f : mats_)
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
        dt = std::min(dt, row_minimum(g.patches[pi].cells(), [&](int i, int j, int k) {
          double r = std::numeric_limits<double>::infinity();
          const double c = knob * f.speedSound_CC[pi](i, j, k);
          const Vec3& u = f.vel_CC[pi](i, j, k);
          for (int d = 0; d < 3; ++d) r = std::min(r, g.dx[d] / (c + std::abs(u[d]) + 1e-100));
          return r;
        }));
  } else {
    const Vec3 area(g.dx[1] * g.dx[2], g.dx[0] * g.dx[2], g.dx[0] * g.dx[1]);
    const double V = g.cell_volume();
    const double grav_vel = std::sqrt(g.dx.dot(setup_.gravity.cwiseAbs()));
    for (std::size_t m = 0; m < mats_.size(); ++m) {
      const IceMaterialFields& f = mats_[m];
      const IceMaterialSpec& spec = setup_.materials[m];
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
        dt = std::min(dt, row_minimum(g.patches[pi].cells(), [&](int i, int j, int k) {
          const IntVec3 C(i, j, k);
          const double v = f.sp_vol_CC[pi](C);
          const double diff_vel =
              std::max(spec.thermal_conductivity * v / spec.cv, spec.dynamic_viscosity * v) / g.dx.norm();
          double swept = 0;
          for (int d = 0; d < 3; ++d) {
            const IntVec3 e = IntVec3::Unit(d);
            const IntVec3 L = C - e, R = C + e;
            const double uC = f.vel_CC[pi](C)[d], uL = f.vel_CC[pi](L)[d], uR = f.vel_CC[pi](R)[d];
            const double c = std::max(f.speedSound_CC[pi](L), f.speedSound_CC[pi](R));
            const double extra = knob * c + std::abs(uR - uL) + grav_vel + diff_vel;
            if (radial() && d == 0) {  // axisymmetric: r-face areas r_f/r_i of the Cartesian one (ice/RadialWeights.h)
              swept += area[d] * (*radial_.hi_row(i) * std::max(0.0, 0.5 * (uC + uR) + extra) +
                                  *radial_.lo_row(i) * std::max(0.0, -(0.5 * (uC + uL) - extra)));
              continue;
            }
            swept += area[d] * (std::max(0.0, 0.5 * (uC + uR) + extra) + std::max(0.0, -(0.5 * (uC + uL) - extra)));
          }
          return V / (swept + 1e-100);
        }));
    }
  }
  dt *= setup_.cfl;
  // Source models' own explicit limits (PassiveScalar diffusion), not scaled by cfl.
  for (const IceModelP& model : setup_.models) dt = std::min(dt, model->stable_timestep());
  // Explicit diffusion limit (viscosity, conduction): the forward-Euler
  // stability bound of u_t = D lap u, dt <= 1/(2 D sum_d 1/dx_d^2), with
  // D = max(mu/rho, k/(rho cv)) over the cells (rho the micro density).
  double inv_dx2 = 0;
  for (int d = 0; d < 3; ++d) inv_dx2 += 1.0 / (g.dx[d] * g.dx[d]);
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const IceMaterialSpec& spec = setup_.materials[m];
    if (spec.dynamic_viscosity == 0.0 && spec.thermal_conductivity == 0.0) continue;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        const double v = mats_[m].sp_vol_CC[pi](i, j, k);
        const double D = std::max(spec.dynamic_viscosity * v, spec.thermal_conductivity * v / spec.cv);
        if (D > 0) dt = std::min(dt, 0.5 / (D * inv_dx2));
      });
  }
  return layout_.min(dt);  // the same on every rank (a minimum is exact in any order)
}

// One explicit ICE step (Vaango theory manual ch. 26 step list, pure-fluid
// subset; inventory ch. 24 "ICE time step"). docs/algorithms/ice.md has the equations.
void IceComponent::advance(double t, double dt, int step) {
  time_ = t;
  // Implicit, and explicit with source models: a step that fails (no pressure
  // convergence, or a negative Lagrangian specific volume, Uintah's
  // recomputeTimeStep) is redone as two steps of dt/2.
  if (redoes_failed_steps()) {
    advance_with_restarts(t, dt, step);
    return;
  }
  advance_one(dt, step);
}

void IceComponent::advance_one(double dt, int step) {
  PhaseTimers& T = phase_timers();
  lag_theta_frozen_ = false;  // the solids' face fractions of this step are computed afresh
  { PhaseTimers::Scope s(T, "ICE: equilibration pressure");       compute_equilibration_pressure(step); }
  if (setup_.implicit.enabled) {
    // Uintah's implicit order: the model sources and the volume fractions
    // they change come before the pressure solve, whose right-hand side
    // carries their mass-exchange term (ImplicitPressure.cpp).
    if (model_src_) { PhaseTimers::Scope s(T, "ICE: model sources"); compute_model_sources(dt, step); }
    PhaseTimers::Scope s(T, "ICE: implicit pressure");            implicit_pressure_solve(dt, step);
  } else {
    { PhaseTimers::Scope s(T, "ICE: face velocities");            compute_face_velocities(dt, press_equil_CC_); }
    { PhaseTimers::Scope s(T, "ICE: face momentum exchange");     add_exchange_to_face_velocities(dt); }
    if (model_src_) { PhaseTimers::Scope s(T, "ICE: model sources"); compute_model_sources(dt, step); }
    { PhaseTimers::Scope s(T, "ICE: pressure increment");         compute_delP_and_pressure(dt); }
  }
  { PhaseTimers::Scope s(T, "ICE: face pressure");                compute_face_pressure(); }
  { PhaseTimers::Scope s(T, "ICE: Lagrangian values, exchange");  lagrangian_values_and_exchange(dt); }
  { PhaseTimers::Scope s(T, "ICE: advection");                    advect_and_advance(dt, step); }
  check_state(step, "end of step");
}

// The coupled MPMICE step calls the step in two halves (the order of
// advance_one). A StepRedoRequest (implicit pressure, Lagrangian specific
// volume) goes up to MpmIceComponent::advance, which redoes the whole coupled
// step with dt/2 (particles and cells restored).
void IceComponent::coupled_pressure_phases(double dt, int step) {
  PhaseTimers& T = phase_timers();
  lag_theta_frozen_ = false;  // the solids' face fractions of this step are computed afresh
  { PhaseTimers::Scope s(T, "ICE: equilibration pressure");       compute_equilibration_pressure(step); }
  if (setup_.implicit.enabled) {
    if (model_src_) { PhaseTimers::Scope s(T, "ICE: model sources"); compute_model_sources(dt, step); }
    {
      PhaseTimers::Scope s(T, "ICE: implicit pressure");
      implicit_pressure_solve(dt, step);  // may ask for a redo (MpmIceComponent::advance)
    }
    { PhaseTimers::Scope s(T, "ICE: face pressure");              compute_face_pressure(); }
    return;
  }
  { PhaseTimers::Scope s(T, "ICE: face velocities");              compute_face_velocities(dt, press_equil_CC_); }
  { PhaseTimers::Scope s(T, "ICE: face momentum exchange");       add_exchange_to_face_velocities(dt); }
  if (model_src_) { PhaseTimers::Scope s(T, "ICE: model sources"); compute_model_sources(dt, step); }
  { PhaseTimers::Scope s(T, "ICE: pressure increment");           compute_delP_and_pressure(dt); }
  { PhaseTimers::Scope s(T, "ICE: face pressure");                compute_face_pressure(); }
}

void IceComponent::coupled_transport_phases(double dt, int step) {
  PhaseTimers& T = phase_timers();
  { PhaseTimers::Scope s(T, "ICE: Lagrangian values, exchange");  lagrangian_values_and_exchange(dt); }
  { PhaseTimers::Scope s(T, "ICE: advection");                    advect_and_advance(dt, step); }
  check_state(step, "end of step");
}

void IceComponent::apply_state_bcs(std::size_t m, CellHaloBatch* deferred) {
  const Grid& g = setup_.grid;
  IceMaterialFields& f = mats_[m];
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& p = g.patches[pi];
    for (int face = 0; face < 6; ++face) {
      const GridFace gf = static_cast<GridFace>(face);
      const auto& bc = setup_.bcs[m][face];
      apply_scalar_bc(g, p, gf, bc[kBcDensity], f.rho_CC[pi]);
      apply_scalar_bc(g, p, gf, bc[kBcTemperature], f.temp_CC[pi]);
      apply_vector_bc(g, p, gf, bc[kBcVelocity], f.vel_CC[pi]);
      if (bc[kBcSpecificVol].kind == BCKind::ComputeFromDensity) {
        for_each_boundary_cell(g, p, gf, [&](const IntVec3& e, const IntVec3&) {
          f.sp_vol_CC[pi](e) = f.vol_frac_CC[pi](e) / f.rho_CC[pi](e);
        });
      } else {
        apply_scalar_bc(g, p, gf, bc[kBcSpecificVol], f.sp_vol_CC[pi]);
      }
    }
    if (setup_.lodi.enabled) lodi_state_bc(m, pi);
  }
  CellHaloBatch now;
  CellHaloBatch& batch = deferred ? *deferred : now;
  batch.add(f.rho_CC).add(f.temp_CC).add(f.vel_CC).add(f.sp_vol_CC);
  halo_->begin_exchange(batch);
  if (!deferred) halo_->finish_exchange(batch);
}

// A NaN, a non-positive density, temperature or specific volume stops the
// run (exit 4) naming the material, the cell and the step.
void IceComponent::check_state_here(int step, const char* phase) const {
  const Grid& g = setup_.grid;
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const IceMaterialFields& f = mats_[m];
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      auto good = [&](int i, int j, int k) {
        const double rho = f.rho_CC[pi](i, j, k), T = f.temp_CC[pi](i, j, k), v = f.sp_vol_CC[pi](i, j, k);
        const Vec3& u = f.vel_CC[pi](i, j, k);
        const double p = press_CC_[pi](i, j, k);
        return rho > 0 && T > 0 && v > 0 && std::isfinite(rho) && std::isfinite(T) && std::isfinite(v) &&
               u.allFinite() && std::isfinite(p);
      };
      // Threaded screen over the rows; only a bad state goes to the serial
      // scan below, which reports the first bad cell in (k, j, i) order.
      const IndexRange box = g.patches[pi].cells_with_extra();
      const int i0 = box.lo[0], n = box.hi[0] - i0;
      std::vector<char> row_bad(static_cast<std::size_t>(box.extent()[1]) * box.extent()[2], 0);
      for_each_row(box, [&](int j, int k) {
        const double *rho = row_ptr(f.rho_CC[pi], i0, j, k), *T = row_ptr(f.temp_CC[pi], i0, j, k);
        const double *v = row_ptr(f.sp_vol_CC[pi], i0, j, k), *p = row_ptr(press_CC_[pi], i0, j, k);
        const Vec3* u = row_ptr(f.vel_CC[pi], i0, j, k);
        bool bad = false;
        for (int c = 0; c < n; ++c)
          bad |= !(rho[c] > 0 && T[c] > 0 && v[c] > 0 && std::isfinite(rho[c]) && std::isfinite(T[c]) &&
                   std::isfinite(v[c]) && std::isfinite(u[c][0]) && std::isfinite(u[c][1]) && std::isfinite(u[c][2]) &&
                   std::isfinite(p[c]));
        row_bad[static_cast<std::size_t>(k - box.lo[2]) * box.extent()[1] + (j - box.lo[1])] = bad;
      });
      if (std::find(row_bad.begin(), row_bad.end(), 1) == row_bad.end()) continue;
      for_each_cell_serial(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
        if (good(i, j, k)) return;
        const double rho = f.rho_CC[pi](i, j, k), T = f.temp_CC[pi](i, j, k), v = f.sp_vol_CC[pi](i, j, k);
        const Vec3& u = f.vel_CC[pi](i, j, k);
        const double p = press_CC_[pi](i, j, k);
        std::ostringstream os;
        os << "ICE " << phase << " at step " << step << ": material " << m << " cell (" << i << "," << j << "," << k
           << ") has rho_CC = " << rho << ", temp_CC = " << T << ", sp_vol_CC = " << v << ", vel_CC = ("
           << u[0] << "," << u[1] << "," << u[2] << "), press_CC = " << p;
        throw NumericalFailure(os.str());
      });
    }
  }
}

}  // namespace tephra
