// Total energy of a mixture of ICE materials (docs/algorithms/ice.md "Total energy at
// shocks", mixtures; ice/IceEnergy.cpp): the cell's face-pressure-work and
// DeBar corrections and the kinetic energy the momentum exchange removes,
// split among the materials by mass.
//
// Oracles:
// 1. Same gas as two materials, each filling the whole tube with half of
//    Sod's densities (same u, T; Toro test 1 states with u = 0, gamma 1.4,
//    c_v = 1, x0 = 0.5): the exact answer is Sod's. The two materials are
//    twins: they must stay identical to round-off (each gets half of every
//    flux and half of the cell's correction). The mixture is not the
//    one-material run to round-off even with Uintah's equations: one ICE
//    material takes p from its advected specific volume (theta = rho v may
//    drift from 1), two materials re-equilibrate sum theta = 1 every step;
//    measured L1(rho_mix - rho_one) = 0.07 (first order) and 0.16 (second)
//    of L1(rho_one - Sod), asserted < 0.25. The mixture's L1 error against
//    Sod must be within 10 % of one material's and below Uintah's
//    equations' (conserveTotalEnergy false).
// 2. Conservation: the two materials side by side (left state = material 0,
//    right state = material 1, the absent material at tiny_rho) between
//    reflecting walls, run through the shock's reflection. No energy
//    crosses a wall, so E = sum_cells sum_m M_m (c_v T_m + |u_m|^2/2) is
//    constant; with the corrections each step changes it by round-off
//    (every correction is a face-flux difference or a redistribution inside
//    a cell). Uintah's equations (conserveTotalEnergy false) lose a
//    measurable fraction (asserted, so that the test shows the difference).
//    Exchange coefficients K = H = 1e3. (Session 17 re-measured K = H =
//    1e10 and 1e15: E/E0 - 1 <= 4.4e-15, worst step 1.8e-14, with both the
//    session-16 and the session-17 exchange solve; the 3e-11 once noted here
//    predates the two-material closed form.)
// 3. Side by side in an open tube: L1(rho - Sod) falls from N = 100 to 200
//    and stays within 1.5 times the one-material error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "tests/support/ExactRiemann.h"
#include "tests/support/IceRuns.h"

namespace tephra {
namespace {

using test::ExactRiemann;
using test::GasState;

const GasState kL{1.0, 0.0, 1.0}, kR{0.125, 0.0, 0.1};
constexpr double kX0 = 0.5;
double kK = 1e3;

enum class Layout { One, Halves, SideBySide };

std::string state_xml(double rho, double p) {
  std::ostringstream x;
  x.precision(17);
  x << "<res>[2,1,1]</res><velocity>[0,0,0]</velocity><density>" << rho << "</density><pressure>" << p
    << "</pressure><temperature>" << p / (0.4 * rho) << "</temperature>";
  return x.str();
}

std::string material_xml(const std::string& objects) {
  return R"(<material><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
   <thermal_conductivity>0</thermal_conductivity><specific_heat>1</specific_heat><gamma>1.4</gamma>)" + objects +
         "</material>";
}

std::string tube_deck(Layout layout, int n, const char* advection, bool walls, bool conserve, double t_end) {
  const std::string left_box = R"(<box label="left"><min>[-1,-1,-1]</min><max>[)" + std::to_string(kX0) + R"(,2,2]</max></box>)";
  const std::string right_box = R"(<box label="right"><min>[)" + std::to_string(kX0) + R"(,-1,-1]</min><max>[2,2,2]</max></box>)";
  std::string mats;
  const double f = layout == Layout::Halves ? 0.5 : 1.0;
  const std::string both = "<geom_object>" + left_box + state_xml(f * kL.rho, f * kL.p) + "</geom_object><geom_object>" +
                           right_box + state_xml(f * kR.rho, f * kR.p) + "</geom_object>";
  if (layout == Layout::One) mats = material_xml(both);
  if (layout == Layout::Halves) mats = material_xml(both) + material_xml(both);
  if (layout == Layout::SideBySide)
    mats = material_xml("<geom_object>" + left_box + state_xml(kL.rho, kL.p) + "</geom_object>") +
           material_xml("<geom_object>" + right_box + state_xml(kR.rho, kR.p) + "</geom_object>");
  std::ostringstream x;
  const double h = 1.0 / n;
  x << R"(<Uintah_specification><Meta><title>mix</title></Meta><SimulationComponent type="ice"/>
  <Time><maxTime>)" << t_end << R"(</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max>
  <delt_init>1e-8</delt_init></Time>
  <DataArchiver><filebase>mix.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>0.4</cfl><ICE><advection type=")" << advection << R"("/><conserveTotalEnergy>)"
    << (conserve ? "true" : "false") << R"(</conserveTotalEnergy></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>)" << mats << "</ICE>";
  if (layout != Layout::One)
    x << R"(<exchange_properties><exchange_coefficients><momentum>)" << kK << R"(</momentum><heat>)" << kK << R"(</heat></exchange_coefficients>
  </exchange_properties>)";
  x << R"(</MaterialProperties><Grid><BoundaryConditions>)";
  for (const char* side : {"x-", "x+"})
    if (walls) x << "<Face side=\"" << side << R"("><BCType id="all" label="Symmetric" var="symmetry"/></Face>)";
    else x << "<Face side=\"" << side << R"("><BCType id="all" label="Pressure" var="Neumann"><value>0</value></BCType>
      <BCType id="all" label="Velocity" var="Neumann"><value>[0,0,0]</value></BCType>
      <BCType id="all" label="Temperature" var="Neumann"><value>0</value></BCType>
      <BCType id="all" label="Density" var="Neumann"><value>0</value></BCType>
      <BCType id="all" label="SpecificVol" var="computeFromDensity"><value>0</value></BCType></Face>)";
  for (const char* side : {"y-", "y+", "z-", "z+"})
    x << "<Face side=\"" << side << R"("><BCType id="all" label="Symmetric" var="symmetry"/></Face>)";
  x << R"(</BoundaryConditions><Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,)" << h << "," << h
    << R"(]</upper><resolution>[)" << n << R"(,1,1]</resolution><extraCells>[1,1,1]</extraCells>
   <patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>)";
  return x.str();
}

