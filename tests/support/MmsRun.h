#pragma once
// Runs the AxisAligned manufactured solution (shared/decks/inputs/MPM/AA.ups)
// in-process with a chosen interpolator, cells per side and end time, with the
// deck's time-step rule (timestep_multiplier x stable dt, capped by delt_max),
// and returns the L2 displacement error at the end and the wall time. Used by
// tests/verification/test_mpm_mms.cpp and tests/bench/bench_mms_work_precision.cpp.
#include <string>

namespace tephra::test {

struct MmsRunResult {
  double error = 0.0;    // MMSDisplacementErrorL2 at end_time
  double seconds = 0.0;  // wall time of initialize + steps
  long particles = 0;
  int steps = 0;
};

MmsRunResult run_axis_aligned(const std::string& interpolator, int cells, double end_time,
                              int particles_per_cell_dir = 2);

}  // namespace tephra::test
