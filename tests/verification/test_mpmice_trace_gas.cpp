// A trace of product gas inside a solid under a compression wave (issue 6,
// C10 "hot sliver"; docs/mpmice.md "BurnRate.ups (C10), session 18").
//
// Scene: inputs/mpmice/trace_gas_ramp.ups = MPMICE/BurnRate.ups cut to 40
// cells of 1 mm, PBX 9501 (visco_scram) from x = 8 mm, no burn model. The
// product gas on the left (JWL, 1.389 kg/m^3, 3000 K: 1.116 MPa) drives a
// compression wave into the PBX; under the PBX the product is a trace
// (theta ~ 1e-11, 300 K, p = 1 atm). Closed box (symmetry planes).
//
// Bound. With heat exchange H = 1e5 W/(m^3 K) the trace exchanges almost no
// heat over 20 us (beta = dt theta_s H/(rho_g cv) ~ 1e5/(1.3 x 595) per
// second: 0.3 % of the difference in 20 us), so a trace gas that stays in
// its cell is compressed adiabatically. At these densities the JWL product
// is an ideal gas, p = omega rho cv T (the exponential terms vanish), gamma =
// 1 + omega, and an adiabatic compression from (p0, T0) gives
//   T = T0 (p/p0)^(omega/(1 + omega)),   omega = 0.45.
// So the product in the cells wholly inside the PBX (x >= 12 mm, 4 cells from
// its surface, theta_s > 0.99) stays below T0 (p_max/p0)^(0.45/1.45) with T0 =
// 300 K, p0 = the initial pressure under the PBX and p_max the largest cell
// pressure of the run so far (a gas cannot be compressed beyond the largest
// pressure it meets). Checked at every microsecond.
//
// Before the fix (ice/FaceFluidShare.h) the trace rode the compression ramp
// with the solids' face-fraction weights (chi up to 3000) and took the
// compression work of every cell it passed. Measured by this test with
// face_fluid_share returning 1 - theta_s,face (the old rule): 660 K at 6 us,
// 960.5 K at 9 us (bound 662.6 K), 2571 K at 20 us (bound 752.9 K): fails.
// With the bound: 685.6 K at 20 us (bound 749.7 K), worst ratio 0.922 (631 K
// of 685 K at 17 us, as the wave reflected from the far wall arrives).
// Also asserted: the product's total mass (no source, closed box) constant to
// round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "ice/FaceFluidShare.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

// The face share itself: a fluid-rich neighbour leaves 1 - theta_s,face as
// it was (MPMICE/advect.ups' exact complement); two trace cells bound it by
// the larger trace.
TEST(FaceFluidShare, BoundedByTheLargerFluidFractionOfTheTwoCells) {
  EXPECT_EQ(face_fluid_share(0.3, 0.5, 1.0), 0.7);        // solid surface: unchanged
  EXPECT_EQ(face_fluid_share(0.3, 1.0, 0.2), 0.7);
  EXPECT_EQ(face_fluid_share(1.0 - 5e-3, 3e-6, 4e-6), 4e-6);  // BurnRate's ramp: 5e-3 -> 4e-6
  EXPECT_EQ(face_fluid_share(1.0, 3e-6, 4e-6), 0.0);      // a face the solid covers stays closed
}

TEST(MpmIceTraceGas, TraceProductInACompressedSolidStaysBelowTheAdiabat) {
  set_thread_count(1);
  std::unique_ptr<Deck> deck = load_deck(test::source_dir() + "/inputs/mpmice/trace_gas_ramp.ups");
  deck->root.finalize_parents();
  std::unique_ptr<MpmIceComponent> c = make_mpmice_component(*deck);
  c->initialize();
  const Grid& g = c->ice().grid();
  const double V = g.cell_volume(), omega = 0.45, T0 = 300.0;
  auto cell = [&](int i) { return IntVec3(i, 0, 0); };
  auto patch = [&](int i) { return g.patch_owning_cell(cell(i)); };
  auto product_mass = [&]() {
    double m = 0;
    for (int i = 0; i < g.cells[0]; ++i) m += c->ice().fields()[1].rho_CC[patch(i)](cell(i)) * V;
    return m;
  };
  const double p0 = c->ice().press_CC()[patch(39)](cell(39));  // under the PBX at t = 0
  const double m0 = product_mass();
  double p_max = 0, worst = 0, worst_T = 0, worst_bound = 0;
  // The deck's time rule (core/sim/TimeLoop.cpp): delt_init 1e-9, then 0.2 x
  // the stable step, at most 1.5 x the previous step.
  double time = 0, dt_prev = 0;
  int steps = 0;
  for (int us = 1; us <= 20; ++us) {
    const double end = us * 1e-6;
    while (time < end * (1 - 1e-12) && steps < 5000) {
      double dt = steps == 0 ? 1e-9 : std::min(0.2 * c->stable_timestep(), 1.5 * dt_prev);
      dt = std::min(dt, end - time);
      c->advance(time, dt, ++steps);
      time += dt;
      dt_prev = dt;
      for (int i = 0; i < g.cells[0]; ++i) p_max = std::max(p_max, c->ice().press_CC()[patch(i)](cell(i)));
    }
    const double bound = T0 * std::pow(p_max / p0, omega / (1 + omega));
    double hottest = 0;
    for (int i = 12; i < g.cells[0]; ++i) {
      if (c->ice().fields()[0].vol_frac_CC[patch(i)](cell(i)) < 0.99) continue;
      hottest = std::max(hottest, c->ice().fields()[1].temp_CC[patch(i)](cell(i)));
    }
    std::printf("t = %5.2f us (%4d steps): hottest product inside the PBX %.1f K, adiabatic bound %.1f K "
                "(p_max %.4e Pa)\n", time * 1e6, steps, hottest, bound, p_max);
    EXPECT_LE(hottest, bound) << "at t = " << time;
    if (hottest / bound > worst) worst = hottest / bound, worst_T = hottest, worst_bound = bound;
  }
  std::printf("worst hottest/bound %.4f (%.1f K of %.1f K); product mass %.6e kg, change %.2e relative\n", worst,
              worst_T, worst_bound, product_mass(), product_mass() / m0 - 1);
  EXPECT_NEAR(product_mass(), m0, 1e-12 * m0);
}

}  // namespace
}  // namespace tephra
