// ICE shock tubes against the exact Riemann solution (tests/support/ExactRiemann).
//
// Decks: inputs/ICE/riemann_sm.ups (Sod-type air tube, decks README A8:
// p* = 28.86 kPa, u* = 285.1 m/s at t = 0.5 ms) and
// orderAccuracy/ICE/riemann.ups (Toro's test 1, A9: p* = 0.4663,
// u* = 1.3609 at t = 0.2). The oracle is the exact solution sampled at the
// cell centres; the observed order of the L1 error between resolutions N and
// 2N is log2(E_N / E_2N). For a solution with shocks and contacts a
// consistent scheme converges at first order at best in L1 (the contact is
// smeared over O(N^(1/2)) cells with first-order upwinding, so the density
// error converges slower than the pressure error; Toro sec. 6.4). Observed
// (N = 100/200/400/800, orders per doubling) with <conserveTotalEnergy>
// (default; docs/algorithms/ice.md "Total energy at shocks"): first order rho 0.59 0.64
// 0.64, p 0.78 0.78 0.82; second order rho 0.84 0.85 0.87, p 0.93 0.88 0.96,
// asserted >= 0.8 for every doubling (the brief's target). Star states at
// N = 800 (second order): p*, u*, rho*R within 0.01 %, rho*L -0.08 %
// (asserted 0.3 %; first order 0.5 %: rho*L -0.34 %). Uintah's energy
// equation (conserveTotalEnergy false) lost 0.18 % of the total energy at the
// shock and left the plateau off by up to 1.5 % whatever N (orders 0.73,
// 0.67, 0.63).
//
// The y and z sizes of the tube are set to one cell width: the deck's 1 mm
// (250 cells over 1 m) would make the time step follow dy, not dx, and turn a
// CFL study into 750 steps per run; the 1-D solution does not depend on them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"

#include "core/grid/Loop.h"
#include "tests/support/ExactRiemann.h"
#include "tests/support/IceRuns.h"
#include "tests/support/ShockTube.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::ExactRiemann;
using test::GasState;

using Errors = test::ShockTubeErrors;

test::IceRun run_tube(int n, const char* advection) {
  test::SodOptions o;
  o.cells = n;
  o.advection = advection;
  test::IceRun r = test::make_sod_run(o);
  test::run_to(r);
  return r;
}

Errors l1_errors(const test::IceRun& r, const ExactRiemann& ex, double x0) { return test::shock_tube_l1(r, ex, x0); }

std::string toro_deck() { return test::shared_dir() + "/decks/orderAccuracy/ICE/riemann.ups"; }

// Sod (A8): gamma 1.4, rho 1.1768/0.11768, p 101325/10132.5, u = 0, x0 = 0.5.
const GasState kSodL = test::sod_left(), kSodR = test::sod_right();
// Toro test 1 (A9): rho, u, p = 1, 0.75, 1 | 0.125, 0, 0.1; x0 = 0.3.
const GasState kToroL{1.0, 0.75, 1.0}, kToroR{0.125, 0.0, 0.1};

TEST(IceRiemann, ExactSolverReproducesTheStarStatesOfTheDecksReadme) {
  const ExactRiemann sod(kSodL, kSodR, 1.4);
  EXPECT_NEAR(sod.p_star(), 28.86e3, 0.01e3);  // README A8: 28.86 kPa
  EXPECT_NEAR(sod.u_star(), 285.1, 0.1);       // README A8: 285.1 m/s
  const ExactRiemann toro(kToroL, kToroR, 1.4);
  EXPECT_NEAR(toro.p_star(), 0.4663, 1e-4);  // Toro table 4.3, test 1
  EXPECT_NEAR(toro.u_star(), 1.3609, 1e-4);
  // README A8: star densities 0.480 (left of contact), 0.2406 (right).
  EXPECT_NEAR(sod.sample(sod.u_star() - 1e-9).rho, 0.480, 1e-3);
  EXPECT_NEAR(sod.sample(sod.u_star() + 1e-9).rho, 0.2406, 1e-4);
}

