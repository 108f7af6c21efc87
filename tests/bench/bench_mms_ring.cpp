// ExpandingRing manufactured solution (inputs/mpm/expanding_ring_mms.ups):
// prints the L2 displacement error, particles, steps and wall time for
//   bench_mms_ring [cells,cells,...] [interpolator] [ppc] [multiplier] [end_time]
// (defaults "16,32,64", cpdi, 2, the deck's 0.2, 0.005 s), one OpenMP thread.
// The study of docs/mpm-convergence.md ("ExpandingRing").
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/grid/Loop.h"
#include "tests/support/MmsRun.h"
#include "tests/support/TestPaths.h"

int main(int argc, char** argv) {
  using namespace tephra::test;
  std::vector<int> cells;
  std::istringstream in(argc > 1 ? argv[1] : "16,32,64");
  for (std::string item; std::getline(in, item, ',');) cells.push_back(std::atoi(item.c_str()));
  tephra::set_thread_count(1);
  double previous = 0.0;
  for (int c : cells) {
    MmsRunOptions o;
    o.deck = source_dir() + "/inputs/mpm/expanding_ring_mms.ups";
    o.planar = true;
    o.interpolator = argc > 2 ? argv[2] : "cpdi";
    o.particles_per_cell_dir = argc > 3 ? std::atoi(argv[3]) : 2;
    o.timestep_multiplier = argc > 4 ? std::atof(argv[4]) : 0.0;
    o.end_time = argc > 5 ? std::atof(argv[5]) : 0.005;
    o.cells = c;
    const MmsRunResult r = run_axis_aligned(o);
    std::printf("ring %s cells %4d particles %7ld steps %5d %8.2f s  L2 error %.4e", o.interpolator.c_str(), c,
                r.particles, r.steps, r.seconds, r.error);
    if (previous > 0.0) std::printf("  order %.2f", std::log2(previous / r.error));
    std::printf("\n");
    previous = r.error;
  }
  return 0;
}
