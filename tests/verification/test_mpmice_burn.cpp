// Simple_Burn in the coupled MPMICE step (mpmice/SolidBurn.h,
// mpmice/ParticleBurn.cpp) on MPMICE/massX.ups (decks README A13): a 1 m^3
// cube of solid (comp_neo_hook, rho 1.179 kg/m^3, 64 particles, cells of
// 0.5 m) in gas of the same density at 300 K; Simple_Burn with ThresholdTemp
// 299 K < 300 K, so the cube burns from step 1.
//
// Oracles:
//  * Mass: particles lose exactly what the product gains (the per-cell rule
//    of ParticleBurn.cpp), so TotalMass = sum p.mass + sum_fluid rho_CC V is
//    constant to round-off while the solid burns - in a closed box (the
//    deck's faces made walls: u = 0 Dirichlet, pressure Neumann). With the
//    deck's open faces (pressure Dirichlet) the explicit pressure step
//    spreads one cell per step, so from step 3 a pressure change of ~1e-7
//    relative reaches the faces and gas enters (measured 1.9e-7 kg at step 4,
//    1e-6 kg at step 5 of 147 kg): the unchanged deck is checked for the
//    particle loss = product gain balance instead.
//  * Rate: with BurnCoeff 1e-3 kg/(m^2 s) no cell hits the mass cap, and the
//    Simple_Burn law gives dm = dt A BurnCoeff (p/refPressure)^0.778 per
//    surface cell. The surface cells are the 8 cells the cube fills (the
//    corner-mass ratio (max - min)/max is 1 - not < 1 - in the cells around
//    it, whose outer corner nodes hold no mass); each is a corner cell of
//    the cube, its mass gradient is along a diagonal by the cube's symmetry,
//    so n = (1,1,1)/sqrt 3 and A = dx^3/(dx sqrt 3) x (sqrt 3)^(1/3)
//    (SimpleBurn.h). Expected: 8 dt A BurnCoeff p^0.778 with p the
//    equilibration pressure of those cells.
//  * Momentum of the transfer: block and gas moving at (1, 0.5, 0) m/s; the
//    product's momentum source equals sum_p (m_p^n - m_p^{n+1}) v_p^n, the
//    momentum of the mass the particles lost, to round-off.
#include <gtest/gtest.h>

#include <cmath>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

struct BurnRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
  const SolidBurnModel* burn = nullptr;
  double time = 0;
  int steps = 0;
};

BurnRun make_run(const char* burn_coeff = nullptr, const char* velocity = nullptr, bool closed = false) {
  BurnRun r;
  r.deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/massX.ups");
  if (closed)
    for (DeckNode& face : test::deck_node(r.deck->root, {"Grid", "BoundaryConditions"}).children)
      for (DeckNode& bc : face.children) {
        std::string label;
        for (auto& [k, v] : bc.attributes)
          if (k == "label") label = v;
        for (auto& [k, v] : bc.attributes)
          if (k == "var" && label == "Pressure") v = "Neumann";
          else if (k == "var" && label == "Velocity") v = "Dirichlet";
        if (label == "Pressure") bc.children.at(0).text = "0.0";
      }
  if (burn_coeff) test::deck_node(r.deck->root, {"Models", "Model", "BurnCoeff"}).text = burn_coeff;
  if (velocity) {
    test::deck_node(r.deck->root, {"MaterialProperties", "MPM", "material", "geom_object", "velocity"}).text = velocity;
    test::deck_node(r.deck->root, {"MaterialProperties", "ICE", "material", "geom_object", "velocity"}).text = velocity;
  }
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  for (const IceModelP& m : r.c->ice().models())
    if (auto* b = dynamic_cast<const SolidBurnModel*>(m.get())) r.burn = b;
  return r;
}

double particle_mass(const MpmIceComponent& c) {
  double m = 0;
  for (double x : c.mpm().materials()[0].particles.mass) m += x;
  return m;
}

