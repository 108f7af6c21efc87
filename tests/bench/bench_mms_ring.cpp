// ExpandingRing manufactured solution (inputs/mpm/expanding_ring_mms.ups):
// prints the L2 displacement error, particles, steps and wall time for
//   bench_mms_ring [cells,cells,...] [interpolator] [ppc] [multiplier] [end_time]
// (defaults "16,32,64", cpdi, 2, the deck's 0.2, 0.005 s), one OpenMP thread,
// and the error by distance to the curved faces; TEPHRA_RING_CUBIC_Z=1 makes
// the z cell as thick as an x cell; TEPHRA_RING_CONFORMING=1 seeds the ring in
// (R, theta) with the curved faces at particle faces (MmsRunOptions::conforming_ring).
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
    o.cubic_z = std::getenv("TEPHRA_RING_CUBIC_Z") != nullptr;
    o.ring_inner = 0.4;
    o.ring_outer = 0.6;
    o.conforming_ring = std::getenv("TEPHRA_RING_CONFORMING") != nullptr;
    const MmsRunResult r = run_axis_aligned(o);
    std::printf("ring %s cells %4d particles %7ld steps %5d %8.2f s  L2 error %.4e", o.interpolator.c_str(), c,
                r.particles, r.steps, r.seconds, r.error);
    if (previous > 0.0) std::printf("  order %.2f", std::log2(previous / r.error));
    std::printf("\n");
    for (int b = 0; b < 4; ++b)
      std::printf("    %s cells from a curved face: %6ld particles, L2 error %.4e\n",
                  b == 0 ? "[0,1)" : b == 1 ? "[1,2)" : b == 2 ? "[2,3)" : ">= 3 ", r.band_count[b], r.band_rms[b]);
    previous = r.error;
  }
  return 0;
}