Errors convergence_study(const char* advection, double min_rho_order, double min_p_order, double star_tol) {
  const ExactRiemann ex(kSodL, kSodR, 1.4);
  constexpr int kRuns = 4;
  Errors e[kRuns];
  const int n[kRuns] = {100, 200, 400, 800};
  for (int k = 0; k < kRuns; ++k) {
    test::IceRun r = run_tube(n[k], advection);
    EXPECT_NEAR(r.time, 5e-4, 1e-15);
    e[k] = l1_errors(r, ex, 0.5);
    // Star-state plateau at the finest grid: the cell nearest the middle of
    // [contact, shock] (x = 0.643 .. 0.779 m at 0.5 ms).
    if (k == kRuns - 1) {
      const int mid = static_cast<int>(0.711 * n[k]), left = static_cast<int>(0.57 * n[k]);
      const double p = r.ice->press_CC()[0](mid, 0, 0), u = r.ice->fields()[0].vel_CC[0](mid, 0, 0)[0];
      const double rho_r = r.ice->fields()[0].rho_CC[0](mid, 0, 0), rho_l = r.ice->fields()[0].rho_CC[0](left, 0, 0);
      const double rho_r_ex = ex.sample((0.711 - 0.5) / r.time).rho, rho_l_ex = ex.sample((0.57 - 0.5) / r.time).rho;
      std::printf("Sod %s N=%d star: p* %+.3f%%  u* %+.3f%%  rho*R %+.3f%%  rho*L %+.3f%%\n", advection, n[k],
                  100 * (p / ex.p_star() - 1), 100 * (u / ex.u_star() - 1), 100 * (rho_r / rho_r_ex - 1),
                  100 * (rho_l / rho_l_ex - 1));
      EXPECT_NEAR(p, ex.p_star(), star_tol * ex.p_star());
      EXPECT_NEAR(u, ex.u_star(), star_tol * ex.u_star());
      EXPECT_NEAR(rho_r, rho_r_ex, star_tol * rho_r_ex);
      EXPECT_NEAR(rho_l, rho_l_ex, star_tol * rho_l_ex);
    }
  }
  const double order_rho = std::log2(e[2].rho / e[3].rho), order_p = std::log2(e[2].p / e[3].p);
  std::printf("Sod %s: L1(rho) %.4g %.4g %.4g %.4g order %.3f %.3f %.3f | L1(p) %.4g %.4g %.4g %.4g order %.3f %.3f %.3f\n",
              advection, e[0].rho, e[1].rho, e[2].rho, e[3].rho, std::log2(e[0].rho / e[1].rho),
              std::log2(e[1].rho / e[2].rho), order_rho, e[0].p, e[1].p, e[2].p, e[3].p, std::log2(e[0].p / e[1].p),
              std::log2(e[1].p / e[2].p), order_p);
  for (int k = 0; k + 1 < kRuns; ++k) {  // every doubling, 100 -> 200 -> 400 -> 800
    EXPECT_GE(std::log2(e[k].rho / e[k + 1].rho), min_rho_order) << advection << " N=" << n[k];
    EXPECT_GE(std::log2(e[k].p / e[k + 1].p), min_p_order) << advection << " N=" << n[k];
  }
  return e[1];
}

// Both orders, N = 100, 200, 400, 800; second order's error at N = 200 must be
// below 0.8 of first order's (observed 0.53).
TEST(IceRiemann, SodConvergesInL1AndSecondOrderBeatsFirstOrder) {
  set_thread_count(1);  // 1-D tubes: loop-helper threads cost more than they save
  const Errors first = convergence_study("FirstOrder", 0.5, 0.5, 0.005);
  const Errors second = convergence_study("SecondOrder", 0.8, 0.8, 0.003);
  std::printf("Sod N=200: L1(rho) first %.4g second %.4g\n", first.rho, second.rho);
  EXPECT_LT(second.rho, 0.8 * first.rho);
  EXPECT_LT(second.p, 0.8 * first.p);
}

// Toro's test 1 as the deck gives it (100 cells, first order, t = 0.2), and
// at 200 cells: the L1 pressure error converges (A9: "converging ~ first order").
TEST(IceRiemann, ToroTest1ConvergesToTheExactSolution) {
  const ExactRiemann ex(kToroL, kToroR, 1.4);
  auto run = [&](int n) {
    auto edit = [&](DeckNode& root) {
      DeckNode& box = test::deck_node(root, {"Grid", "Level", "Box"});
      test::deck_node(box, {"resolution"}).text = "[" + std::to_string(n) + ",1,1]";
    };
    test::IceRun r = test::make_ice_run(toro_deck(), edit);
    test::run_to(r);
    EXPECT_NEAR(r.time, 0.2, 1e-14);
    return l1_errors(r, ex, 0.3);
  };
  set_thread_count(1);
  const Errors e100 = run(100), e200 = run(200);
  const double order = std::log2(e100.p / e200.p);
  std::printf("Toro 1: L1(p) %.4g %.4g order %.3f; L1(rho) %.4g %.4g order %.3f\n", e100.p, e200.p, order, e100.rho,
              e200.rho, std::log2(e100.rho / e200.rho));
  EXPECT_GE(order, 0.4);  // observed 0.50; a sonic rarefaction (Toro sec. 6.4 "entropy glitch") slows first order
  EXPECT_LT(e100.p, 0.03);  // the pressure jump is 0.9: a few percent smeared over cells
}