TEST(MpmIceBurn, MassXInAClosedBoxConservesTotalMassWhileTheSolidBurns) {
  set_thread_count(1);
  BurnRun r = make_run(nullptr, nullptr, true);
  ASSERT_NE(r.burn, nullptr);
  const std::set<std::string> sums = {"TotalMass"};
  const double M0 = r.c->reductions(sums)["TotalMass"][0];
  const double mp0 = particle_mass(*r.c);
  double burned = 0;
  for (int step = 1; step <= 5; ++step) {
    const double dt = 1e-4;  // the deck's delt_init and delt_max
    r.c->advance(r.time, dt, step);
    r.time += dt;
    burned += r.burn->mass_burned_last_step();
    const double M = r.c->reductions(sums)["TotalMass"][0];
    // Round-off: the sums run over 1000 cells of ~0.15 kg (measured 1.1e-14 relative).
    EXPECT_NEAR(M, M0, 1e-13 * M0) << "step " << step;
  }
  const double mp = particle_mass(*r.c);
  // Measured: the solid went from 1.1793 kg to 0.108 kg in 5 steps.
  EXPECT_GT(burned, 0.5 * mp0);
  EXPECT_NEAR(mp0 - mp, burned, 1e-14 * mp0) << "particles lost " << mp0 - mp << " kg, the product got " << burned;
}

// The unchanged deck (open faces) to its end, t = 5e-4 s: what the particles
// lose is what the burn model reports and the product gets.
TEST(MpmIceBurn, MassXParticlesLoseWhatTheProductGains) {
  set_thread_count(1);
  BurnRun r = make_run();
  ASSERT_NE(r.burn, nullptr);
  const double mp0 = particle_mass(*r.c);
  double burned = 0;
  for (int step = 1; step <= 5; ++step) {
    r.c->advance(r.time, 1e-4, step);
    r.time += 1e-4;
    burned += r.burn->mass_burned_last_step();
  }
  const double mp = particle_mass(*r.c);
  EXPECT_GT(burned, 0.5 * mp0);
  EXPECT_NEAR(mp0 - mp, burned, 1e-14 * mp0);
}

TEST(MpmIceBurn, BurnRateIsTheSimpleBurnLaw) {
  set_thread_count(1);
  BurnRun r = make_run("1e-3");
  ASSERT_NE(r.burn, nullptr);
  const double mp0 = particle_mass(*r.c);
  const double dt = 1e-4;
  r.c->advance(0.0, dt, 1);
  const Grid& g = r.c->ice().grid();
  const double dx = g.dx[0];
  int cells = 0;
  double expected = 0;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    const bool cube = i >= 4 && i <= 5 && j >= 4 && j <= 5 && k >= 4 && k <= 5;
    if (!cube) return;
    ++cells;
    const double p = r.c->ice().press_equil_CC()[0](i, j, k);
    const double A = dx * dx / std::sqrt(3.0) * std::cbrt(std::sqrt(3.0));
    expected += dt * A * 1e-3 * std::pow(p / 1.0, 0.778);
  });
  ASSERT_EQ(cells, 8);
  EXPECT_NEAR(r.burn->mass_burned_last_step(), expected, 1e-12 * expected);
  EXPECT_NEAR(mp0 - particle_mass(*r.c), expected, 1e-12 * expected);
}

TEST(MpmIceBurn, TransferCarriesTheParticlesMomentum) {
  set_thread_count(1);
  BurnRun r = make_run("1e-3", "[1.0, 0.5, 0.0]");
  ASSERT_NE(r.burn, nullptr);
  for (int step = 1; step <= 3; ++step) {
    const Particles before = r.c->mpm().materials()[0].particles;
    r.c->advance(r.time, 1e-4, step);
    r.time += 1e-4;
    const Particles& after = r.c->mpm().materials()[0].particles;
    ASSERT_EQ(after.size(), before.size());
    Vec3 lost = Vec3::Zero();
    for (std::size_t i = 0; i < after.size(); ++i) lost += (before.mass[i] - after.mass[i]) * before.v[i];
    const Vec3 P = r.burn->momentum_burned_last_step();
    EXPECT_GT(P[0], 0.0);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(P[d], lost[d], 1e-13 * lost.norm()) << "step " << step << " axis " << d;
  }
}

}  // namespace
}  // namespace tephra
