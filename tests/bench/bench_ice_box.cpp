// Benchmark (not a test): explicit ICE throughput on a 3-D ideal-gas box, in
// cell-steps per second (interior cells x steps / wall time), for 1, 2 and 4
// materials and 1 and 2 threads, second-order advection.
// Run: build/bin/bench_ice_box [n=64] [steps=10] [materials=all] [threads=1,2] [phases=0] [patches_x=1]
// (under mpirun -np N the patches_x slabs are spread over the ranks; every
// rank prints its table, the wall times are the same to a few per cent)
// (materials 0 = 1, 2 and 4, else that count; threads 0 = 1 and 2; phases 1 prints the
// PhaseTimers table of the timed steps of each run).
// Each material fills one slab of the box along x (the others are present at
// tiny_rho everywhere, as in Uintah), with a pressure jump between slabs so
// that the step does real work; all walls are symmetry planes. Output: a
// table on stdout and CSV lines ("csv,n,materials,threads,wall,rate,cpu_rate")
// for plots.
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/PhaseTimers.h"
#include "core/deck/DeckLoader.h"
#include "core/grid/MpiHaloExchange.h"
#include "core/grid/Loop.h"
#include "ice/IceComponent.h"

using namespace tephra;

namespace {

std::string box_deck(int n, int materials, int patches_x) {
  std::ostringstream x;
  x << R"(<?xml version="1.0"?><Uintah_specification>
  <Meta><title>ICE box bench</title></Meta>
  <SimulationComponent type="ice"/>
  <Time><maxTime>1</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max>
    <timestep_multiplier>1</timestep_multiplier></Time>
  <DataArchiver><filebase>bench.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>0.4</cfl><ICE><advection type="SecondOrder"/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>)";
  for (int m = 0; m < materials; ++m) {
    const double x0 = double(m) / materials, x1 = double(m + 1) / materials;
    x << R"(<material><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>716</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="b)" << m << R"("><min>[)" << x0 << R"(,0,0]</min><max>[)" << x1
      << R"(,1,1]</max></box><res>[2,2,2]</res><velocity>[0,0,0]</velocity><density>)" << 1.1768 * (1 + m)
      << R"(</density><pressure>101325</pressure><temperature>)" << 300 + 50 * m
      << R"(</temperature></geom_object></material>)";
  }
  x << "</ICE>";
  if (materials > 1) {
    x << "<exchange_properties><exchange_coefficients><momentum>";
    const int pairs = materials * (materials - 1) / 2;
    for (int k = 0; k < pairs; ++k) x << (k ? ", " : "") << "1e10";
    x << "</momentum><heat>";
    for (int k = 0; k < pairs; ++k) x << (k ? ", " : "") << "1e10";
    x << "</heat></exchange_coefficients></exchange_properties>";
  }
  x << R"(</MaterialProperties>
  <Grid><BoundaryConditions>)";
  for (const char* side : {"x-", "x+", "y-", "y+", "z-", "z+"})
    x << "<Face side=\"" << side << R"("><BCType id="all" label="Symmetric" var="symmetry"/></Face>)";
  x << R"(</BoundaryConditions><Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,1,1]</upper>
    <resolution>[)" << n << "," << n << "," << n << R"(]</resolution><extraCells>[1,1,1]</extraCells>
    <patches>[)" << patches_x << R"(,1,1]</patches></Box></Level></Grid></Uintah_specification>)";
  return x.str();
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 64;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 10;
  // Optional: only this material count (1, 2 or 4), e.g. for profiling.
  const int only = argc > 3 ? std::atoi(argv[3]) : 0;
  const int only_threads = argc > 4 ? std::atoi(argv[4]) : 0;
  const bool phases = argc > 5 && std::atoi(argv[5]) != 0;
  const int patches_x = argc > 6 ? std::atoi(argv[6]) : 1;
  std::printf("ICE box %d^3, second-order advection, %d steps after one warm-up step\n", n, steps);
  // cell-steps per CPU-second (process CPU time, all threads) stays meaningful
  // when other jobs share the cores; the wall figure is the issue's measure.
  std::printf("%10s %8s %12s %18s %22s %20s\n", "materials", "threads", "wall [s]", "cell-steps/s",
              "cell-steps/s/thread", "cell-steps/CPU-s");
  const std::vector<int> counts = only != 0 ? std::vector<int>{only} : std::vector<int>{1, 2, 4};
  for (int materials : counts) {
    for (int threads : {1, 2}) {
      if (only_threads != 0 && threads != only_threads) continue;
      set_thread_count(threads);
      auto deck = load_deck_from_string(box_deck(n, materials, patches_x), "bench_ice_box.ups", ".");
      auto ice = make_ice_component(*deck);
      ice->initialize();
      double t = 0;
      double dt = ice->stable_timestep();
      ice->advance(t, dt, 1);  // warm-up (first touch of the scratch fields)
      t += dt;
      phase_timers() = PhaseTimers{};  // the table shows the timed steps only
      const MpiHaloExchange::Traffic sent0 = MpiHaloExchange::traffic();
      const auto start = std::chrono::steady_clock::now();
      const std::clock_t cpu0 = std::clock();
      for (int k = 2; k <= steps + 1; ++k) {
        dt = ice->stable_timestep();
        ice->advance(t, dt, k);
        t += dt;
      }
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
      const double rate = double(n) * n * n * steps / wall, cpu_rate = double(n) * n * n * steps / cpu;
      std::printf("%10d %8d %12.3f %18.3e %22.3e %20.3e\n", materials, threads, wall, rate, rate / threads, cpu_rate);
      std::printf("csv,%d,%d,%d,%.4f,%.4e,%.4e\n", n, materials, threads, wall, rate, cpu_rate);
      // Halo traffic of this rank per timed step (0 in one process):
      // docs/scaling.md counts it per patch face.
      const MpiHaloExchange::Traffic sent1 = MpiHaloExchange::traffic();
      if (sent1.messages > sent0.messages)
        std::printf("halo per step: %.1f exchange calls, %.1f messages, %.0f bytes sent by this rank\n",
                    double(sent1.calls - sent0.calls) / steps, double(sent1.messages - sent0.messages) / steps,
                    8.0 * double(sent1.doubles - sent0.doubles) / steps);
      if (phases) std::printf("%s\n", phase_timers().table(wall).c_str());
    }
  }
  return 0;
}
