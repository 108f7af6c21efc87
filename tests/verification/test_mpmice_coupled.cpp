// The coupled MPMICE step (mpmice/, docs/mpmice.md) on two decks with known
// answers.
//
// Quiescent box (inputs/mpmice/quiescent_block.ups): a steel block
// (comp_neo_hook_plastic) at rest in air at rest, T = 300 K, p = p_ref =
// 101325 Pa, closed walls. Exact solution: nothing moves. Every term of the
// step vanishes on it only if the coupling is consistent: the solid's cell
// volume fraction from the particles plus the air's fills each cell at p_ref
// (equilibration), no pressure gradient (face velocities, delP), particle
// pressure p_p - p_ref = 0 (internal force), no exchange. Asserted for 1000
// steps: |v| < 1e-10 m/s for particles and every material's cells, pressure
// constant to 1e-10 relative.
//
// MPMICE/advect.ups (decks README A12, unchanged): steel block and air at
// (10,10,10) m/s. Exact: the block translates rigidly, x_p(t) = x_p(0) + v t;
// pressure stays 101325 Pa; total momentum constant. Exact in the discrete
// step too: the solid's face volume fluxes come from the particles' motion and
// the air crosses each face through the area the solid leaves
// (ice/IceLagrangianFlux.cpp), so sum theta = 1 holds without a pressure change.
#include <gtest/gtest.h>

#include <cmath>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/CoupledRuns.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::CoupledRun;
using test::run_to;

CoupledRun make_run(const std::string& path) { return test::make_coupled_run(path); }

// max over cells (with extra cells) of |p - p0|/p0 and of |u - u0| over all materials.
void cell_deviation(const MpmIceComponent& c, const Vec3& u0, double p0, double& dp, double& du,
                    std::size_t first_material = 0) {
  dp = du = 0;
  const Grid& g = c.ice().grid();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
      dp = std::max(dp, std::abs(c.ice().press_CC()[pi](i, j, k) / p0 - 1));
      for (std::size_t m = first_material; m < c.ice().fields().size(); ++m)
        du = std::max(du, (c.ice().fields()[m].vel_CC[pi](i, j, k) - u0).cwiseAbs().maxCoeff());
    });
}

double particle_speed_deviation(const MpmIceComponent& c, const Vec3& u0) {
  double du = 0;
  for (const MpmMaterial& m : c.mpm().materials())
    for (const Vec3& v : m.particles.v) du = std::max(du, (v - u0).cwiseAbs().maxCoeff());
  return du;
}

TEST(MpmIce, QuiescentBlockInAirStaysAtRest) {
  set_thread_count(1);
  CoupledRun r = make_run(test::source_dir() + "/inputs/mpmice/quiescent_block.ups");
  ASSERT_EQ(r.c->ice().fields().size(), 2u);  // MPM steel first, then air
  double dp = 0, du = 0;
  cell_deviation(*r.c, Vec3::Zero(), 101325.0, dp, du);
  EXPECT_LT(dp, 1e-10) << "initial equilibration pressure is not uniform";
  // The block does take part: its cell holds the full steel volume fraction.
  double theta_max = 0;
  const Grid& g = r.c->ice().grid();
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    theta_max = std::max(theta_max, r.c->ice().fields()[0].vol_frac_CC[0](i, j, k));
  });
  EXPECT_GT(theta_max, 0.1);
  run_to(r, 1.0, 1000);
  EXPECT_EQ(r.steps, 1000);
  cell_deviation(*r.c, Vec3::Zero(), 101325.0, dp, du);
  EXPECT_LT(du, 1e-10);
  EXPECT_LT(dp, 1e-10);
  EXPECT_LT(particle_speed_deviation(*r.c, Vec3::Zero()), 1e-10);
}

