// Semi-implicit pressure of ICE (Kashiwa et al., LA-13903; Uintah's
// ICE::implicitPressureSolve / setupMatrix / setupRHS / updatePressure):
// the face velocities depend on the end-of-step pressure, and the pressure
// is found so that the volume fractions the faces move balance the
// compressibility of the cell. docs/algorithms/ice.md, "Implicit pressure".
//
// Unknown p (cell pressure). With kappa_m = v_m/c_m^2, A_m(u_f) the net
// inflow of theta_m through the faces moved by the face velocities u_f(p)
// (the advection operator of the explicit step), the volume balance is
//   R(p) = sum_m theta_m kappa_m (p - p_eq) - sum_m A_m(u_f(p)) = 0.
// The face velocity (eq. 26.1 with p instead of p_eq) changes with a
// correction dp as u_f -> u_f - dt v_f (dp_R - dp_L)/dx_d (after the face
// exchange: v_f -> svFC = E^-1 v_f), so the flux theta_f u_f dt/dx_d changes
// by -a_f (dp_R - dp_L) with
//   a_f = sum_m theta_f,m svFC_m dt^2/dx_d^2,
//   theta_f = (theta_L + theta_R)/2,  v_f = 2 v_L v_R/(v_L + v_R)
// (ImplicitPressureMatrix.cpp, also for MPMICE's solids).
// Source models (Uintah's setupRHS, impICE.cc): the mass a model adds in a
// cell, S_M,m, arrives at the micro specific volume v_m of its material and
// must be squeezed into the cell as well, so the balance gains the term
//   term1 = sum_m S_M,m v_m / V          (delP_MassX_ before the division,
// computed with the volume fractions in compute_model_sources, which runs
// first, as Uintah's computeModelSources/updateVolumeFraction do):
//   R(p) = sum_m theta_m kappa_m (p - p_eq) - sum_m A_m(u_f(p)) - term1 = 0.
// After convergence (Uintah's computeDel_P) the increment splits as
//   delP_MassX = term1 / sum theta kappa,  delP_Dilatate = p - p_eq - delP_MassX,
// the same split the explicit step makes (eq. 26.2), and p >= 1e-12 Pa (Uintah's clamp).
// Newton-like outer iterations solve the symmetric positive definite system
//   (sum theta kappa + sum_faces a_f) dp_C - sum_faces a_f dp_nb = -R(p)
// (a_f with the face exchange in it, as Uintah's sp_vol_FC, and, in MPMICE,
// the fluids' flux through the area the solids leave:
// ImplicitPressureMatrix.cpp; it neglects the upwind switch of the flux; the
// outer iterations carry the exact residual), p <- p + dp, until
// max |R| < outer_iteration_tolerance. R is a volume fraction, so the
// tolerance is dimensionless (as Uintah's max_RHS).
// Boundary faces: a face whose velocity a BC fixes (Dirichlet velocity,
// symmetry) has a_f = 0; a Dirichlet pressure keeps dp = 0 in the extra cell
// (a_f on the diagonal only); a Neumann pressure moves the extra cell with the
// interior (a_f drops out). Periodic faces couple through hypre's periodic grid.
//
// Failure: a linear solve that does not reach its tolerance, more than
// iters_before_timestep_restart outer iterations, or a diverging outer
// iteration (max |R| above 101x its smallest value so far, Uintah's impICE.cc
// test), asks for a redo of the step
// (StepRedoRequest, core/sim/StepRedo.h). Uintah recomputes the step with
// dt * 0.75 (ICE::recomputeDelT; MPMICE::recomputeDelT: dt/2); Tephra's time
// loop owns dt, so the interval is redone as two steps of dt/2 (recursively,
// at most kMaxStepHalvings halvings, then NumericalFailure), by ICE alone
// (advance_with_restarts) and by MPMICE (the whole coupled step,
// mpmice/MpmIceComponent.cpp). No convergence in max_outer_iterations:
// NumericalFailure (Uintah: ConvergenceFailure).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/base/Log.h"
#include "core/grid/Loop.h"
#include "core/sim/StepRedo.h"
#include "ice/IceBoundary.h"
#include "ice/IceComponent.h"

namespace tephra {

// The state a failed attempt must put back (everything else a step reads is
// recomputed from it): the cell state, the pressure (the next Newton start),
// and the source models' carried fields, scalars and sums.
std::function<void()> IceComponent::step_snapshot() {
  save_step_start(redo_start_, true);
  return [this] { restore_step_start(redo_start_); };
}

// core/sim/StepRedo.h: the interval [t, t + dt] as one step, or (after a
// StepRedoRequest) as two of dt/2; source models read the time of each part.
void IceComponent::advance_with_restarts(double t, double dt, int step) {
  StepRedo redo;
  redo.who = "ICE";
  redo.snapshot = [this] { return step_snapshot(); };
  redo.attempt = [this, step](double t0, double h) {
    time_ = t0;
    advance_one(h, step);
  };
  try {
    advance_with_redo(redo, t, dt, step);
  } catch (const NumericalFailure&) {
    step_restarts_ += redo.redos;  // the redos before the limit count too
    throw;
  }
  step_restarts_ += redo.redos;
  time_ = t;
}

// rhs = -R(p) = sum_m A_m(u_f(p)) + term1 - sum theta kappa (p - p_eq); returns max |rhs|.
double IceComponent::pressure_residual(double dt) {
  const Grid& g = setup_.grid;
  sum_volume_flux_and_kappa(dt);
  double max_rhs = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const double term1 = model_src_ ? delP_MassX_[pi](i, j, k) : 0.0;
      const double r = delP_Dilatate_[pi](i, j, k) + term1 -
                       sum_kappa_[pi](i, j, k) * (press_CC_[pi](i, j, k) - press_equil_CC_[pi](i, j, k));
      rhs_[pi](i, j, k) = r;
      if (std::abs(r) > max_rhs) {
        max_rhs = std::abs(r);
        max_rhs_cell_ = IntVec3(i, j, k);
      }
    });
  return max_rhs;
}

