#include "tests/support/PatchedRuns.h"

#include <algorithm>

#include "core/sim/RunParameters.h"
#include "mpmice/ComponentFactory.h"
#include "tests/support/IceRuns.h"

namespace tephra::test {

PatchedRun start_patched_run(const std::string& path, const std::string& patches, int steps) {
  PatchedRun r;
  r.deck = load_deck(path);
  deck_node(r.deck->root, {"Grid", "Level", "Box", "patches"}).text = patches;
  r.deck->root.finalize_parents();
  r.c = make_component(*r.deck);
  r.c->initialize();
  const TimeParameters tp = read_time_parameters(r.deck->root.require_child("Time"));
  for (int s = 1; s <= steps; ++s) {
    const double dt = std::min(tp.delt_max, tp.timestep_multiplier * r.c->stable_timestep());
    r.c->advance(r.t, dt, s);
    r.t += dt;
  }
  return r;
}

}  // namespace tephra::test
