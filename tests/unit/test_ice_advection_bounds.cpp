// The donor outflow bounds of second-order advection (ice/AdvectionBounds.h).
//
// 1. A trace next to a steep rise (the BurnRate.ups mechanism in pure
//    advection): a periodic 2-D box, u = (1, 1) with phi = 0.45 per face
//    (sum of the outgoing phi 0.9 < 1, the CFL bound of check_outflux), mass
//    1e-8 / 1e-12 in a checkerboard (a trace with its own steep variation)
//    around a block of mass 1 downstream. A trace cell with qmin ~ 0 behind
//    and the block ahead on both axes gets the limited differences
//    alpha g_d = (q - qmin) (Barth-Jespersen with gsum = (1 + 1)/4), slab
//    values q + q (1 - phi)/2 = 1.275 q on both outgoing faces and an outflow
//    of 2 * 0.45 * 1.275 q = 1.15 q: more than it holds (the two slabs'
//    shared corner is counted twice). The temperature psi (300 K in the
//    block, 300..3000 K in the trace) rides on the mass fluxes.
//    Without the bounds the mass goes negative (asserted: the test sees the
//    mechanism). With them, over 200 steps:
//      - every cell keeps M > 0 (item 1: M_new >= (q - F1)/2 > 0 before
//        inflows, F1 = 0.9 q here);
//      - psi stays in [300, 3000], the initial range (item 2: the new psi is
//        a mean of values within the neighbours' range, a maximum principle);
//      - the total mass is conserved to round-off (one flux per face).
// 2. A limited donor sends exactly A_D = (q_D + F1_D)/2 (the bound's identity),
//    with face weights w (the MPMICE chi L) included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/HaloExchange.h"
#include "core/grid/Loop.h"
#include "ice/AdvectionBounds.h"
#include "ice/IceAdvection.h"

namespace tephra {
namespace {

Grid periodic_square(int n) {
  std::ostringstream x;
  x << "<Uintah_specification><Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1,1," << 1.0 / n
    << "]</upper><resolution>[" << n << "," << n << ",1]</resolution><extraCells>[0,0,0]</extraCells><patches>[2,1,1]"
    << "</patches></Box><periodic>[1,1,1]</periodic></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(x.str(), "square.ups", ".");
  return make_grid(deck->root.require_child("Grid"));
}

// A periodic line of n cells along x in [0, 1], one cell across (of width 1/n).
Grid periodic_line(int n) {
  std::ostringstream x;
  x << "<Uintah_specification><Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1," << 1.0 / n << ","
    << 1.0 / n << "]</upper><resolution>[" << n << ",1,1]</resolution><extraCells>[0,0,0]</extraCells>"
    << "<patches>[1,1,1]</patches></Box><periodic>[1,1,1]</periodic></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(x.str(), "line.ups", ".");
  return make_grid(deck->root.require_child("Grid"));
}

struct TraceRun {
  double min_mass = 1e300, min_psi = 1e300, max_psi = -1e300, mass_drift = 0;
  int steps = 0;
};

TraceRun run_trace(bool bounded, int nsteps) {
  set_thread_count(1);
  const int n = 16;
  const Grid g = periodic_square(n);
  LocalHaloExchange halo(g);
  CellScalars mass(g, 2), psi(g, 2), dm(g, 2), dq(g, 2), scratch(g, 2);
  FaceScalars u(g, 0), mflux(g, 0), pflux(g, 0);
  const double dt = 0.45 * g.dx[0];  // phi = 0.45 on the x and y faces
  u.x.fill(1.0);
  u.y.fill(1.0);
  u.z.fill(0.0);
  double total0 = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const bool block = i >= 8 && i < 12 && j >= 8 && j < 12;
      mass[pi](i, j, k) = block ? 1.0 : ((i + j) % 2 == 0 ? 1e-8 : 1e-12);
      psi[pi](i, j, k) = block ? 300.0 : 300.0 + 2700.0 * ((i * 7 + j * 3) % 5) / 4.0;
      total0 += mass[pi](i, j, k);
    });
  TraceRun r;
  for (int s = 0; s < nsteps; ++s) {
    halo.exchange(mass);
    halo.exchange(psi);
    density_fluxes(g, AdvectionOrder::Second, mass, u, dt, mflux);
    if (bounded) {
      outflow_limits(g, mass, u, nullptr, dt, mflux, scratch);
      halo.exchange(scratch);
      limit_outflow(g, mass, u, nullptr, dt, scratch, mflux);
    }
    specific_fluxes(g, AdvectionOrder::Second, psi, u, mflux, dt, pflux);
    if (bounded) {
      flag_out_of_range_donors(g, psi, mass, mflux, pflux, scratch);
      halo.exchange(scratch);
      donor_value_fluxes(g, psi, mflux, scratch, pflux);
    }
    flux_divergence(g, mflux, dm);
    flux_divergence(g, pflux, dq);
    double total = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        const double m_new = mass[pi](i, j, k) + dm[pi](i, j, k);
        psi[pi](i, j, k) = (mass[pi](i, j, k) * psi[pi](i, j, k) + dq[pi](i, j, k)) / m_new;
        mass[pi](i, j, k) = m_new;
        total += m_new;
        r.min_mass = std::min(r.min_mass, m_new);
        r.min_psi = std::min(r.min_psi, psi[pi](i, j, k));
        r.max_psi = std::max(r.max_psi, psi[pi](i, j, k));
      });
    r.mass_drift = std::max(r.mass_drift, std::abs(total - total0) / total0);
    r.steps = s + 1;
    if (!(r.min_mass > 0)) break;  // the unbounded scheme: stop at the first overdraft
  }
  return r;
}

