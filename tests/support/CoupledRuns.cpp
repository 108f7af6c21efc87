#include "tests/support/CoupledRuns.h"

#include <algorithm>

namespace tephra::test {

CoupledRun make_coupled_run(const std::string& deck_path, const std::function<void(DeckNode&)>& edit) {
  CoupledRun r;
  r.deck = load_deck(deck_path);
  if (edit) edit(r.deck->root);
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  return r;
}

void run_to(CoupledRun& r, double end_time, int max_steps) {
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

}  // namespace tephra::test
