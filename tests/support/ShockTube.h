#pragma once
// Sod's shock tube (decks README A8, inputs/ICE/riemann_sm.ups) run in-process
// at any resolution, advection order, cfl and with or without the implicit
// pressure solve, and its L1 errors against the exact Riemann solution. Used
// by the Riemann and cfl-sweep verification tests and the work-precision
// benchmark.
#include <string>

#include "tests/support/ExactRiemann.h"
#include "tests/support/IceRuns.h"

namespace tephra::test {

struct ShockTubeErrors {
  double rho = 0, p = 0, u = 0;  // L1 = sum |q - q_exact| dx over the interior cells
};

struct SodOptions {
  int cells = 200;
  std::string advection = "SecondOrder";
  double cfl = -1;        // < 0: the deck's 0.25
  bool implicit = false;  // add <ImplicitSolver> (cg + pfmg, outer tolerance 1e-10; knob 0.5, Uintah's default)
};

// Sod (A8): gamma 1.4, rho 1.1768/0.11768, p 101325/10132.5, u = 0, x0 = 0.5.
GasState sod_left();
GasState sod_right();

// Builds the run: the deck with the tube's y and z sizes set to one cell
// width (so the time step follows dx) and the options applied.
IceRun make_sod_run(const SodOptions& o);
ShockTubeErrors shock_tube_l1(const IceRun& r, const ExactRiemann& ex, double x0);

}  // namespace tephra::test
