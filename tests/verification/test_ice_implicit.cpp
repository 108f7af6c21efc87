// Implicit ICE pressure (ice/ImplicitPressure.cpp), periodic ICE grids and
// TimestepControl.
//
// 1. Sod (decks README A8, riemann_sm.ups, N = 200) with <ImplicitSolver>
//    added and knob_for_speedSound = 1 (the explicit time step): the implicit
//    and explicit solutions differ by far less than either differs from the
//    exact Riemann solution (the discretisation error). Measured in the test
//    output (L1 over the tube).
// 2. Low-Mach contact: a periodic 1-D box of air moving at u = 1 m/s (Mach
//    0.003) with a hot slab at the same pressure. Exact solution: the slab
//    translates, p and u stay uniform. For an ideal gas with one c_v the
//    conservative (compatible) transport of mass, internal energy and
//    specific volume keeps p = (gamma-1) E uniform, so p and u must stay
//    uniform to the solver tolerance, and with a uniform face velocity the
//    centroid of the density deficit moves by u t (the deficit is zero where
//    the periodic face wraps). Observed: |p/p0 - 1| 8.4e-13, |u - 1| 1.1e-11,
//    centroid shift 0.25 to 1e-9 in 41 steps (second order). Implicit with knob 0 takes
//    dt = cfl dx/|u|, explicit dt = cfl dx/(c + |u|): ratio (c + u)/u ~ 348.
// 4. Step redo (core/sim/StepRedo.h): an implicit Sod step forced to ask for
//    a redo is run as two steps of dt/2 and ends with the same bits as the
//    run that took those two half steps.
// 3. The unmodified orderAccuracy/ICE/rayleigh.ups (periodic in x,
//    ImplicitSolver, TimestepControl aggressive with knob 0): u_x against
//    Stokes' first problem u = U erfc(y / (2 sqrt(nu t))).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/grid/Loop.h"
#include "core/sim/StepRedo.h"
#include "tests/support/ExactRiemann.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

test::IceRun sod(int n, bool implicit) {
  auto edit = [&](DeckNode& root) {
    DeckNode& box = test::deck_node(root, {"Grid", "Level", "Box"});
    test::deck_node(box, {"resolution"}).text = "[" + std::to_string(n) + ",1,1]";
    const double w = 1.0 / n;
    test::deck_node(box, {"upper"}).text = "[1," + std::to_string(w) + "," + std::to_string(w) + "]";
    if (implicit) test::add_implicit_solver(root, "1.0");
  };
  test::IceRun r = test::make_ice_run(test::shared_dir() + "/decks/inputs/ICE/riemann_sm.ups", edit);
  test::run_to(r);
  return r;
}

TEST(IceImplicit, SodImplicitMatchesExplicitWithinTheDiscretisationError) {
  set_thread_count(1);
  const int n = 200;
  test::IceRun e = sod(n, false), i = sod(n, true);
  ASSERT_NEAR(i.time, e.time, 1e-15);
  const test::ExactRiemann ex({1.1768292682926831, 0.0, 101325.0}, {0.11768292682926831, 0.0, 10132.5}, 1.4);
  const Grid& g = e.ice->grid();
  double d_rho = 0, d_p = 0, err_e = 0, err_i = 0, err_pe = 0;
  for (int c = 0; c < g.cells[0]; ++c) {
    const double x = g.cell_center(c, 0, 0)[0];
    const test::GasState s = ex.sample((x - 0.5) / e.time);
    const double re = e.ice->fields()[0].rho_CC[0](c, 0, 0), ri = i.ice->fields()[0].rho_CC[0](c, 0, 0);
    const double pe = e.ice->press_CC()[0](c, 0, 0), pi = i.ice->press_CC()[0](c, 0, 0);
    d_rho += std::abs(re - ri) * g.dx[0];
    d_p += std::abs(pe - pi) * g.dx[0];
    err_e += std::abs(re - s.rho) * g.dx[0];
    err_i += std::abs(ri - s.rho) * g.dx[0];
    err_pe += std::abs(pe - s.p) * g.dx[0];
  }
  std::printf("Sod N=%d, %d steps: L1(rho_imp - rho_exp) = %.3e, L1(rho_exp - exact) = %.3e, "
              "L1(rho_imp - exact) = %.3e; L1(p_imp - p_exp) = %.3e, L1(p_exp - exact) = %.3e; outer its (last) %d\n",
              n, i.steps, d_rho, err_e, err_i, d_p, err_pe, i.ice->last_outer_iterations());
  EXPECT_LT(d_rho, 0.25 * err_e);
  EXPECT_LT(d_p, 0.25 * err_pe);
  EXPECT_LT(err_i, 1.1 * err_e);
  EXPECT_GE(i.ice->last_outer_iterations(), 1);
}

