// Work-precision data on the AxisAligned manufactured solution (AA.ups):
// for each interpolator and 8, 16, 32 cells per side, the wall time and the
// L2 displacement error at the end time; printed and written to
// mms_work_precision.csv. Usage: bench_mms_work_precision [end_time] [ppc_dir]
// (defaults 0.005 s and 1 particle per cell direction). The PNG plot is not
// written yet.
#include <cstdio>
#include <cstdlib>

#include "tests/support/MmsRun.h"

int main(int argc, char** argv) {
  const double end_time = argc > 1 ? std::atof(argv[1]) : 0.005;
  const int ppc = argc > 2 ? std::atoi(argv[2]) : 1;
  std::FILE* csv = std::fopen("mms_work_precision.csv", "w");
  if (csv) std::fprintf(csv, "interpolator,cells,particles,steps,seconds,l2_error\n");
  for (const char* interp : {"linear", "gimp", "cpdi", "3rdorderBS"})
    for (int n : {8, 16, 32}) {
      const auto r = tephra::test::run_axis_aligned(interp, n, end_time, ppc);
      std::printf("%-10s cells %2d  particles %7ld  steps %4d  %8.2f s  L2 error %.4e\n", interp, n, r.particles,
                  r.steps, r.seconds, r.error);
      std::fflush(stdout);
      if (csv) std::fprintf(csv, "%s,%d,%ld,%d,%.6g,%.6e\n", interp, n, r.particles, r.steps, r.seconds, r.error);
    }
  if (csv) std::fclose(csv);
}