TEST(IceAdvectionBounds, UnboundedSecondOrderOverdrawsATraceNextToASteepRise) {
  const TraceRun r = run_trace(false, 200);
  std::printf("unbounded: min mass %.3e after %d steps\n", r.min_mass, r.steps);
  EXPECT_LT(r.min_mass, 0.0);  // the mechanism the bound removes
}

TEST(IceAdvectionBounds, BoundedTraceKeepsPositiveMassAndTemperatureRange) {
  const TraceRun r = run_trace(true, 200);
  std::printf("bounded: %d steps, min mass %.3e, psi in [%.6f, %.6f], mass drift %.2e\n", r.steps, r.min_mass,
              r.min_psi, r.max_psi, r.mass_drift);
  EXPECT_EQ(r.steps, 200);
  EXPECT_GT(r.min_mass, 0.0);
  // Maximum principle: the initial range [300, 3000] K, to round-off.
  EXPECT_GE(r.min_psi, 300.0 * (1 - 1e-12));
  EXPECT_LE(r.max_psi, 3000.0 * (1 + 1e-12));
  EXPECT_LT(r.mass_drift, 1e-14);  // telescoping face fluxes: round-off (16^2 cells, sum ~ 16)
}

// 1-D line x-periodic: q = (1e-12, 1e-8, 1) repeated, u > 0, phi = 0.2, the
// trace cell's face weight w = 2.5 (phi w = 0.5, the MPMICE limit). First
// order it sends F1 = 0.5e-8; second order 0.5 (q + dq (1 - phi)/2) ~ 0.9e-8 >
// A = (1e-8 + 0.5e-8)/2 = 0.75e-8. After limit_outflow its outflow is A.
TEST(IceAdvectionBounds, LimitedDonorSendsHalfOfContentPlusFirstOrderOutflow) {
  set_thread_count(1);
  const Grid g = periodic_line(9);
  LocalHaloExchange halo(g);
  CellScalars q(g, 2), limit(g, 2);
  FaceScalars u(g, 0), w(g, 0), flux(g, 0);
  const double dt = 0.2 * g.dx[0];
  u.x.fill(1.0);
  u.y.fill(0.0);
  u.z.fill(0.0);
  w.x.fill(1.0);
  const double pattern[3] = {1e-12, 1e-8, 1.0};
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) { q[0](i, j, k) = pattern[i % 3]; });
  for (int i = 1; i < 9; i += 3) w.x[0](i + 1, 0, 0) = 2.5;  // the trace cell i's outgoing (high) face
  halo.exchange(q);
  density_fluxes(g, AdvectionOrder::Second, q, u, dt, flux);
  for (int i = 1; i < 9; i += 3) flux.x[0](i + 1, 0, 0) *= 2.5;
  const double before = flux.x[0](2, 0, 0);
  ASSERT_TRUE(outflow_limits(g, q, u, &w, dt, flux, limit));
  halo.exchange(limit);
  limit_outflow(g, q, u, &w, dt, limit, flux);
  const double F1 = 0.5e-8, A = 0.5 * (1e-8 + F1);
  std::printf("trace donor: second order %.6e, first order %.6e, bound %.6e, limited %.6e (s = %.4f)\n", before,
              F1, A, flux.x[0](2, 0, 0), limit[0](1, 0, 0));
  EXPECT_GT(before, A);
  EXPECT_NEAR(flux.x[0](2, 0, 0), A, 1e-15 * A);
  EXPECT_EQ(limit[0](2, 0, 0), 1.0);  // the big cell (q = 1) sends 0.2 + O(phi): not limited
}

