// MPMICE piston: a heavy steel piston moving at u = 100 m/s drives a shock
// into air at rest (issue-6 verification; deck inputs/mpmice/piston_shock.ups,
// 1-D: 200 cells of 5 mm along x, one cell thick with symmetry planes on y/z).
//
// Exact (Rankine-Hugoniot for a piston in an ideal gas, e.g. Landau-Lifshitz
// Fluid Mechanics sec. 89 / Thompson, Compressible-Fluid Dynamics sec. 7.2):
//   c0 = sqrt(g p0/rho0),  Us = (g+1)u/4 + sqrt(((g+1)u/4)^2 + c0^2),
//   p1 = p0 + rho0 Us u   (momentum jump across the shock, the gas behind it
//   moving with the piston).
// With g = 1.4, p0 = 101325 Pa, rho0 = 1.1792946927 kg/m^3 (T = 300 K, cv =
// 716): c0 = 346.8 m/s, Us = 412.0 m/s, p1 = 149909 Pa.
//
// The piston is a steel block 0.1 m long with density 89000 kg/m^3: the net
// pressure on it (p1 ahead, the rarefaction behind) slows it by ~13 m/s^2, i.e.
// by 0.02 % of u over the 1.2 ms run, so it is a constant-speed piston to well
// inside the 2 % tolerance. Air fills the domain on both sides of it.
//
// Asserted (issue 6): the post-shock plateau pressure (mean over the middle
// 60 % of the cells between the piston face and the shock) and the shock speed
// (motion of the half-jump point between t = 0.6 ms and t = 1.2 ms) within 2 %
// of the closed form, the gas behind the shock at the piston's speed.
//
// Measured (200 cells, 324 steps): plateau p = 149823 Pa (-0.06 %) at 1.2 ms
// and 149312 Pa (-0.40 %) at 0.6 ms, shock speed 409.5 m/s (-0.60 %), gas
// behind the shock at 99.98 m/s. Before the solids' volume fluxes came from
// the particles (docs/mpmice.md "Volume fluxes") the same run gave -2.71 %,
// -2.11 % and 92.9 m/s: the donor-cell advection smeared air into the
// piston's cells, where the exchange locked it to the piston.
//
// SymmetryPlanesCloseThePiston (passes) checks what the symmetry-plane
// doubling of VT step 1 (MpmIceTransfers.cpp solid_state_to_cells) fixes: in
// a one-cell-thick domain every node lies on a y/z symmetry plane; without
// the doubling the piston's cells held theta_solid = 0.25, the air passed
// through the piston (5.4 % more air ahead of it after 1.2 ms) and the test
// above "passed" the pressure at -1.4 % for the wrong reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

struct PistonProfile {
  std::vector<double> x, p, u;  // interior cells along x (j = k = 0)
};

PistonProfile profile(const MpmIceComponent& c) {
  PistonProfile pr;
  const Grid& g = c.ice().grid();
  for (int i = 0; i < g.cells[0]; ++i) {
    const int pi = g.patch_owning_cell(IntVec3(i, 0, 0));
    pr.x.push_back(g.cell_center(i, 0, 0)[0]);
    pr.p.push_back(c.ice().press_CC()[pi](i, 0, 0));
    pr.u.push_back(c.ice().fields()[1].vel_CC[pi](i, 0, 0)[0]);  // air
  }
  return pr;
}

// Rightmost x where p falls through p_half (linear interpolation between cells).
double shock_position(const PistonProfile& pr, double p_half) {
  for (std::size_t i = pr.x.size() - 1; i > 0; --i)
    if (pr.p[i - 1] >= p_half && pr.p[i] < p_half)
      return pr.x[i - 1] + (pr.x[i] - pr.x[i - 1]) * (pr.p[i - 1] - p_half) / (pr.p[i - 1] - pr.p[i]);
  return NAN;
}

// Mean pressure and air velocity over the middle 60 % between x_a and x_b.
void plateau(const PistonProfile& pr, double x_a, double x_b, double& p, double& u) {
  const double lo = x_a + 0.2 * (x_b - x_a), hi = x_b - 0.2 * (x_b - x_a);
  double sp = 0, su = 0;
  int n = 0;
  for (std::size_t i = 0; i < pr.x.size(); ++i)
    if (pr.x[i] >= lo && pr.x[i] <= hi) sp += pr.p[i], su += pr.u[i], ++n;
  p = sp / n;
  u = su / n;
}

