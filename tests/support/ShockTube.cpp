#include "tests/support/ShockTube.h"

#include <cmath>
#include <sstream>

#include "tests/support/TestPaths.h"

namespace tephra::test {

GasState sod_left() { return {1.1768292682926831, 0.0, 101325.0}; }
GasState sod_right() { return {0.11768292682926831, 0.0, 10132.5}; }

IceRun make_sod_run(const SodOptions& o) {
  auto edit = [&](DeckNode& root) {
    DeckNode& box = deck_node(root, {"Grid", "Level", "Box"});
    deck_node(box, {"resolution"}).text = "[" + std::to_string(o.cells) + ",1,1]";
    std::ostringstream w;
    w.precision(17);
    w << "[1," << 1.0 / o.cells << "," << 1.0 / o.cells << "]";
    deck_node(box, {"upper"}).text = w.str();
    for (auto& a : deck_node(root, {"CFD", "ICE", "advection"}).attributes)
      if (a.first == "type") a.second = o.advection;
    if (o.cfl > 0) {
      std::ostringstream c;
      c.precision(17);
      c << o.cfl;
      deck_node(root, {"CFD", "cfl"}).text = c.str();
    }
    if (o.implicit) add_implicit_solver(root);
  };
  return make_ice_run(shared_dir() + "/decks/inputs/ICE/riemann_sm.ups", edit);
}

ShockTubeErrors shock_tube_l1(const IceRun& r, const ExactRiemann& ex, double x0) {
  const Grid& g = r.ice->grid();
  ShockTubeErrors e;
  for (int i = 0; i < g.cells[0]; ++i) {
    const double x = g.cell_center(i, 0, 0)[0];
    const GasState s = ex.sample((x - x0) / r.time);
    e.rho += std::abs(r.ice->fields()[0].rho_CC[0](i, 0, 0) - s.rho) * g.dx[0];
    e.p += std::abs(r.ice->press_CC()[0](i, 0, 0) - s.p) * g.dx[0];
    e.u += std::abs(r.ice->fields()[0].vel_CC[0](i, 0, 0)[0] - s.u) * g.dx[0];
  }
  return e;
}

}  // namespace tephra::test