// Toro's tests 2-5 (Toro, "Riemann Solvers ...", 3rd ed., table 4.1 and sec.
// 4.3.3), gamma = 1.4, on [0, 1] with the deck riemann.ups's set-up (c_v = 1,
// Neumann ends, T = p/((gamma - 1) rho c_v) so the EOS gives the table's p):
//   2: 1, -2, 0.4 | 1, 2, 0.4               x0 = 0.5, t = 0.15   (123 problem: near vacuum)
//   3: 1, 0, 1000 | 1, 0, 0.01              x0 = 0.5, t = 0.012  (left half of Woodward-Colella)
//   4: 5.99924, 19.5975, 460.894 | 5.99242, -6.19633, 46.0950   x0 = 0.4, t = 0.035 (shock collision)
//   5: 1, -19.59745, 1000 | 1, -19.59745, 0.01                  x0 = 0.8, t = 0.012 (stationary contact)
// Oracle: the runs finish (a non-positive rho_CC, temp_CC or sp_vol_CC stops
// ICE with NumericalFailure) with rho_CC > 0 and press_CC > 0 in every cell
// after every step, and the L1 errors of rho and p fall from N = 100 to 200.
// Measured L1(rho) N = 100 -> 200 (docs/algorithms/ice.md): 3: 0.21 -> 0.16 (first),
// 0.10 -> 0.070 (second); 4: 0.91 -> 0.61, 0.51 -> 0.27; 5: 0.12 -> 0.083,
// 0.13 -> 0.080. Without the energy correction tests 3-5 (second order) and 4
// (both) did not converge (Toro 4 second order 2.41 -> 2.46).
// Toro 2 with SecondOrder used to stop at step 80 (N = 100) with a negative
// sp_vol_CC in a nearly emptied cell: the compatible flux F_M v_slab carried
// several times the swept volume where rho changes by orders of magnitude
// between neighbours. T and v of one material are now advected as the
// contents M T, M v (ice/IceAdvectContent.cpp); Toro 2 converges at both orders
// (Toro2ConvergesAtBothOrders below).
struct ToroCase {
  int id;
  GasState L, R;
  double x0, t_end;
};
const ToroCase kToro[] = {
    {2, {1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 0.5, 0.15},
    {3, {1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 0.5, 0.012},
    {4, {5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, 0.4, 0.035},
    {5, {1.0, -19.59745, 1000.0}, {1.0, -19.59745, 0.01}, 0.8, 0.012},
};

// walls: symmetry (reflecting) ends instead of Neumann; conserve: the
// <conserveTotalEnergy> value (docs/algorithms/ice.md "Total energy at shocks").
std::string toro_case_deck(const ToroCase& c, int n, const char* advection, double cfl, bool walls = false,
                           bool conserve = true) {
  auto state = [](const GasState& s) {
    std::ostringstream x;
    x.precision(17);
    x << "<res>[2,1,1]</res><velocity>[" << s.u << ",0,0]</velocity><density>" << s.rho << "</density><pressure>" << s.p
      << "</pressure><temperature>" << s.p / (0.4 * s.rho) << "</temperature>";
    return x.str();
  };
  std::ostringstream x;
  const double h = 1.0 / n;
  x << R"(<Uintah_specification><Meta><title>toro</title></Meta><SimulationComponent type="ice"/>
  <Time><maxTime>)" << c.t_end << R"(</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max>
  <delt_init>1e-8</delt_init></Time>
  <DataArchiver><filebase>toro.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>)" << cfl << R"(</cfl><ICE><advection type=")" << advection << R"("/><conserveTotalEnergy>)"
    << (conserve ? "true" : "false") << R"(</conserveTotalEnergy></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE><material><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
   <thermal_conductivity>0</thermal_conductivity><specific_heat>1</specific_heat><gamma>1.4</gamma>
   <geom_object><difference><box label="all"><min>[-1,-1,-1]</min><max>[2,2,2]</max></box>
     <box label="right"><min>[)" << c.x0 << R"(,-1,-1]</min><max>[2,2,2]</max></box></difference>)"
    << state(c.L) << R"(</geom_object>
   <geom_object><box label="right"/>)" << state(c.R) << R"(</geom_object></material></ICE></MaterialProperties>
  <Grid><BoundaryConditions>)";
  for (const char* side : {"x-", "x+"})
    if (walls) x << "<Face side=\"" << side << R"("><BCType id="0" label="Symmetric" var="symmetry"/></Face>)";
    else x << "<Face side=\"" << side << R"("><BCType id="0" label="Pressure" var="Neumann"><value>0</value></BCType>
      <BCType id="0" label="Velocity" var="Neumann"><value>[0,0,0]</value></BCType>
      <BCType id="0" label="Temperature" var="Neumann"><value>0</value></BCType>
      <BCType id="0" label="Density" var="Neumann"><value>0</value></BCType>
      <BCType id="0" label="SpecificVol" var="computeFromDensity"><value>0</value></BCType></Face>)";
  for (const char* side : {"y-", "y+", "z-", "z+"})
    x << "<Face side=\"" << side << R"("><BCType id="0" label="Symmetric" var="symmetry"/></Face>)";
  x << R"(</BoundaryConditions><Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,)" << h << "," << h
    << R"(]</upper><resolution>[)" << n << R"(,1,1]</resolution><extraCells>[1,1,1]</extraCells>
   <patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>)";
  return x.str();
}