// advect.ups, the particles: the block translates as v t, keeps its speed and
// its mass; the total mass (particles + air) is constant (the air entering
// through the open x-, y-, z- faces equals the air leaving through x+, y+, z+:
// uniform state). Measured (5^3 cells, 20 steps to t = 0.01 s): max
// |x_p - x_p0 - v t| = 5.0e-15 m, max |v_p - v| = 9.1e-13 m/s, total mass
// change 0 (6.7e-6 m/s and 1.6e-3 m/s, 6.7e-6 before the particle volume
// fluxes); the bounds are round-off.
TEST(MpmIce, AdvectDeckTranslatesTheBlock) {
  set_thread_count(1);
  CoupledRun r = make_run(test::shared_dir() + "/decks/inputs/MPMICE/advect.ups");
  const std::set<std::string> sums = {"TotalMass"};
  auto s0 = r.c->reductions(sums);
  const Particles p0 = r.c->mpm().materials()[0].particles;
  run_to(r, 0.01, 1000);
  EXPECT_GE(r.steps, 10);
  const Vec3 u0(10, 10, 10);
  const Particles& p = r.c->mpm().materials()[0].particles;
  ASSERT_EQ(p.size(), 8u);
  double dx = 0, mass0 = 0, mass1 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    dx = std::max(dx, (p.x[i] - p0.x[i] - u0 * r.time).cwiseAbs().maxCoeff());
    mass0 += p0.mass[i];
    mass1 += p.mass[i];
  }
  EXPECT_LT(dx, 1e-12) << "block displacement error after t = " << r.time;
  EXPECT_EQ(mass1, mass0);
  EXPECT_LT(particle_speed_deviation(*r.c, u0), 1e-10);
  auto s1 = r.c->reductions(sums);
  EXPECT_NEAR(s1["TotalMass"][0], s0["TotalMass"][0], 1e-13 * s0["TotalMass"][0]);
}

// The exact answer of advect.ups (decks README A12): pressure 101325 Pa and
// the air's velocity 10 m/s in every cell to round-off, total momentum
// (particles + air) constant. Measured: max |p/101325 - 1| = 1.1e-14 over 20
// steps, momentum 7e-14 relative (3.8e-2 and 0.25 m/s with the donor-cell
// volume flux of the solid's projected theta_s, docs/mpmice.md).
TEST(MpmIce, AdvectDeckKeepsPressure) {
  set_thread_count(1);
  CoupledRun r = make_run(test::shared_dir() + "/decks/inputs/MPMICE/advect.ups");
  const std::set<std::string> sums = {"TotalMomentum"};
  auto s0 = r.c->reductions(sums);
  run_to(r, 0.01, 1000);
  double dp = 0, du = 0;
  cell_deviation(*r.c, Vec3(10, 10, 10), 101325.0, dp, du, 1);
  EXPECT_LT(dp, 1e-10);
  EXPECT_LT(du, 1e-9);
  auto s1 = r.c->reductions(sums);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(s1["TotalMomentum"][d], s0["TotalMomentum"][d], 1e-12 * s0["TotalMomentum"][d]);
}

// A closed box (quiescent_block.ups with the block thrown at 5 m/s along x):
// no face of the box lets mass through (Dirichlet u = 0: zero face velocity,
// zero donor flux) and the particles keep their mass, so the total mass
// (particles + air) is an exact discrete invariant: conserved to round-off
// over 200 steps while the block and the air exchange momentum (K = 1e10).
TEST(MpmIce, ClosedBoxConservesMassWithAMovingBlock) {
  set_thread_count(1);
  CoupledRun r;
  r.deck = load_deck(test::source_dir() + "/inputs/mpmice/quiescent_block.ups");
  DeckNode& mpm_mat = test::deck_node(r.deck->root, {"MaterialProperties", "MPM", "material", "geom_object", "velocity"});
  mpm_mat.text = "[5.0, 0.0, 0.0]";
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  const std::set<std::string> sums = {"TotalMass", "TotalMomentum"};
  auto s0 = r.c->reductions(sums);
  run_to(r, 1.0, 200);
  auto s1 = r.c->reductions(sums);
  EXPECT_NEAR(s1["TotalMass"][0], s0["TotalMass"][0], 1e-13 * s0["TotalMass"][0]);
  // The block did move (initial momentum = block mass 8900 kg/m^3 x (0.1 m)^3
  // x 5 m/s = 44.5 kg m/s, the air at rest) and shared its momentum with the air.
  EXPECT_NEAR(s0["TotalMomentum"][0], 44.5, 1e-9);
  double air_speed = 0;
  const Grid& g = r.c->ice().grid();
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    air_speed = std::max(air_speed, std::abs(r.c->ice().fields()[1].vel_CC[0](i, j, k)[0]));
  });
  EXPECT_GT(air_speed, 0.1);
}

}  // namespace
}  // namespace tephra
