#include "tests/support/IceRuns.h"

#include <algorithm>
#include <stdexcept>

namespace tephra::test {

DeckNode& deck_node(DeckNode& root, std::initializer_list<const char*> path) {
  DeckNode* n = &root;
  for (const char* name : path) {
    auto it = std::find_if(n->children.begin(), n->children.end(), [&](const DeckNode& c) { return c.name == name; });
    if (it == n->children.end()) throw std::runtime_error(std::string("deck has no element ") + name);
    n = &*it;
  }
  return *n;
}

IceRun make_ice_run(const std::string& deck_path, const std::function<void(DeckNode&)>& edit) {
  IceRun r;
  r.deck = load_deck(deck_path);
  if (edit) edit(r.deck->root);
  r.deck->root.finalize_parents();
  r.ice = make_ice_component(*r.deck);
  r.ice->initialize();
  return r;
}

void run_to(IceRun& r, double end_time, int max_steps) {
  const DeckNode& time = r.deck->root.require_child("Time");
  if (end_time < 0) end_time = time.get_double("maxTime");
  const double delt_init = time.get_double("delt_init", 0.0);
  const double delt_max = time.get_double("delt_max", 1e300);
  while (r.time < end_time * (1 - 1e-14) && r.steps < max_steps) {
    double dt = (r.steps == 0 && delt_init > 0) ? delt_init : r.ice->stable_timestep();
    dt = std::min({dt, delt_max, end_time - r.time});
    ++r.steps;
    r.ice->advance(r.time, dt, r.steps);
    r.time += dt;
  }
}

}  // namespace tephra::test
