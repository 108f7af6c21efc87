#pragma once
// Builds the simulation component a deck asks for (<SimulationComponent
// type=...>): mpm, ice, mpmice, ... Everything the component needs is read
// and validated here, before step 1. A component or option Tephra does not
// have yet is a MissingFeature (exit 3) naming it.
#include <memory>
#include <string>
#include <vector>

#include "core/deck/DeckLoader.h"
#include "core/sim/Component.h"

namespace tephra {

std::unique_ptr<Component> make_component(const Deck& deck);

// The registered keys of a model family (`tephra --list FAMILY`); throws
// UsageError for an unknown family, listing the families.
std::vector<std::string> registered_keys(const std::string& family);

}  // namespace tephra