// 3. The skip of bound_outflow (kOutflowBoundInactive, AdvectionBounds.h):
//    with S_D = sum_out phi <= 0.3 everywhere no donor can be limited, since
//    F_D <= 2 q_D S_D <= A_D = q_D (1 + S_D)/2 for S_D <= 1/3. Checked on the
//    steepest fields the limiter admits: masses spread over 12 decades at
//    random (log-uniform, so alpha g reaches q - q_min), random face
//    velocities of both signs scaled so that check_outflux's largest S_D is
//    0.3; 20 fields. Also: check_outflux returns that largest S_D (closed
//    form for u = (1, 1): 2 phi), and at S_D = 0.9 the same kind of field
//    does limit cells (the skip is not vacuous).
TEST(IceAdvectionBounds, NoDonorIsLimitedBelowTheInactiveOutflow) {
  set_thread_count(1);
  const Grid g = periodic_square(16);
  LocalHaloExchange halo(g);
  CellScalars mass(g, 2), limit(g, 2);
  FaceScalars u(g, 0), flux(g, 0);
  // check_outflux on u = (1, 1): every cell sends phi through its x-high and y-high faces.
  u.x.fill(1.0);
  u.y.fill(1.0);
  u.z.fill(0.0);
  const double phi = 0.15, dt0 = phi * g.dx[0];
  EXPECT_NEAR(check_outflux(g, u, dt0, 0), 2 * phi, 1e-15);  // S_D = 2 phi (closed form)
  unsigned state = 12345u;
  auto uniform = [&]() {  // LCG (Numerical Recipes constants), [0, 1)
    state = 1664525u * state + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  int limited_at_09 = 0;
  for (int trial = 0; trial < 20; ++trial) {
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        mass[pi](i, j, k) = std::pow(10.0, -12.0 * uniform());
      });
    }
    halo.exchange(mass);
    // u in [-1, 1), a hash of the periodic face index, so that the face
    // arrays of the two patches agree on their shared and periodic faces.
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for (int d = 0; d < 2; ++d)
        for_each_cell_serial(u.at(d, pi).with_ghosts(), [&](int i, int j, int k) {
          const int ii = ((i % 16) + 16) % 16, jj = ((j % 16) + 16) % 16;
          const unsigned h = 2654435761u * unsigned(ii + 16 * jj + 256 * d + 1000 * trial + 7);
          u.at(d, pi)(i, j, k) = 2.0 * double(h >> 8) / double(1u << 24) - 1.0;
        });
    const double dt_ref = 0.1 * g.dx[0];            // |u| < 1, at most 4 outgoing faces: S_D < 0.4
    const double S1 = check_outflux(g, u, dt_ref, 0);  // largest S_D at dt_ref (S_D is linear in dt)
    for (double target : {kOutflowBoundInactive, 0.9}) {
      const double dt = dt_ref * target / S1;
      ASSERT_NEAR(check_outflux(g, u, dt, 0), target, 1e-12);
      density_fluxes(g, AdvectionOrder::Second, mass, u, dt, flux);
      const bool any = outflow_limits(g, mass, u, nullptr, dt, flux, limit);
      if (target == kOutflowBoundInactive) {
        EXPECT_FALSE(any) << "trial " << trial;
      } else if (any) {
        ++limited_at_09;
      }
    }
  }
  std::printf("fields with limited donors at S = 0.9: %d of 20\n", limited_at_09);
  EXPECT_GT(limited_at_09, 0);
}