std::string low_mach_deck(const std::string& extra_ice) {
  return R"(<?xml version="1.0"?><Uintah_specification>
  <Meta><title>low-Mach periodic contact</title></Meta>
  <SimulationComponent type="ice"/>
  <Time><maxTime>0.25</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max>
    <timestep_multiplier>1</timestep_multiplier></Time>
  <DataArchiver><filebase>lowmach.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>0.4</cfl><ICE><advection type="SecondOrder"/>)" +
         extra_ice + R"(</ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE><material><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
    <thermal_conductivity>0</thermal_conductivity><specific_heat>716</specific_heat><gamma>1.4</gamma>
    <geom_object><box label="hot"><min>[0.25,-1,-1]</min><max>[0.5,1,1]</max></box><res>[2,2,2]</res>
      <velocity>[1,0,0]</velocity><density>1.0698445454545454</density><pressure>101325</pressure><temperature>330</temperature>
    </geom_object>
    <geom_object><box label="all"><min>[-1,-1,-1]</min><max>[2,2,2]</max></box><res>[2,2,2]</res>
      <velocity>[1,0,0]</velocity><density>1.176829</density><pressure>101325</pressure><temperature>300</temperature>
    </geom_object></material></ICE></MaterialProperties>
  <Grid><BoundaryConditions>
    <Face side="y-"><BCType id="all" label="Symmetric" var="symmetry"/></Face>
    <Face side="y+"><BCType id="all" label="Symmetric" var="symmetry"/></Face>
    <Face side="z-"><BCType id="all" label="Symmetric" var="symmetry"/></Face>
    <Face side="z+"><BCType id="all" label="Symmetric" var="symmetry"/></Face>
  </BoundaryConditions><Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,0.015625,0.015625]</upper>
    <resolution>[64,1,1]</resolution><extraCells>[0,1,1]</extraCells><patches>[2,1,1]</patches></Box>
    <periodic>[1,0,0]</periodic></Level></Grid></Uintah_specification>)";
}

