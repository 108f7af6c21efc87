#pragma once
// Running an ICE deck in-process for the verification tests: load the deck,
// optionally edit it, and step with the deck's rule (delt_init first, then
// the stable step, cut to land on maxTime).
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>

#include "core/deck/DeckLoader.h"
#include "ice/IceComponent.h"

namespace tephra::test {

// The first element along `path` below `root` (each name a child of the
// previous); throws std::runtime_error if missing.
DeckNode& deck_node(DeckNode& root, std::initializer_list<const char*> path);

// A deck element with text and no children.
DeckNode leaf(const std::string& name, const std::string& text);

// Adds <CFD><ICE><ImplicitSolver> as in rayleigh.ups with a reachable inner
// tolerance (cg + pfmg, 1e-12, 200 iterations; 20 outer iterations to
// `outer_tol`), and, when `knob` is not empty, <TimestepControl> aggressive
// with that speed-of-sound knob (else Uintah's default knob 0.5).
void add_implicit_solver(DeckNode& root, const std::string& knob = "", const std::string& outer_tol = "1e-10");

struct IceRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<IceComponent> ice;
  double time = 0;
  int steps = 0;
};

// Loads `deck_path`, applies `edit` to the root, builds and initialises the
// component.
IceRun make_ice_run(const std::string& deck_path, const std::function<void(DeckNode&)>& edit = {});
// Steps to `end_time` (the deck's maxTime when < 0) or `max_steps`.
void run_to(IceRun& run, double end_time = -1, int max_steps = 1 << 30);

}  // namespace tephra::test
