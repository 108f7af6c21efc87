#pragma once
// Running an MPMICE deck in-process for the verification tests: load the
// deck, optionally edit it, and step with the deck's time rule (delt_init
// first, then timestep_multiplier times the stable step, at most delt_max,
// cut to land on the end time). The MPMICE twin of tests/support/IceRuns.h.
#include <functional>
#include <memory>
#include <string>

#include "core/deck/DeckLoader.h"
#include "mpmice/MpmIceComponent.h"

namespace tephra::test {

struct CoupledRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
  double time = 0;
  int steps = 0;
};

// Loads `deck_path`, applies `edit` to the root, builds and initialises the component.
CoupledRun make_coupled_run(const std::string& deck_path, const std::function<void(DeckNode&)>& edit = {});
// Steps until `end_time` or `max_steps` steps in all.
void run_to(CoupledRun& r, double end_time, int max_steps);

}  // namespace tephra::test
