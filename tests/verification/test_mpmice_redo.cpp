// The MPMICE step redo at its latest trigger (core/sim/StepRedo.h,
// MpmIceComponent::save_step_start / restore_step_start): the explicit step
// of a deck with <Models> asks for a redo at the Lagrangian specific-volume
// check (ice/IceStep.cpp), after the burn has taken mass from the particles,
// the equilibration, face velocities, pressure and exchange have written the
// cells, and the MPM grid has been integrated -- everything the step writes
// before that point must be put back.
//
// Deck: MPMICE/massX.ups (decks README A13) unchanged: a solid cube burning
// (Simple_Burn) in gas, 1e-4 s steps. The test's hook (set_redo_check_hook)
// throws StepRedoRequest at step 3:
//  1. once, at dt: the state after 5 steps must equal, bit for bit, that of a
//     run whose step 3 is two calls of dt/2 (the redo starts from exactly the
//     step's start and leaves nothing of the failed attempt behind);
//  2. at dt and again at the first dt/2 (nested: one snapshot buffer serves
//     every level): equal to the run whose step 3 is dt/4, dt/4, dt/2.
// Control: the run without a redo differs from both (the comparison can fail).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "core/io/StateArchive.h"
#include "core/sim/StepRedo.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

constexpr double kDt = 1e-4;  // massX's delt_init and delt_max

struct RedoRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
  double t = 0;
  int step = 0;
  void advance(double dt) { c->advance(t, dt, step), t += dt; }  // a part of step `step`
  void steps(int n) {
    for (int i = 0; i < n; ++i) ++step, advance(kDt);
  }
};

RedoRun make_run() {
  const std::string dir = test::shared_dir() + "/decks/inputs/MPMICE";
  std::ifstream in(dir + "/massX.ups");
  std::stringstream ss;
  ss << in.rdbuf();
  RedoRun r;
  r.deck = load_deck_from_string(ss.str(), "massX.ups", dir);
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  return r;
}

long long differing_entries(const MpmIceComponent& a, const MpmIceComponent& b) {
  StateArchive sa, sb;
  a.save_state(sa);
  b.save_state(sb);
  long long n = 0;
  for (const auto& [name, va] : sa.all_doubles()) {
    const std::vector<double>& vb = sb.doubles(name);
    if (va.size() != vb.size()) n += static_cast<long long>(std::max(va.size(), vb.size()));
    else
      for (std::size_t i = 0; i < va.size(); ++i) n += va[i] != vb[i];
  }
  for (const auto& [name, va] : sa.all_ints()) n += va != sb.ints(name);
  return n;
}

double particle_mass(const MpmIceComponent& c) {
  double m = 0;
  for (double x : c.mpm().materials()[0].particles.mass) m += x;
  return m;
}

// Forces a redo at step 3 for each dt in `fail_at` (each once), then runs to step 5.
RedoRun forced_run(const std::vector<double>& fail_at, int& thrown) {
  RedoRun r = make_run();
  std::vector<double> pending = fail_at;
  const RedoRun* rp = &r;
  r.c->mutable_ice().set_redo_check_hook([&pending, &thrown, rp](double, double h) {
    if (rp->step == 3 && !pending.empty() && h == pending.front()) {
      pending.erase(pending.begin());
      ++thrown;
      throw StepRedoRequest{"forced by the test"};
    }
  });
  r.steps(5);
  return r;
}

TEST(MpmIceRedo, RedoAtTheLagrangianCheckEqualsTheHalfSteps) {
  set_thread_count(1);
  int thrown = 0;
  RedoRun forced = forced_run({kDt}, thrown);
  RedoRun halves = make_run(), plain = make_run();
  plain.steps(5);
  halves.steps(2);
  const double m2 = particle_mass(*halves.c);
  halves.step = 3;
  halves.advance(0.5 * kDt);
  halves.advance(0.5 * kDt);
  halves.steps(2);
  const long long d_halves = differing_entries(*forced.c, *halves.c), d_plain = differing_entries(*forced.c, *plain.c);
  std::printf("forced redo at the Lagrangian check: %d redo(s); particle mass burned by step 5 %.6e kg; entries "
              "differing from the dt/2 run %lld, from the run without redo %lld\n",
              forced.c->step_redos(), m2 - particle_mass(*halves.c), d_halves, d_plain);
  EXPECT_EQ(thrown, 1);
  EXPECT_EQ(forced.c->step_redos(), 1);
  EXPECT_LT(particle_mass(*halves.c), m2);  // the burn wrote the particles during the step
  EXPECT_EQ(d_halves, 0);
  EXPECT_GT(d_plain, 0);
}

TEST(MpmIceRedo, NestedRedoEqualsTheQuarterSteps) {
  set_thread_count(1);
  int thrown = 0;
  RedoRun forced = forced_run({kDt, 0.5 * kDt}, thrown);
  RedoRun parts = make_run(), halves = make_run();
  parts.steps(2);
  parts.step = 3;
  parts.advance(0.25 * kDt);
  parts.advance(0.25 * kDt);
  parts.advance(0.5 * kDt);
  parts.steps(2);
  halves.steps(2);
  halves.step = 3;
  halves.advance(0.5 * kDt);
  halves.advance(0.5 * kDt);
  halves.steps(2);
  const long long d_parts = differing_entries(*forced.c, *parts.c), d_halves = differing_entries(*forced.c, *halves.c);
  std::printf("nested forced redo: %d redo(s); entries differing from dt/4, dt/4, dt/2: %lld; from dt/2, dt/2: %lld\n",
              forced.c->step_redos(), d_parts, d_halves);
  EXPECT_EQ(thrown, 2);
  EXPECT_EQ(forced.c->step_redos(), 2);
  EXPECT_EQ(d_parts, 0);
  EXPECT_GT(d_halves, 0);
}

}  // namespace
}  // namespace tephra