test::IceRun start(Layout layout, int n, const char* adv, bool walls, bool conserve, double t_end) {
  test::IceRun r;
  r.deck = load_deck_from_string(tube_deck(layout, n, adv, walls, conserve, t_end), "mix.ups", ".");
  r.ice = make_ice_component(*r.deck);
  r.ice->initialize();
  return r;
}

// Sum over the interior cells and materials of M (c_v T + |u|^2/2), c_v = 1.
double total_energy(const IceComponent& ice) {
  const Grid& g = ice.grid();
  const double V = g.cell_volume();
  double e = 0;
  for (const IceMaterialFields& f : ice.fields())
    for (int i = 0; i < g.cells[0]; ++i)
      e += f.rho_CC[0](i, 0, 0) * V * (f.temp_CC[0](i, 0, 0) + 0.5 * f.vel_CC[0](i, 0, 0).squaredNorm());
  return e;
}

double mixture_density(const IceComponent& ice, int i) {
  double s = 0;
  for (const IceMaterialFields& f : ice.fields()) s += f.rho_CC[0](i, 0, 0);
  return s;
}

double l1_density(const IceComponent& ice, double t) {
  const ExactRiemann ex(kL, kR, 1.4);
  const Grid& g = ice.grid();
  double e = 0;
  for (int i = 0; i < g.cells[0]; ++i)
    e += std::abs(mixture_density(ice, i) - ex.sample((g.cell_center(i, 0, 0)[0] - kX0) / t).rho) * g.dx[0];
  return e;
}

// Steps a and b together with the same time steps (b's from a's stable step).
void step_together(test::IceRun& a, test::IceRun& b, double t_end) {
  while (a.time < t_end * (1 - 1e-14)) {
    const double dt = std::min(a.steps == 0 ? 1e-8 : a.ice->stable_timestep(), t_end - a.time);
    a.ice->advance(a.time, dt, ++a.steps);
    b.ice->advance(b.time, dt, ++b.steps);
    a.time += dt;
    b.time += dt;
  }
}

