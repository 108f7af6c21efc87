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

DeckNode leaf(const std::string& name, const std::string& text) {
  DeckNode n;
  n.name = name;
  n.text = text;
  return n;
}

void add_implicit_solver(DeckNode& root, const std::string& knob, const std::string& outer_tol) {
  DeckNode& ice = deck_node(root, {"CFD", "ICE"});
  DeckNode is = leaf("ImplicitSolver", "");
  is.children.push_back(leaf("max_outer_iterations", "20"));
  is.children.push_back(leaf("outer_iteration_tolerance", outer_tol));
  is.children.push_back(leaf("iters_before_timestep_restart", "10"));
  DeckNode p = leaf("Parameters", "");
  p.attributes.push_back({"variable", "implicitPressure"});
  p.children.push_back(leaf("solver", "cg"));
  p.children.push_back(leaf("preconditioner", "pfmg"));
  p.children.push_back(leaf("tolerance", "1e-12"));
  p.children.push_back(leaf("maxiterations", "200"));
  is.children.push_back(p);
  ice.children.push_back(is);
  if (knob.empty()) return;
  DeckNode tc = leaf("TimestepControl", "");
  tc.children.push_back(leaf("Scheme_for_delT_calc", "aggressive"));
  tc.children.push_back(leaf("knob_for_speedSound", knob));
  ice.children.push_back(tc);
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
