// Work-precision on Sod's shock tube (decks README A8, riemann_sm.ups to
// t = 0.5 ms): for first- and second-order advection, explicit and
// semi-implicit (hypre) pressure, and N = 100, 200, 400, 800 cells, the
// time of the run and the L1 density error against the exact Riemann
// solution (tests/support/ExactRiemann). Time = process CPU seconds (one
// thread: equal to the run time on an idle core, and still meaningful when
// other jobs share the cores; session 16, was wall time). Printed as a table and CSV lines
// ("csv,...") and drawn as run time against error to
// <build>/ice_sod_work_precision.png (one line per scheme, one point per N).
// Usage: bench_ice_sod_work_precision [cells=100,200,400,800] [cfl=deck's 0.25]
// One thread (a 1-D tube: the loop helper's threads cost more than they save).
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/grid/Loop.h"
#include "tests/support/PngPlot.h"
#include "tests/support/ShockTube.h"

using namespace tephra;

int main(int argc, char** argv) {
  std::vector<int> cells;
  {
    std::stringstream in(argc > 1 ? argv[1] : "100,200,400,800");
    for (std::string item; std::getline(in, item, ',');) cells.push_back(std::atoi(item.c_str()));
  }
  const double cfl = argc > 2 ? std::atof(argv[2]) : -1;
  set_thread_count(1);
  const test::ExactRiemann ex(test::sod_left(), test::sod_right(), 1.4);
  test::LogLogPlot plot;
  plot.title = "ICE Sod shock tube: work precision";
  plot.xlabel = "L1 density error (kg/m^2)";
  plot.ylabel = "CPU time (s)";
  std::printf("%-10s %-12s %6s %7s %12s %12s %12s\n", "pressure", "advection", "cells", "steps", "seconds", "L1(rho)",
              "L1(p)");
  for (bool implicit : {false, true}) {
    for (const char* adv : {"FirstOrder", "SecondOrder"}) {
      test::PlotSeries s;
      s.label = std::string(implicit ? "implicit " : "explicit ") + adv;
      for (int n : cells) {
        test::SodOptions o;
        o.cells = n;
        o.advection = adv;
        o.cfl = cfl;
        o.implicit = implicit;
        const std::clock_t t0 = std::clock();
        test::IceRun r = test::make_sod_run(o);
        test::run_to(r);
        const double sec = double(std::clock() - t0) / CLOCKS_PER_SEC;
        const test::ShockTubeErrors e = test::shock_tube_l1(r, ex, 0.5);
        std::printf("%-10s %-12s %6d %7d %12.4f %12.4e %12.4e\n", implicit ? "implicit" : "explicit", adv, n, r.steps,
                    sec, e.rho, e.p);
        std::printf("csv,%s,%s,%d,%d,%.6f,%.6e,%.6e\n", implicit ? "implicit" : "explicit", adv, n, r.steps, sec, e.rho,
                    e.p);
        s.x.push_back(e.rho);
        s.y.push_back(sec);
      }
      plot.series.push_back(s);
    }
  }
  const std::string png =
      (std::filesystem::path(TEPHRA_TEST_WORK_DIR).parent_path() / "ice_sod_work_precision.png").string();
  test::write_png(test::draw_log_log(plot), png);
  std::printf("plot: %s\n", png.c_str());
  return 0;
}