TEST(IceMixtureEnergy, TwoHalvesOfOneGasMatchTheOneMaterialTube) {
  set_thread_count(1);
  const double t_end = 0.2;
  for (const char* adv : {"FirstOrder", "SecondOrder"}) {
    double l1_two[2], l1_one[2], l1_diff = 0;
    for (bool conserve : {true, false}) {
      test::IceRun one = start(Layout::One, 200, adv, false, conserve, t_end);
      test::IceRun two = start(Layout::Halves, 200, adv, false, conserve, t_end);
      step_together(one, two, t_end);
      const IceComponent& a = *one.ice;
      const IceComponent& b = *two.ice;
      const Grid& g = a.grid();
      double twin = 0, diff = 0;  // the two materials against each other; the mixture against one material
      for (int i = 0; i < g.cells[0]; ++i) {
        twin = std::max({twin, std::abs(b.fields()[0].rho_CC[0](i, 0, 0) / b.fields()[1].rho_CC[0](i, 0, 0) - 1),
                         std::abs(b.fields()[0].temp_CC[0](i, 0, 0) / b.fields()[1].temp_CC[0](i, 0, 0) - 1),
                         std::abs(b.fields()[0].vel_CC[0](i, 0, 0)[0] - b.fields()[1].vel_CC[0](i, 0, 0)[0])});
        diff += std::abs(mixture_density(b, i) - a.fields()[0].rho_CC[0](i, 0, 0)) * g.dx[0];
      }
      l1_two[conserve] = l1_density(b, t_end);
      l1_one[conserve] = l1_density(a, t_end);
      if (conserve) l1_diff = diff;
      std::printf("halves %s conserveTotalEnergy=%d N=200 (%d steps): twins differ by %.3g; L1(rho_mix - rho_one) %.4g; "
                  "L1(rho - Sod) two materials %.5g, one material %.5g\n",
                  adv, conserve, one.steps, twin, diff, l1_two[conserve], l1_one[conserve]);
      EXPECT_LT(twin, 1e-12) << adv;  // identical materials stay identical (round-off)
    }
    EXPECT_LT(l1_diff, 0.25 * l1_one[1]) << adv;         // measured 0.07 (first order), 0.16 (second)
    EXPECT_LT(l1_two[1], 1.1 * l1_one[1]) << adv;        // as close to Sod as one material
    EXPECT_LT(l1_two[1], l1_two[0]) << adv;              // closer to Sod than Uintah's equations
  }
}

TEST(IceMixtureEnergy, ClosedTwoMaterialTubeConservesTotalEnergyToRoundOff) {
  set_thread_count(1);
  const double t_end = 0.4;  // the shock (speed 1.75) reflects from x = 1 at t = 0.29
  for (const char* adv : {"FirstOrder", "SecondOrder"}) {
    for (bool conserve : {true, false}) {
      test::IceRun r = start(Layout::SideBySide, 200, adv, true, conserve, t_end);
      const double e0 = total_energy(*r.ice);
      double worst_step = 0;
      while (r.time < t_end * (1 - 1e-14)) {
        const double dt = std::min(r.steps == 0 ? 1e-8 : r.ice->stable_timestep(), t_end - r.time);
        const double before = total_energy(*r.ice);
        r.ice->advance(r.time, dt, ++r.steps);
        r.time += dt;
        worst_step = std::max(worst_step, std::abs(total_energy(*r.ice) - before) / e0);
      }
      const double drift = total_energy(*r.ice) / e0 - 1.0;
      std::printf("closed two-material tube %s conserveTotalEnergy=%d: %d steps, E/E0 - 1 = %.3g, worst step %.3g\n", adv,
                  conserve, r.steps, drift, worst_step);
      if (conserve) {
        EXPECT_LT(std::abs(drift), 1e-13) << adv;
        EXPECT_LT(worst_step, 1e-13) << adv;
      } else {
        EXPECT_GT(std::abs(drift), 1e-3) << adv;
      }
    }
  }
}

// Side by side in an open tube to t = 0.2: the two-material run against the
// one-material run and Sod's exact density.
TEST(IceMixtureEnergy, SideBySideTubeConvergesToSod) {
  set_thread_count(1);
  const double t_end = 0.2;
  for (const char* adv : {"FirstOrder", "SecondOrder"}) {
    double e_two[2], e_one[2];
    for (int k = 0; k < 2; ++k) {
      const int n = 100 << k;
      test::IceRun one = start(Layout::One, n, adv, false, true, t_end);
      test::IceRun two = start(Layout::SideBySide, n, adv, false, true, t_end);
      test::run_to(one, t_end);
      test::run_to(two, t_end);
      e_one[k] = l1_density(*one.ice, t_end);
      e_two[k] = l1_density(*two.ice, t_end);
    }
    std::printf("side by side %s: L1(rho - Sod) N=100/200 two materials %.4g %.4g, one material %.4g %.4g\n", adv,
                e_two[0], e_two[1], e_one[0], e_one[1]);
    EXPECT_LT(e_two[1], e_two[0]) << adv;
    EXPECT_LT(e_two[1], 1.5 * e_one[1]) << adv;
  }
}

}  // namespace
}  // namespace tephra
