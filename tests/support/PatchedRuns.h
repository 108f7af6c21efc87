#pragma once
// Any component's deck run in-process with its <patches> replaced (the MPI
// tests split a deck over the ranks this way): load, set
// <Grid><Level><Box><patches>, make the component from the deck's
// SimulationComponent, initialize, then `steps` steps of
// min(delt_max, timestep_multiplier x stable dt).
#include <memory>
#include <string>

#include "core/deck/DeckLoader.h"
#include "core/sim/Component.h"

namespace tephra::test {

struct PatchedRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<Component> c;
  double t = 0;
};

PatchedRun start_patched_run(const std::string& path, const std::string& patches, int steps);

}  // namespace tephra::test