TEST(MpmIcePiston, ShockMatchesRankineHugoniot) {
  set_thread_count(1);
  std::unique_ptr<Deck> deck = load_deck(test::source_dir() + "/inputs/mpmice/piston_shock.ups");
  deck->root.finalize_parents();
  std::unique_ptr<MpmIceComponent> c = make_mpmice_component(*deck);
  c->initialize();

  const double g = 1.4, p0 = 101325.0, rho0 = 1.1792946927374306, u = 100.0;
  const double c0 = std::sqrt(g * p0 / rho0);
  const double a = (g + 1) * u / 4;
  const double Us = a + std::sqrt(a * a + c0 * c0);
  const double p1 = p0 + rho0 * Us * u;
  const double x_face0 = 0.3;  // piston's front face at t = 0

  const double delt_init = 1e-6, mult = 0.8;
  double time = 0;
  int steps = 0;
  auto run_to = [&](double end) {
    while (time < end * (1 - 1e-14) && steps < 5000) {
      double dt = steps == 0 ? delt_init : mult * c->stable_timestep();
      dt = std::min(dt, end - time);
      ++steps;
      c->advance(time, dt, steps);
      time += dt;
    }
  };

  double xs[2], pm[2], um[2];
  const double t[2] = {0.6e-3, 1.2e-3};
  for (int n = 0; n < 2; ++n) {
    run_to(t[n]);
    const PistonProfile pr = profile(*c);
    const double x_face = x_face0 + u * t[n];
    // The plateau first from the exact shock position, then the half-jump
    // point from the measured plateau.
    plateau(pr, x_face, x_face0 + Us * t[n], pm[n], um[n]);
    xs[n] = shock_position(pr, 0.5 * (p0 + pm[n]));
    plateau(pr, x_face, xs[n], pm[n], um[n]);
    std::printf("t = %.3e s (%d steps): plateau p = %.1f Pa (exact %.1f, %+.2f %%), air u = %.2f m/s, "
                "shock at x = %.4f m (exact %.4f)\n",
                t[n], steps, pm[n], p1, 100 * (pm[n] / p1 - 1), um[n], xs[n], x_face0 + Us * t[n]);
  }
  const double Us_measured = (xs[1] - xs[0]) / (t[1] - t[0]);
  std::printf("shock speed %.2f m/s (exact %.2f, %+.2f %%)\n", Us_measured, Us, 100 * (Us_measured / Us - 1));

  EXPECT_NEAR(pm[1], p1, 0.02 * p1) << "post-shock pressure";
  EXPECT_NEAR(Us_measured, Us, 0.02 * Us) << "shock speed";
  EXPECT_NEAR(pm[0], p1, 0.02 * p1) << "post-shock pressure at the first time";
  // The gas behind the shock moves with the piston.
  EXPECT_NEAR(um[1], u, 0.02 * u);
  // The piston did keep its speed (heavy piston, see above).
  for (const Vec3& v : c->mpm().materials()[0].particles.v) EXPECT_NEAR(v[0], u, 0.002 * u);
}

// VT step 1 with symmetry planes: at t = 0 the cells inside the piston hold
// the full solid volume (8 particles filling each cell, solid at p_ref so
// rho_micro = rho0: theta_solid = 1 exactly up to round-off), and the piston
// is impermeable: the air mass ahead of the piston's mid-plane (x > 0.25 + u
// t) stays the initial rho0 x 0.7 m per unit area. Measured: 5.5e-6 relative
// after 1.2 ms (1.2e-4 with donor-cell fluxes for the solid; 5.4e-2 without
// the doubling); bound 10x the measured figure.
TEST(MpmIcePiston, SymmetryPlanesCloseThePiston) {
  set_thread_count(1);
  std::unique_ptr<Deck> deck = load_deck(test::source_dir() + "/inputs/mpmice/piston_shock.ups");
  deck->root.finalize_parents();
  std::unique_ptr<MpmIceComponent> c = make_mpmice_component(*deck);
  c->initialize();
  const Grid& g = c->ice().grid();
  const double rho0 = 1.1792946927374306, u = 100.0;
  for (int i = 41; i < 59; ++i)  // cells wholly inside the piston [0.2, 0.3]
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {  // extra cells are the mirror images
        const int pi = g.patch_owning_cell(IntVec3(i, 0, 0));
        EXPECT_NEAR(c->ice().fields()[0].vol_frac_CC[pi](i, j, k), 1.0, 1e-12) << i << " " << j << " " << k;
      }
  double time = 0;
  int steps = 0;
  while (time < 1.2e-3 * (1 - 1e-14) && steps < 5000) {
    double dt = steps == 0 ? 1e-6 : 0.8 * c->stable_timestep();
    dt = std::min(dt, 1.2e-3 - time);
    c->advance(time, dt, ++steps);
    time += dt;
  }
  double air_ahead = 0;
  for (int i = 0; i < g.cells[0]; ++i)
    if (g.cell_center(i, 0, 0)[0] > 0.25 + u * time)
      air_ahead += c->ice().fields()[1].rho_CC[g.patch_owning_cell(IntVec3(i, 0, 0))](i, 0, 0) * g.dx[0];
  std::printf("air ahead of the piston's mid-plane: %.6e kg/m^2 (initial %.6e, %+.2e relative)\n", air_ahead,
              rho0 * 0.7, air_ahead / (rho0 * 0.7) - 1);
  EXPECT_NEAR(air_ahead, rho0 * 0.7, 5e-5 * rho0 * 0.7);
}

}  // namespace
}  // namespace tephra