struct ToroResult {
  Errors e;
  double min_rho = 1e300, min_p = 1e300;
  int steps = 0;
};

ToroResult run_toro(const ToroCase& c, int n, const char* advection, double cfl) {
  test::IceRun r;
  r.deck = load_deck_from_string(toro_case_deck(c, n, advection, cfl), "toro.ups", ".");
  r.ice = make_ice_component(*r.deck);
  r.ice->initialize();
  ToroResult out;
  const Grid& g = r.ice->grid();
  while (r.time < c.t_end * (1 - 1e-14)) {
    const double dt = std::min(r.steps == 0 ? 1e-8 : r.ice->stable_timestep(), c.t_end - r.time);
    r.ice->advance(r.time, dt, ++r.steps);
    r.time += dt;
    for (int i = 0; i < g.cells[0]; ++i) {
      out.min_rho = std::min(out.min_rho, r.ice->fields()[0].rho_CC[0](i, 0, 0));
      out.min_p = std::min(out.min_p, r.ice->press_CC()[0](i, 0, 0));
    }
  }
  out.steps = r.steps;
  out.e = l1_errors(r, ExactRiemann(c.L, c.R, 1.4), c.x0);
  return out;
}

// Total energy sum_c rho V (c_v T + |u|^2/2) over the interior cells (c_v = 1 in these decks).
double total_energy(const IceComponent& ice) {
  const Grid& g = ice.grid();
  const double V = g.cell_volume();
  double e = 0;
  for (int i = 0; i < g.cells[0]; ++i) {
    const IceMaterialFields& f = ice.fields()[0];
    e += f.rho_CC[0](i, 0, 0) * V * (f.temp_CC[0](i, 0, 0) + 0.5 * f.vel_CC[0](i, 0, 0).squaredNorm());
  }
  return e;
}