TEST(IceImplicit, LowMachContactTakesLargeStepsAndKeepsPressureUniform) {
  set_thread_count(1);
  const std::string dir = test::scratch_dir("ice_low_mach");
  const std::string solver = R"(<ImplicitSolver><max_outer_iterations>20</max_outer_iterations>
    <outer_iteration_tolerance>1e-10</outer_iteration_tolerance><iters_before_timestep_restart>10</iters_before_timestep_restart>
    <Parameters variable="implicitPressure"><solver>cg</solver><preconditioner>pfmg</preconditioner>
    <tolerance>1e-12</tolerance><maxiterations>200</maxiterations></Parameters></ImplicitSolver>
    <TimestepControl><Scheme_for_delT_calc>aggressive</Scheme_for_delT_calc><knob_for_speedSound>0</knob_for_speedSound></TimestepControl>)";
  auto write = [&](const std::string& name, const std::string& xml) {
    std::ofstream(dir + "/" + name) << xml;
    return dir + "/" + name;
  };
  test::IceRun ex = test::make_ice_run(write("explicit.ups", low_mach_deck("")));
  test::IceRun im = test::make_ice_run(write("implicit.ups", low_mach_deck(solver)));
  const double dt_ex = ex.ice->stable_timestep(), dt_im = im.ice->stable_timestep();
  double c = 0;  // the largest sound speed (the hot slab) sets the explicit step
  for (std::size_t pi = 0; pi < ex.ice->grid().patches.size(); ++pi)
    for_each_cell_serial(ex.ice->grid().patches[pi].cells(),
                         [&](int i, int j, int k) { c = std::max(c, ex.ice->fields()[0].speedSound_CC[pi](i, j, k)); });
  std::printf("low Mach: dt explicit %.4e, implicit %.4e, ratio %.1f (expected (c+u)/u = %.1f)\n", dt_ex, dt_im,
              dt_im / dt_ex, (c + 1.0) / 1.0);
  EXPECT_NEAR(dt_im / dt_ex, c + 1.0, 1e-6 * c);  // dt = cfl dx/|u| against cfl dx/(c + |u|)

  const Grid& g = im.ice->grid();
  auto deficit_centroid = [&](const test::IceRun& r) {
    double s = 0, sx = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int, int) {
        const double w = 1.176829 - r.ice->fields()[0].rho_CC[pi](i, 0, 0);
        s += w;
        sx += w * g.cell_center(i, 0, 0)[0];
      });
    return sx / s;
  };
  const double x0 = deficit_centroid(im);
  test::run_to(im);
  EXPECT_NEAR(im.time, 0.25, 1e-14);
  // p0 = (gamma - 1) cv rho T = 0.4 * 716 * 1.176829 * 300 (both slabs: rho_hot = rho_cold 300/330).
  const double p0 = 0.4 * 716.0 * 1.176829 * 300.0;
  double dp = 0, du = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int, int) {
      dp = std::max(dp, std::abs(im.ice->press_CC()[pi](i, 0, 0) / p0 - 1.0));
      du = std::max(du, std::abs(im.ice->fields()[0].vel_CC[pi](i, 0, 0)[0] - 1.0));
    });
  const double shift = deficit_centroid(im) - x0;
  std::printf("low Mach implicit: %d steps, max |p/p0 - 1| = %.2e, max |u - 1| = %.2e, centroid shift %.9f (exact 0.25)\n",
              im.steps, dp, du, shift);
  EXPECT_LE(im.steps, 45);  // 0.25 s / (0.4 * 1/64 s) = 40 steps
  EXPECT_LT(dp, 1e-9);
  EXPECT_LT(du, 1e-7);
  EXPECT_NEAR(shift, 0.25, 1e-6);
}

// TimestepControl "conservative" (Uintah's swept-volume rule) on the low-Mach
// deck: uniform u = 1 along x, no gravity or diffusion. Per cell the outflow
// characteristic speeds are, along x, (1 + c) on the high face and (c - 1) on
// the low face, along y and z c on both, with c = knob max(c_L, c_R); so
//   dt = cfl V / sum_d 2 c A_d = cfl / (2 c sum_d 1/dx_d),
// set by the hot slab's (largest) c. knob 0.5 halves c.
TEST(IceImplicit, ConservativeTimestepIsTheSweptVolumeBound) {
  const std::string dir = test::scratch_dir("ice_conservative_dt");
  for (double knob : {1.0, 0.5}) {
    const std::string tc = "<TimestepControl><Scheme_for_delT_calc>conservative</Scheme_for_delT_calc>"
                           "<knob_for_speedSound>" + std::to_string(knob) + "</knob_for_speedSound></TimestepControl>";
    std::ofstream(dir + "/c.ups") << low_mach_deck(tc);
    test::IceRun r = test::make_ice_run(dir + "/c.ups");
    const Grid& g = r.ice->grid();
    double c = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(),
                           [&](int i, int j, int k) { c = std::max(c, r.ice->fields()[0].speedSound_CC[pi](i, j, k)); });
    const double expected = 0.4 / (2.0 * knob * c * (1 / g.dx[0] + 1 / g.dx[1] + 1 / g.dx[2]));
    EXPECT_NEAR(r.ice->stable_timestep(), expected, 1e-12 * expected) << "knob " << knob;
  }
}