// Where the largest residual of this process sits: its cell, and the volume
// fractions there (the why of a stalled outer iteration).
std::string IceComponent::residual_where() const {
  const IntVec3& c = max_rhs_cell_;
  std::ostringstream os;
  os << " in cell (" << c[0] << "," << c[1] << "," << c[2] << ") of this process; theta";
  const Grid& g = setup_.grid;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    if (g.patches[pi].cells().contains(c)) {
      for (const IceMaterialFields& f : mats_) os << " " << f.vol_frac_CC[pi](c);
      os << ", p " << press_CC_[pi](c) << " Pa, p_eq " << press_equil_CC_[pi](c) << " Pa";
    }
  return os.str();
}

void IceComponent::implicit_pressure_solve(double dt, int step) {
  const Grid& g = setup_.grid;
  const ImplicitSettings& im = setup_.implicit;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) press_CC_[pi] = press_equil_CC_[pi];
  // ICE alone the matrix depends on theta, v, K (fixed over the outer
  // iterations); with MPMICE solids it depends on the face velocities of the
  // iterate too (ImplicitPressureMatrix.cpp) and is rebuilt every iteration.
  bool coupled = false;
  for (std::size_t m = 0; m < mats_.size(); ++m) coupled = coupled || has_lagrangian_flux(m);
  if (!coupled) assemble_pressure_matrix(dt);
  int it = 0;
  double max_rhs = 0, smallest = 0;
  for (;; ++it) {
    compute_face_velocities(dt, press_CC_);
    add_exchange_to_face_velocities(dt);
    if (coupled && it == 0) freeze_solid_face_fractions(dt);  // IceLagrangianFlux.cpp: why
    max_rhs = layout_.max(pressure_residual(dt));  // the same on every rank: one decision
    if (max_rhs < im.outer_iteration_tolerance) break;
    if (it == im.max_outer_iterations) {
      std::ostringstream os;
      os << "ICE implicit pressure at step " << step << ": no convergence in " << im.max_outer_iterations
         << " outer iterations (max |residual| = " << max_rhs << " > outer_iteration_tolerance = "
         << im.outer_iteration_tolerance << residual_where() << ")";
      throw NumericalFailure(os.str());
    }
    // Uintah (impICE.cc): a residual more than 100x above the smallest of the
    // outer iterations so far is a diverging iteration: redo the step.
    smallest = it == 0 ? max_rhs : std::min(smallest, max_rhs);
    if (max_rhs - smallest > 100.0 * smallest) {
      std::ostringstream os;
      os << "the outer iteration diverges (max |residual| = " << max_rhs << " > 101 x the smallest so far, "
         << smallest << residual_where() << ")";
      throw StepRedoRequest{os.str()};
    }
    if (it >= im.iters_before_timestep_restart) {
      std::ostringstream os;
      os << "more than iters_before_timestep_restart = " << im.iters_before_timestep_restart
         << " outer iterations (max |residual| = " << max_rhs << residual_where() << ")";
      throw StepRedoRequest{os.str()};
    }
    if (coupled) assemble_pressure_matrix(dt);
    if (implicit_trace_enabled()) trace_outer_iteration(dt, step, it, max_rhs);
    if (outer_hook_) outer_hook_(*this, dt, step, it);
    const LinearSolveResult r = pressure_solver_->solve(stencil_, rhs_, delta_p_);
    if (!r.converged) {
      std::ostringstream os;
      os << "the hypre " << im.hypre.solver << " solve stopped at relative residual " << r.relative_residual
         << " after " << r.iterations << " iterations";
      throw StepRedoRequest{os.str()};
    }
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      for_each_cell(g.patches[pi].cells(), [&](int i, int j, int k) { press_CC_[pi](i, j, k) += delta_p_[pi](i, j, k); });
      apply_pressure_bc(pi, press_CC_);
    }
    halo_->exchange(press_CC_);
  }
  last_outer_iterations_ = it;
  // delP_Dilatate = p - p_eq - delP_MassX feeds the energy and
  // specific-volume updates exactly as the explicit increment does.
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    for_each_cell(g.patches[pi].cells(), [&](int i, int j, int k) {
      double dp_massx = 0;
      if (model_src_) {
        dp_massx = delP_MassX_[pi](i, j, k) / sum_kappa_[pi](i, j, k);
        delP_MassX_[pi](i, j, k) = dp_massx;
        press_CC_[pi](i, j, k) = std::max(1e-12, press_CC_[pi](i, j, k));
      }
      delP_Dilatate_[pi](i, j, k) = press_CC_[pi](i, j, k) - press_equil_CC_[pi](i, j, k) - dp_massx;
    });
    if (model_src_) apply_pressure_bc(pi, press_CC_);
  }
  if (model_src_) halo_->exchange(press_CC_);
}

}  // namespace tephra
