// Benchmark (not a test): the MPM speed benchmark ../shared/decks/bench/spheres.ups
// (two elastic spheres, 115,712 particles, 88x40x40 cells, GIMP, dt = 1e-5 s).
//
//   build/bin/bench_mpm_spheres [steps]              all four runs (gimp/linear x 1/2 threads)
//   build/bin/bench_mpm_spheres --one INTERP THREADS [steps]   one run
//
// Each run is its own process (this executable started again), so the peak
// resident memory VmHWM of /proc/self/status belongs to that run alone. A run
// loads and validates the deck (the linear run rewrites <interpolator>),
// builds the MPM component, initializes it and takes `steps` steps (default
// 200, the deck's 2 ms) with the deck's rule dt = min(0.5 dt_stable, delt_max)
// (the time loop's output and checkpoints are left out), then prints
//   particle-steps/s = particles * steps / wall time of the steps,
//   the same per thread, and per CPU-second of the process (user + system: on
//   a shared machine the wall figure includes waiting for a core),
//   VmHWM / particles (bytes per particle, whole process: libraries included),
//   (VmHWM - VmRSS before the component was built) / particles,
// and the per-phase table of the steps (PhaseTimers).
// Targets (issue): >= 1.5 M particle-steps/s on one core with GIMP, >= 3 M
// with linear, >= 1.8x with two threads, <= 1 KB per particle.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

#include "core/base/PhaseTimers.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/Validate.h"
#include "core/grid/Loop.h"
#include "core/parallel/Ranks.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

namespace {

// A "Vm...:  1234 kB" line of /proc/self/status, in bytes (0 if absent).
double proc_status_bytes(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return 1024.0 * std::atof(line.c_str() + std::string(key).size() + 1);
  return 0.0;
}

// User + system CPU time of this process [s] (all its threads).
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
}

std::size_t particles_here(const MpmComponent& c) {
  std::size_t n = 0;
  for (const auto& m : c.materials()) n += m.particles.size();
  return n;
}

int run_one(const std::string& interp, int threads, int steps) {
  const std::string path = test::shared_dir() + "/decks/bench/spheres.ups";
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    return 1;
  }
  std::stringstream s;
  s << in.rdbuf();
  std::string xml = s.str();
  const std::string key = "<interpolator>gimp</interpolator>";
  const auto at = xml.find(key);
  if (at == std::string::npos) {
    std::fprintf(stderr, "%s: no %s to rewrite\n", path.c_str(), key.c_str());
    return 1;
  }
  xml.replace(at, key.size(), "<interpolator>" + interp + "</interpolator>");

  set_thread_count(threads);
  const double rss_before = proc_status_bytes("VmRSS");
  auto deck = load_deck_from_string(xml, path, test::shared_dir() + "/decks/bench");
  validate_deck(*deck);
  auto c = make_mpm_component(*deck);
  c->initialize();
  // Under mpirun (MPM on ranks, docs/parallel.md) the particles of all ranks; rank 0's lines are the figures.
  const Ranks ranks = world_ranks();
  std::size_t particles = 0;
  for (double n : all_gather({double(particles_here(*c))})) particles += std::size_t(n);

  phase_timers() = PhaseTimers{};  // the table shows the steps only
  const double delt_max = 1.0e-5, multiplier = 0.5;
  double t = 0.0;
  const double cpu_start = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  for (int k = 1; k <= steps; ++k) {
    const double dt = std::min(multiplier * c->stable_timestep(), delt_max);
    c->advance(t, dt, k);
    t += dt;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpu_seconds() - cpu_start;
  const double hwm = proc_status_bytes("VmHWM");
  const double rate = double(particles) * steps / wall;
  barrier();
  std::printf("%-8s threads %d  ranks %d (this: %d)  particles %zu  steps %d  t = %.3e s  wall %.3f s\n", interp.c_str(),
              threads, ranks.size, ranks.rank, particles, steps, t, wall);
  std::printf("  particle-steps/s %.3e   per thread %.3e   per CPU-second %.3e (CPU %.3f s)\n", rate,
              rate / threads, double(particles) * steps / cpu, cpu);
  std::printf("  VmHWM %.1f MB = %.0f B/particle; above the pre-build RSS: %.0f B/particle\n", hwm / 1048576.0,
              hwm / particles, (hwm - rss_before) / particles);
  std::printf("%s\n", phase_timers().table(wall).c_str());
  std::fflush(stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 4 && std::string(argv[1]) == "--one")
    return run_one(argv[2], std::atoi(argv[3]), argc > 4 ? std::atoi(argv[4]) : 200);
  const int steps = argc > 1 ? std::atoi(argv[1]) : 200;
  // This executable's path (a shell started by std::system would read its own /proc/self/exe).
  char buf[4096] = {};
  const ssize_t len = readlink("/proc/self/exe", buf, sizeof buf - 1);
  const std::string self = len > 0 ? std::string(buf, std::size_t(len)) : std::string(argv[0]);
  int rc = 0;
  for (const char* interp : {"gimp", "linear"})
    for (int threads : {1, 2}) {
      const std::string cmd = self + " --one " + interp + " " + std::to_string(threads) + " " +
                              std::to_string(steps);
      std::fflush(stdout);
      rc |= std::system(cmd.c_str());
    }
  return rc == 0 ? 0 : 1;
}
