// The semi-implicit pressure in the coupled MPMICE step (<ImplicitSolver>,
// ice/ImplicitPressure.cpp, ice/ImplicitPressureMatrix.cpp, docs/mpmice.md).
//
// Deck: inputs/mpmice/quiescent_block.ups (a steel block of 0.1 m in air,
// 5^3 cells of 0.1 m, closed walls, K = 1e10 between steel and air) with
// <ImplicitSolver> added (cg + pfmg to 1e-12, outer tolerance 1e-10).
//
// 1. At rest: nothing moves (exact solution). |u| < 1e-10 m/s on particles
//    and cells and p = 101325 Pa to 1e-10 relative for 200 steps.
// 2. The block thrown at 5 m/s along x. Implicit and explicit solve the same
//    step except for the pressure the face velocities see (p_eq, explicit;
//    the end-of-step p, implicit): they differ by O(dt) (first order in
//    time), so the difference after a fixed time T must halve when dt halves
//    (ratio 2 +- 25 %), and be small against the change itself. Exact
//    discrete invariants in both: total mass (particles + air; no face of
//    the box lets mass through) to round-off, y and z momentum (zero by the
//    mirror symmetry of the set-up in y and z, 0 to round-off).
// 3. The outer iteration converges: at most 4 outer iterations per step.
// 4. A solve that cannot converge (max_outer_iterations = 1 with an outer
//    tolerance of 1e-300) stops with NumericalFailure (exit 4) naming the step.
// 5. Step redo (core/sim/StepRedo.h, MpmIceComponent::advance): a step whose
//    solve asks for a redo is put back and run as two steps of dt/2; the
//    state is then the same bits as a run that took those two half steps;
//    past kMaxStepHalvings halvings it is NumericalFailure naming the cell.
#include <gtest/gtest.h>

#include <cmath>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/sim/RunParameters.h"
#include "core/sim/StepRedo.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

struct ImplicitRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
  double time = 0;
  int steps = 0;
  int max_outer = 0;
};

ImplicitRun make_run(bool implicit, double block_speed, const std::string& outer_tol = "1e-10", int max_outer = 20,
                     const std::string& inner_tol = "", int iters_before_restart = 10) {
  ImplicitRun r;
  r.deck = load_deck(test::source_dir() + "/inputs/mpmice/quiescent_block.ups");
  if (block_speed != 0.0)
    test::deck_node(r.deck->root, {"MaterialProperties", "MPM", "material", "geom_object", "velocity"}).text =
        "[" + std::to_string(block_speed) + ", 0.0, 0.0]";
  if (implicit) {
    test::add_implicit_solver(r.deck->root, "", outer_tol);
    test::deck_node(r.deck->root, {"CFD", "ICE", "ImplicitSolver", "max_outer_iterations"}).text =
        std::to_string(max_outer);
    test::deck_node(r.deck->root, {"CFD", "ICE", "ImplicitSolver", "iters_before_timestep_restart"}).text =
        std::to_string(iters_before_restart);
    if (!inner_tol.empty())
      test::deck_node(r.deck->root, {"CFD", "ICE", "ImplicitSolver", "Parameters", "tolerance"}).text = inner_tol;
  }
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  return r;
}

void run_fixed(ImplicitRun& r, double dt, int n) {
  for (int i = 0; i < n; ++i) {
    ++r.steps;
    r.c->advance(r.time, dt, r.steps);
    r.time += dt;
    r.max_outer = std::max(r.max_outer, r.c->ice().last_outer_iterations());
  }
}

// max over interior cells of |a - b| of the air velocity (x) and of the pressure.
void field_difference(const ImplicitRun& a, const ImplicitRun& b, double& du, double& dp) {
  du = dp = 0;
  const Grid& g = a.c->ice().grid();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      du = std::max(du, std::abs(a.c->ice().fields()[1].vel_CC[pi](i, j, k)[0] -
                                 b.c->ice().fields()[1].vel_CC[pi](i, j, k)[0]));
      dp = std::max(dp, std::abs(a.c->ice().press_CC()[pi](i, j, k) - b.c->ice().press_CC()[pi](i, j, k)));
    });
}

// max over interior cells of |u_air,x| and |p - p0|.
void field_size(const ImplicitRun& a, double p0, double& u, double& p) {
  u = p = 0;
  const Grid& g = a.c->ice().grid();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      u = std::max(u, std::abs(a.c->ice().fields()[1].vel_CC[pi](i, j, k)[0]));
      p = std::max(p, std::abs(a.c->ice().press_CC()[pi](i, j, k) - p0));
    });
}