// Energy budget of an isolated tube: Sod's states (Toro test 1 with u = 0:
// 1, 0, 1 | 0.125, 0, 0.1, x0 = 0.5) between reflecting walls, run to t = 0.4
// (the shock has hit the right wall and runs back, the rarefaction has
// reflected from the left wall). No energy crosses a wall (face velocity 0),
// so E(t) = E(0) exactly; with <conserveTotalEnergy> each step changes E by
// round-off only (the corrections are differences of face fluxes, docs/algorithms/ice.md).
// Uintah's energy equation (false) loses a measured fraction, asserted > 1e-3
// so that this test shows the difference.
TEST(IceRiemann, ClosedShockTubeConservesTotalEnergyToRoundOff) {
  set_thread_count(1);
  const ToroCase sod{1, {1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 0.5, 0.4};
  for (const char* adv : {"FirstOrder", "SecondOrder"}) {
    for (bool conserve : {true, false}) {
      test::IceRun r;
      r.deck = load_deck_from_string(toro_case_deck(sod, 200, adv, 0.4, true, conserve), "tube.ups", ".");
      r.ice = make_ice_component(*r.deck);
      r.ice->initialize();
      const double e0 = total_energy(*r.ice);
      double worst_step = 0;
      while (r.time < sod.t_end * (1 - 1e-14)) {
        const double dt = std::min(r.steps == 0 ? 1e-8 : r.ice->stable_timestep(), sod.t_end - r.time);
        const double before = total_energy(*r.ice);
        r.ice->advance(r.time, dt, ++r.steps);
        r.time += dt;
        worst_step = std::max(worst_step, std::abs(total_energy(*r.ice) - before) / e0);
      }
      const double drift = total_energy(*r.ice) / e0 - 1.0;
      std::printf("closed tube %s conserveTotalEnergy=%d: %d steps, E/E0 - 1 = %.3g, worst step %.3g\n", adv, conserve,
                  r.steps, drift, worst_step);
      if (conserve) {
        EXPECT_LT(std::abs(drift), 1e-13) << adv;
        EXPECT_LT(worst_step, 1e-14) << adv;
      } else {
        EXPECT_LT(drift, -1e-3) << adv;
      }
    }
  }
}

TEST(IceRiemann, ToroTests2To5KeepDensityAndPressurePositive) {
  set_thread_count(1);
  for (const ToroCase& c : kToro) {
    for (const char* adv : {"FirstOrder", "SecondOrder"}) {
      const ToroResult a = run_toro(c, 100, adv, 0.4), b = run_toro(c, 200, adv, 0.4);
      std::printf("Toro %d %s: N=100/200 L1(rho) %.4g %.4g  L1(u) %.4g %.4g  L1(p) %.4g %.4g; min rho %.3g, min p %.3g (%d steps)\n",
                  c.id, adv, a.e.rho, b.e.rho, a.e.u, b.e.u, a.e.p, b.e.p, std::min(a.min_rho, b.min_rho),
                  std::min(a.min_p, b.min_p), b.steps);
      EXPECT_GT(std::min(a.min_rho, b.min_rho), 0.0) << "Toro " << c.id << " " << adv;
      EXPECT_GT(std::min(a.min_p, b.min_p), 0.0) << "Toro " << c.id << " " << adv;
      // With <conserveTotalEnergy> the strong shocks converge (before: tests 3-5
      // second order and 4 first order did not): L1 falls from N = 100 to 200.
      EXPECT_LT(b.e.rho, a.e.rho) << "Toro " << c.id << " " << adv;
      EXPECT_LT(b.e.p, a.e.p) << "Toro " << c.id << " " << adv;
    }
  }
}

// Toro's test 2 (the 123 problem: two rarefactions leave a near-vacuum,
// exact star state p* = 0.00189, rho* = 0.0219, u* = 0; Toro table 4.3) at
// N = 100, 200, 400, both orders: rho and p stay positive after every step,
// the L1 errors of rho, u and p against the exact solution fall at every
// doubling. Measured second order L1(rho) 0.0173/0.0095/0.0050, first order
// 0.0363/0.0243/0.0159 (docs/algorithms/ice.md). ICE's cell-centred
// velocity empties the centre cells far below rho* (min rho ~1e-6 at second
// order, ~1e-4 at first): the positivity is the point of this test, the
// centre's density is the scheme's known weakness (Toro sec. 6.4 "the 123
// problem": most conservative schemes overheat / underfill the centre).
TEST(IceRiemann, Toro2ConvergesAtBothOrders) {
  set_thread_count(1);
  const ToroCase& c = kToro[0];
  ASSERT_EQ(c.id, 2);
  const ExactRiemann ex(c.L, c.R, 1.4);
  EXPECT_NEAR(ex.p_star(), 0.00189, 1e-5);  // Toro table 4.3, test 2
  EXPECT_NEAR(ex.u_star(), 0.0, 1e-12);
  for (const char* adv : {"FirstOrder", "SecondOrder"}) {
    ToroResult r[3];
    const int n[3] = {100, 200, 400};
    for (int k = 0; k < 3; ++k) r[k] = run_toro(c, n[k], adv, 0.4);
    std::printf("Toro 2 %s: N=100/200/400 L1(rho) %.4g %.4g %.4g  L1(u) %.4g %.4g %.4g  L1(p) %.4g %.4g %.4g; "
                "min rho %.3g %.3g %.3g, min p %.3g %.3g %.3g\n",
                adv, r[0].e.rho, r[1].e.rho, r[2].e.rho, r[0].e.u, r[1].e.u, r[2].e.u, r[0].e.p, r[1].e.p, r[2].e.p,
                r[0].min_rho, r[1].min_rho, r[2].min_rho, r[0].min_p, r[1].min_p, r[2].min_p);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(r[k].min_rho, 0.0) << adv << " N=" << n[k];
      EXPECT_GT(r[k].min_p, 0.0) << adv << " N=" << n[k];
    }
    for (int k = 0; k + 1 < 3; ++k) {
      EXPECT_LT(r[k + 1].e.rho, r[k].e.rho) << adv << " N=" << n[k];
      EXPECT_LT(r[k + 1].e.u, r[k].e.u) << adv << " N=" << n[k];
      EXPECT_LT(r[k + 1].e.p, r[k].e.p) << adv << " N=" << n[k];
    }
  }
}

}  // namespace
}  // namespace tephra