// Implicit Sod, N = 100, fixed dt = 1e-5 s (CFL ~0.4). At step 3 the first
// outer iteration of the full-dt attempt throws StepRedoRequest (as a stalled
// solve does); ICE restores the step's start (IceComponent::step_snapshot)
// and runs two steps of dt/2. Expected: after 5 steps every array of the
// restart state equals, bit for bit, that of the run whose step 3 is two
// calls of dt/2; the run without the redo differs (the test can fail).
TEST(IceImplicit, ForcedFailureRedoesTheStepAtHalfDt) {
  set_thread_count(1);
  auto edit = [](DeckNode& root) {
    DeckNode& box = test::deck_node(root, {"Grid", "Level", "Box"});
    test::deck_node(box, {"resolution"}).text = "[100,1,1]";
    test::deck_node(box, {"upper"}).text = "[1,0.01,0.01]";
    test::add_implicit_solver(root, "1.0");
  };
  const std::string deck = test::shared_dir() + "/decks/inputs/ICE/riemann_sm.ups";
  test::IceRun forced = test::make_ice_run(deck, edit), halves = test::make_ice_run(deck, edit),
               plain = test::make_ice_run(deck, edit);
  const double dt = 1e-5;
  int thrown = 0;
  forced.ice->set_outer_iteration_hook([&](IceComponent&, double h, int step, int) {
    if (step == 3 && h == dt && thrown++ == 0) throw StepRedoRequest{"forced by the test"};
  });
  for (int step = 1; step <= 5; ++step) {
    const double t = (step - 1) * dt;
    forced.ice->advance(t, dt, step);
    plain.ice->advance(t, dt, step);
    if (step == 3) {
      halves.ice->advance(t, 0.5 * dt, step);
      halves.ice->advance(t + 0.5 * dt, 0.5 * dt, step);
    } else {
      halves.ice->advance(t, dt, step);
    }
  }
  auto differing = [](const IceComponent& a, const IceComponent& b) {
    StateArchive sa, sb;
    a.save_state(sa);
    b.save_state(sb);
    long long n = 0;
    for (const auto& [name, va] : sa.all_doubles()) {
      const std::vector<double>& vb = sb.doubles(name);
      for (std::size_t i = 0; i < va.size() && i < vb.size(); ++i) n += va[i] != vb[i];
    }
    return n;
  };
  const long long d_halves = differing(*forced.ice, *halves.ice), d_plain = differing(*forced.ice, *plain.ice);
  std::printf("ICE forced redo: %d redo(s); entries differing from the dt/2 run %lld, from the run without redo %lld\n",
              forced.ice->step_restarts(), d_halves, d_plain);
  EXPECT_EQ(forced.ice->step_restarts(), 1);
  EXPECT_EQ(halves.ice->step_restarts(), 0);
  EXPECT_EQ(d_halves, 0);
  EXPECT_GT(d_plain, 0);
}

TEST(IceImplicit, UnmodifiedRayleighDeckMatchesStokesFirstProblem) {
  set_thread_count(1);
  test::IceRun r = test::make_ice_run(test::shared_dir() + "/decks/orderAccuracy/ICE/rayleigh.ups");
  test::run_to(r);
  const Grid& g = r.ice->grid();
  ASSERT_TRUE(g.periodic[0]);
  const double U = 10.0, nu = 1e-4 / 1.1792946927374306, t = r.time;
  const double delta = 2.0 * std::sqrt(nu * t);
  double l1 = 0, spread = 0;
  for (int j = 0; j < g.cells[1]; ++j) {
    const double y = g.cell_center(0, j, 0)[1];
    const double u0 = r.ice->fields()[0].vel_CC[0](0, j, 0)[0];
    l1 += std::abs(u0 - U * std::erfc(y / delta)) * g.dx[1];
    for (int i = 1; i < g.cells[0]; ++i)
      spread = std::max(spread, std::abs(r.ice->fields()[0].vel_CC[0](i, j, 0)[0] - u0));
  }
  l1 /= U * delta;
  std::printf("rayleigh.ups: t = %.4g s, %d steps, L1(u - U erfc)/(U delta) = %.3e, x-spread %.1e\n", t, r.steps, l1,
              spread);
  EXPECT_NEAR(t, 2e-3, 1e-12);
  EXPECT_LT(l1, 1e-2);
  EXPECT_LT(spread, 1e-12);  // periodic in x: every column identical
}

}  // namespace
}  // namespace tephra