double particle_vx(const ImplicitRun& r) {
  const Particles& p = r.c->mpm().materials()[0].particles;
  double m = 0, mv = 0;
  for (std::size_t i = 0; i < p.size(); ++i) m += p.mass[i], mv += p.mass[i] * p.v[i][0];
  return mv / m;
}

TEST(MpmIceImplicit, QuiescentBlockStaysAtRest) {
  set_thread_count(1);
  ImplicitRun r = make_run(true, 0.0);
  run_fixed(r, 1e-5, 200);
  double du = 0, dp = 0;
  const Grid& g = r.c->ice().grid();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
      dp = std::max(dp, std::abs(r.c->ice().press_CC()[pi](i, j, k) / 101325.0 - 1));
      for (const IceMaterialFields& f : r.c->ice().fields()) du = std::max(du, f.vel_CC[pi](i, j, k).cwiseAbs().maxCoeff());
    });
  for (const Vec3& v : r.c->mpm().materials()[0].particles.v) du = std::max(du, v.cwiseAbs().maxCoeff());
  std::printf("quiescent implicit: max |u| %.3g m/s, max |p/p0 - 1| %.3g, max outer iterations %d\n", du, dp,
              r.max_outer);
  EXPECT_LT(du, 1e-10);
  EXPECT_LT(dp, 1e-10);
}

TEST(MpmIceImplicit, ThrownBlockAgreesWithExplicitToFirstOrderInTime) {
  set_thread_count(1);
  const double T = 4e-4;  // 40 steps of 1e-5 s: the block moves 2 mm, the air's pressure pulse 0.14 m
  double diff_u[2], diff_p[2], diff_vp[2];
  for (int level = 0; level < 2; ++level) {
    const int n = 40 << level;
    const double dt = T / n;
    ImplicitRun ex = make_run(false, 5.0), im = make_run(true, 5.0);
    const std::set<std::string> sums = {"TotalMass", "TotalMomentum"};
    const auto s0 = im.c->reductions(sums);
    run_fixed(ex, dt, n);
    run_fixed(im, dt, n);
    field_difference(ex, im, diff_u[level], diff_p[level]);
    diff_vp[level] = std::abs(particle_vx(ex) - particle_vx(im));
    double u_size = 0, p_size = 0;
    field_size(ex, 101325.0, u_size, p_size);
    const auto s1 = im.c->reductions(sums);
    std::printf("dt %.3g: |du_air| %.4g (of %.4g m/s), |dp| %.4g (of %.4g Pa), |dv_block| %.4g m/s (block %.6f), "
                "max outer iterations %d; mass %.3g rel, momentum y,z %.3g %.3g\n",
                dt, diff_u[level], u_size, diff_p[level], p_size, diff_vp[level], particle_vx(im), im.max_outer,
                s1.at("TotalMass")[0] / s0.at("TotalMass")[0] - 1, s1.at("TotalMomentum")[1],
                s1.at("TotalMomentum")[2]);
    EXPECT_NEAR(s1.at("TotalMass")[0], s0.at("TotalMass")[0], 1e-13 * s0.at("TotalMass")[0]);
    EXPECT_LT(std::abs(s1.at("TotalMomentum")[1]), 1e-12 * s0.at("TotalMomentum")[0]);
    EXPECT_LT(std::abs(s1.at("TotalMomentum")[2]), 1e-12 * s0.at("TotalMomentum")[0]);
    EXPECT_LE(im.max_outer, 4);
    // The implicit/explicit difference is small against the flow itself.
    EXPECT_LT(diff_u[level], 0.1 * u_size);
    EXPECT_LT(diff_p[level], 0.1 * p_size);
  }
  // At least first order in time: the difference falls by >= 2 (less 10 %)
  // when dt halves. Measured 3.79 (u) and 3.61 (p): second order.
  EXPECT_GT(diff_u[0] / diff_u[1], 1.8);
  EXPECT_GT(diff_p[0] / diff_p[1], 1.8);
}

