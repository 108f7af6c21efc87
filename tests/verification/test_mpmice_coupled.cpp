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
// pressure stays 101325 Pa; with no walls acting (Neumann faces, uniform
// velocity) total MPM + ICE momentum and total mass are conserved.
#include <gtest/gtest.h>

#include <cmath>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

struct Run {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
  double time = 0;
  int steps = 0;
};

Run make_run(const std::string& path) {
  Run r;
  r.deck = load_deck(path);
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  return r;
}

// The deck's time rule: delt_init first, then timestep_multiplier * stable
// step, cut to land on maxTime.
void run_to(Run& r, double end_time, int max_steps) {
  const DeckNode& time = r.deck->root.require_child("Time");
  const double delt_init = time.get_double("delt_init", 0.0);
  const double mult = time.get_double("timestep_multiplier", 1.0);
  const double delt_max = time.get_double("delt_max", 1e300);
  while (r.time < end_time * (1 - 1e-14) && r.steps < max_steps) {
    double dt = (r.steps == 0 && delt_init > 0) ? delt_init : mult * r.c->stable_timestep();
    dt = std::min({dt, delt_max, end_time - r.time});
    ++r.steps;
    r.c->advance(r.time, dt, r.steps);
    r.time += dt;
  }
}

// max over cells (with extra cells) of |p - p0|/p0 and of |u - u0| over all materials.
void cell_deviation(const MpmIceComponent& c, const Vec3& u0, double p0, double& dp, double& du) {
  dp = du = 0;
  const Grid& g = c.ice().grid();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
      dp = std::max(dp, std::abs(c.ice().press_CC()[pi](i, j, k) / p0 - 1));
      for (const IceMaterialFields& f : c.ice().fields())
        du = std::max(du, (f.vel_CC[pi](i, j, k) - u0).cwiseAbs().maxCoeff());
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
  Run r = make_run(test::source_dir() + "/inputs/mpmice/quiescent_block.ups");
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

TEST(MpmIce, AdvectDeckTranslatesTheBlock) {
  set_thread_count(1);
  Run r = make_run(test::shared_dir() + "/decks/inputs/MPMICE/advect.ups");
  const std::set<std::string> sums = {"TotalMass", "TotalMomentum", "KineticEnergy"};
  auto s0 = r.c->reductions(sums);
  const std::vector<Vec3> x0 = r.c->mpm().materials()[0].particles.x;
  run_to(r, 0.01, 1000);
  EXPECT_GE(r.steps, 10);
  auto s1 = r.c->reductions(sums);
  const Vec3 u0(10, 10, 10);
  // Rigid translation: x_p = x_p0 + v t.
  double dx = 0;
  const auto& x = r.c->mpm().materials()[0].particles.x;
  for (std::size_t i = 0; i < x.size(); ++i) dx = std::max(dx, (x[i] - x0[i] - u0 * r.time).cwiseAbs().maxCoeff());
  EXPECT_LT(dx, 1e-12) << "block displacement error after t = " << r.time;
  double dp = 0, du = 0;
  cell_deviation(*r.c, u0, 101325.0, dp, du);
  EXPECT_LT(dp, 1e-10);
  EXPECT_LT(du, 1e-9);
  EXPECT_LT(particle_speed_deviation(*r.c, u0), 1e-9);
  EXPECT_NEAR(s1["TotalMass"][0], s0["TotalMass"][0], 1e-13 * s0["TotalMass"][0]);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(s1["TotalMomentum"][d], s0["TotalMomentum"][d], 1e-12 * std::abs(s0["TotalMomentum"][d]));
  EXPECT_NEAR(s1["KineticEnergy"][0], s0["KineticEnergy"][0], 1e-12 * s0["KineticEnergy"][0]);
}

}  // namespace
}  // namespace tephra