// Item 2's round-off allowance is relative to the terms of each comparison,
// not to the neighbourhood's largest |psi|. The numbers of the cookoff run's
// stop at 1.097 ms (docs/mpmice.md "Session 27: the contents' range check"):
// a trace-gas donor D (M = 2.1249e-21, v = 2.1891e-3 m^3/kg) beside a
// near-vacuum trace (v = 8.4195e7) sends F = 1.168e-21 of mass through one
// face; its remaining content RQ = M v - F_Q must lie in [lo, hi] RM with
// RM = M - F = 0.957e-21 > 0 and lo = 3.06e-5, so any RQ < 0 is outside.
// The former allowance 1e-12 max|psi| M = 1.8e-25 let RQ = -1.2e-25 pass
// (the cookoff donor: v went to -1.2e-4); the new one, 1e-12 times the
// compared terms (~1e-35 here), flags it. Mutation (the former allowance,
// temporary): the third case fails.
TEST(IceAdvectionBounds, RangeCheckAllowanceIsRelativeToTheComparedTerms) {
  set_thread_count(1);
  const Grid g = periodic_line(5);
  LocalHaloExchange halo(g);
  CellScalars mass(g, 2), psi(g, 2), flag(g, 2);
  FaceScalars mflux(g, 0), pflux(g, 0);
  const double psi_of[5] = {3.06e-5, 8.4195e7, 2.1891e-3, 3.06e-5, 3.06e-5};
  auto run = [&](double content_flux) {
    for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
      psi[0](i, j, k) = psi_of[i];
      mass[0](i, j, k) = i == 2 ? 2.1249e-21 : 4.8e-19;
    });
    halo.exchange(psi);
    halo.exchange(mass);
    mflux.x.fill(0.0);
    pflux.x.fill(0.0);
    mflux.y.fill(0.0);
    pflux.y.fill(0.0);
    mflux.z.fill(0.0);
    pflux.z.fill(0.0);
    // The face between cells 1 and 2 (face index 2), flow towards cell 1: donor 2.
    mflux.x[0](2, 0, 0) = -1.168e-21;
    pflux.x[0](2, 0, 0) = -content_flux;
    flag_out_of_range_donors(g, psi, mass, mflux, pflux, flag);
    return flag[0](2, 0, 0);
  };
  // The slab value 4.34e-3: RQ = 2.1249e-21 x 2.1891e-3 - 5.070e-24 = -4.2e-25 < 0.
  EXPECT_EQ(run(5.070e-24), 1.0);
  // Within the range: the donor's own value (first order), RQ = v_D RM exactly: not flagged.
  EXPECT_EQ(run(1.168e-21 * 2.1891e-3), 0.0);
  // The cookoff's margin: RQ = -1.2e-25 (its r-face weight 0.941 on 5.070e-24), the former allowance 1.8e-25.
  EXPECT_EQ(run(2.1249e-21 * 2.1891e-3 + 1.2e-25), 1.0);
}

}  // namespace
}  // namespace tephra
