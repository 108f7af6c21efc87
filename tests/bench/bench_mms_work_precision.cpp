// Work-precision data on the AxisAligned manufactured solution (AA.ups):
// for each interpolator and 8, 16, 32 cells per side, the wall time and the
// L2 displacement error at the end time; printed and written to
// mms_work_precision.csv (current directory); the work-precision plot (wall
// time against L2 error, one line per interpolator, one point per
// resolution) is drawn to <build>/mms_work_precision.png. Usage:
//   bench_mms_work_precision [end_time] [ppc_dir] [timestep_multiplier] [interpolators] [cells]
// (defaults 0.005 s, 1 particle per cell direction, the deck's 0.2,
// "linear,gimp,cpdi,3rdorderBS", "8,16,32": the settings of
// tests/verification/test_mpm_mms.cpp). A run that fails (linear at 32^3
// inverts a particle) is printed and left out of the plot.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/MmsRun.h"
#include "tests/support/PngPlot.h"

namespace {
std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  tephra::test::MmsRunOptions o;
  o.end_time = argc > 1 ? std::atof(argv[1]) : 0.005;
  o.particles_per_cell_dir = argc > 2 ? std::atoi(argv[2]) : 1;
  o.timestep_multiplier = argc > 3 ? std::atof(argv[3]) : 0.0;
  // TEPHRA_MMS_PERIODIC_MIRROR=1: AxisAligned on [-1, 1]^3, periodic, no faces (MmsRunOptions::periodic_mirror).
  o.periodic_mirror = std::getenv("TEPHRA_MMS_PERIODIC_MIRROR") != nullptr;
  // TEPHRA_MMS_AMPLITUDE=A: AxisAligned with amplitude A instead of Vaango's 0.05 (MmsRunOptions::amplitude).
  if (const char* a = std::getenv("TEPHRA_MMS_AMPLITUDE")) o.amplitude = std::atof(a);
  const auto interps = split(argc > 4 ? argv[4] : "linear,gimp,cpdi,3rdorderBS");
  const auto cells = split(argc > 5 ? argv[5] : "8,16,32");
  std::FILE* csv = std::fopen("mms_work_precision.csv", "w");
  if (csv) std::fprintf(csv, "interpolator,cells,particles,steps,seconds,l2_error\n");
  tephra::test::LogLogPlot plot;
  plot.title = "AA MMS work-precision, t = " + std::to_string(o.end_time).substr(0, 5) + " s";
  plot.xlabel = "L2 displacement error (m)";
  plot.ylabel = "wall time (s)";
  for (const auto& interp : interps) {
    plot.series.push_back({interp, {}, {}});
    for (const auto& n : cells) {
      o.interpolator = interp;
      o.cells = std::atoi(n.c_str());
      tephra::test::MmsRunResult r;
      try {
        r = tephra::test::run_axis_aligned(o);
      } catch (const std::exception& e) {
        std::printf("%-10s cells %2d  failed: %s\n", interp.c_str(), o.cells, e.what());
        continue;
      }
      plot.series.back().x.push_back(r.error);
      plot.series.back().y.push_back(r.seconds);
      std::printf("%-10s cells %2d  particles %7ld  steps %4d  %8.2f s  L2 error %.4e\n", interp.c_str(), o.cells,
                  r.particles, r.steps, r.seconds, r.error);
      std::fflush(stdout);
      if (csv) std::fprintf(csv, "%s,%d,%ld,%d,%.6g,%.6e\n", interp.c_str(), o.cells, r.particles, r.steps, r.seconds,
                            r.error);
    }
  }
  if (csv) std::fclose(csv);
  const std::string png =
      (std::filesystem::path(TEPHRA_TEST_WORK_DIR).parent_path() / "mms_work_precision.png").string();
  tephra::test::write_png(tephra::test::draw_log_log(plot), png);
  std::printf("plot: %s\n", png.c_str());
}
