// Benchmark (not a test): explicit-MPM throughput on the colliding-disks deck
// at three grid resolutions, in particle-steps per second and node-steps per
// second. Run: build/bin/bench_mpm_throughput [steps]
// The deck's cell size is refined by rewriting <resolution>; particles per
// cell stay 2x2x2, so the particle count grows with the cell count.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 100;
  std::ifstream in(test::source_dir() + "/inputs/mpm/disks.ups");
  std::stringstream s;
  s << in.rdbuf();
  std::printf("%-10s %10s %10s %8s %12s %16s %14s\n", "cells", "particles", "nodes", "steps", "wall [s]",
              "particle-steps/s", "node-steps/s");
  for (int n : {20, 40, 80}) {
    std::string xml = std::regex_replace(s.str(), std::regex("<resolution>\\[20,20,1\\]</resolution>"),
                                         "<resolution>[" + std::to_string(n) + "," + std::to_string(n) + ",1]</resolution>");
    auto deck = load_deck_from_string(xml, "disks.ups", test::source_dir() + "/inputs/mpm");
    auto c = make_mpm_component(*deck);
    c->initialize();
    std::size_t particles = 0;
    for (const auto& m : c->materials()) particles += m.particles.size();
    const double nodes = double(n + 1) * (n + 1) * 2;
    double t = 0.0;
    auto start = std::chrono::steady_clock::now();
    for (int k = 1; k <= steps; ++k) {
      const double dt = std::min(0.2 * c->stable_timestep(), 0.01);
      c->advance(t, dt, k);
      t += dt;
    }
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-10s %10zu %10.0f %8d %12.4f %16.3e %14.3e\n", (std::to_string(n) + "x" + std::to_string(n)).c_str(),
                particles, nodes, steps, wall, particles * steps / wall, nodes * steps / wall);
  }
  return 0;
}