TEST(MpmIceImplicit, UnconvergedSolveIsANumericalFailure) {
  set_thread_count(1);
  // Outer tolerance 1e-300 (hypre to 1e-301, clamped to PressureSolver::kRoundOffFloor):
  // one outer iteration cannot reach it.
  ImplicitRun r = make_run(true, 5.0, "1e-300", 1, "1e-301");
  try {
    run_fixed(r, 1e-5, 10);  // step 1 may balance exactly (air and block start locked)
    FAIL() << "no NumericalFailure";
  } catch (const NumericalFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("implicit pressure at step"), std::string::npos) << what;
    EXPECT_NE(what.find("no convergence in 1 outer iterations"), std::string::npos) << what;
  }
}

// Every array of the restart state (particles, nodes, cells, model state) of
// two runs: the number of entries whose bits differ (NaN-free states).
long long differing_entries(const ImplicitRun& a, const ImplicitRun& b) {
  StateArchive sa, sb;
  a.c->save_state(sa);
  b.c->save_state(sb);
  long long n = 0;
  EXPECT_EQ(sa.all_doubles().size(), sb.all_doubles().size());
  for (const auto& [name, va] : sa.all_doubles()) {
    const std::vector<double>& vb = sb.doubles(name);
    if (va.size() != vb.size()) {
      n += static_cast<long long>(std::max(va.size(), vb.size()));
      continue;
    }
    for (std::size_t i = 0; i < va.size(); ++i) n += va[i] != vb[i];
  }
  for (const auto& [name, va] : sa.all_ints()) n += va != sb.ints(name);
  return n;
}

// 5a. Forced once: at step 3 the first outer iteration of the full-dt attempt
// throws StepRedoRequest (as a stalled solve does, ImplicitPressure.cpp).
// MPMICE restores the step's start (save_state/load_state) and runs
// [t, t + dt] as two steps of dt/2, which converge. Expected: after 5 steps
// the state equals, bit for bit, that of a run whose step 3 is two calls of
// dt/2 (same step number) -- the redo starts from exactly the saved start and
// leaves nothing of the failed attempt behind. Control: the run without the
// forced failure differs from both (so the comparison can fail).
TEST(MpmIceImplicit, ForcedFailureRedoesTheStepAtHalfDt) {
  set_thread_count(1);
  const double dt = 1e-5;
  ImplicitRun forced = make_run(true, 5.0), halves = make_run(true, 5.0), plain = make_run(true, 5.0);
  int thrown = 0;
  forced.c->mutable_ice().set_outer_iteration_hook([&](IceComponent&, double h, int step, int) {
    if (step == 3 && h == dt && thrown == 0) {
      ++thrown;
      throw StepRedoRequest{"forced by the test"};
    }
  });
  run_fixed(forced, dt, 5);
  run_fixed(plain, dt, 5);
  run_fixed(halves, dt, 2);
  halves.c->advance(halves.time, 0.5 * dt, 3);
  halves.c->advance(halves.time + 0.5 * dt, 0.5 * dt, 3);
  halves.time += dt;
  halves.steps = 3;
  run_fixed(halves, dt, 2);
  const long long d_halves = differing_entries(forced, halves), d_plain = differing_entries(forced, plain);
  std::printf("forced redo: %d redo(s); entries differing from the dt/2 run %lld, from the run without redo %lld\n",
              forced.c->step_redos(), d_halves, d_plain);
  EXPECT_EQ(thrown, 1);
  EXPECT_EQ(forced.c->step_redos(), 1);
  EXPECT_EQ(halves.c->step_redos(), 0);
  EXPECT_EQ(d_halves, 0);
  EXPECT_GT(d_plain, 0);
}

// 5b. A real failure at every level: iters_before_timestep_restart = 1 with
// an outer tolerance of 1e-300 (unreachable; max_outer_iterations 20 is not
// reached first). The first step that does not balance exactly asks for a
// redo at dt, dt/2, dt/4, dt/8 and dt/16: 4 redos, then NumericalFailure
// (exit 4) naming the step, the cell of the largest residual and the why.
TEST(MpmIceImplicit, RedoLimitIsANumericalFailureNamingTheCell) {
  set_thread_count(1);
  ImplicitRun r = make_run(true, 5.0, "1e-300", 20, "1e-301", 1);
  try {
    run_fixed(r, 1e-5, 10);
    FAIL() << "no NumericalFailure";
  } catch (const NumericalFailure& e) {
    const std::string what = e.what();
    std::printf("redo limit after %d redos: %s\n", r.c->step_redos(), what.c_str());
    EXPECT_EQ(e.code(), ExitCode::NumericalFailure);
    EXPECT_EQ(r.c->step_redos(), kMaxStepHalvings);
    EXPECT_NE(what.find("MPMICE step " + std::to_string(r.steps)), std::string::npos) << what;
    EXPECT_NE(what.find("more than iters_before_timestep_restart = 1"), std::string::npos) << what;
    EXPECT_NE(what.find("in cell ("), std::string::npos) << what;
    EXPECT_NE(what.find("after 4 halvings"), std::string::npos) << what;
  }
}

// SteadyBurn_2dRT.ups (decks README C13), unchanged: steel ring, hollow
// PBX 9501 (Steady_Burn), TST product gas, implicit ICE (outer tolerance
// 1.01e-7, iters_before_timestep_restart 16), stepped with the deck's time
// rule (delt_init 1e-10, then min(0.7 dt_stable, 1.7 dt_prev)).
// 1. Session 15 cycled at step 12 (max |R| between 1.07e-7 and 1.75e-7 for 16
//    outer iterations, exit 4): a solid's face fraction F_s/phi_s jumped
//    between 1 and 0 when the iterate turned phi_s against F_s
//    (IceLagrangianFlux.cpp freeze_solid_face_fractions). Now every step to
//    16 converges; measured at most 4 outer iterations (asserted <= 6).
// 2. The matrix is the Jacobian: at every outer iteration of step 12, in the
//    cell of the largest residual (mixed steel/HMX cells with a trace of gas,
//    theta_gas ~ 2.6e-5), row c of the assembled matrix against the one-sided
//    finite differences of the residual, -d(rhs_c)/dp_n (h = 1e-7 p,
//    ImplicitPressureCheck.cpp): where the residual is smooth (J+ = J- to
//    1e-6 of the diagonal) every entry agrees to 1e-4 of the diagonal
//    (measured 1.4e-9). Session 15's matrix was 2x off in such cells.
TEST(MpmIceImplicit, SteadyBurn2dRtConvergesWithTheJacobianMatrix) {
  set_thread_count(1);
  auto deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/SteadyBurn_2dRT.ups");
  deck->root.finalize_parents();
  auto c = make_mpmice_component(*deck);
  c->initialize();
  const TimeParameters tp = read_time_parameters(deck->root.require_child("Time"));
  int rows_checked = 0;
  double worst = 0;
  c->mutable_ice().set_outer_iteration_hook([&](IceComponent& ice, double dt, int step, int) {
    if (step != 12) return;
    const IntVec3 c = ice.max_residual_cell();
    const IceComponent::JacobianRow row = ice.implicit_jacobian_row(dt, c);
    const double diag = std::abs(row.matrix[kCenter]);
    bool smooth = true;
    for (int s = 0; s < kStencilSize; ++s) smooth = smooth && std::abs(row.fd_plus[s] - row.fd_minus[s]) < 1e-6 * diag;
    std::printf("step 12 cell (%d,%d): A_cc %.4g, J+_cc %.4g, J-_cc %.4g, smooth %d\n", c[0], c[1], row.matrix[0],
                row.fd_plus[0], row.fd_minus[0], int(smooth));
    if (!smooth) return;
    ++rows_checked;
    for (int s = 0; s < kStencilSize; ++s) worst = std::max(worst, std::abs(row.matrix[s] - row.fd_plus[s]) / diag);
  });
  double t = 0, prev_dt = 0;
  int max_outer = 0;
  for (int step = 1; step <= 16; ++step) {
    double dt = *tp.delt_init;
    if (step > 1) dt = std::min(tp.timestep_multiplier * c->stable_timestep(), (1 + *tp.max_delt_increase) * prev_dt);
    ASSERT_NO_THROW(c->advance(t, dt, step)) << "step " << step;
    t += dt;
    prev_dt = dt;
    max_outer = std::max(max_outer, c->ice().last_outer_iterations());
  }
  std::printf("SteadyBurn_2dRT: 16 steps to t = %.4g s, max outer iterations %d; step 12: %d smooth rows, "
              "max |A - J| / A_cc = %.3g\n", t, max_outer, rows_checked, worst);
  EXPECT_LE(max_outer, 6);
  EXPECT_GE(rows_checked, 1);
  EXPECT_LT(worst, 1e-4);
}

}  // namespace
}  // namespace tephra
