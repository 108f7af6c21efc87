#pragma once
// Wall time per named phase of a step ("MPM: interpolate particles to grid",
// "output", ...). The table printed at the end of a run shows what ran.
// With the environment variable TEPHRA_PHASE_CPU=1 each phase also records
// the CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID, a system call
// per scope, so off by default); with one thread that is the phase's CPU
// time, which a loaded machine does not inflate (tests/bench/mpmice_coupling.py).
#include <chrono>
#include <string>
#include <vector>

namespace tephra {

class PhaseTimers {
 public:
  struct Entry {
    std::string name;
    double seconds = 0.0;
    long long calls = 0;
    double cpu_seconds = 0.0;  // with TEPHRA_PHASE_CPU=1
  };

  // RAII scope: times one call of a phase.
  class Scope {
   public:
    Scope(PhaseTimers& t, const std::string& name);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PhaseTimers& timers_;
    size_t index_;
    std::chrono::steady_clock::time_point start_;
    double cpu_start_ = 0.0;
  };

  size_t index_of(const std::string& name);
  void add(size_t index, double seconds, double cpu_seconds = 0.0);
  // True when TEPHRA_PHASE_CPU=1 (read once).
  static bool cpu_timing();
  const std::vector<Entry>& entries() const { return entries_; }
  std::string table(double total_seconds) const;  // formatted, one line per phase

 private:
  std::vector<Entry> entries_;
};

// The process-wide timers of the running simulation.
PhaseTimers& phase_timers();

}  // namespace tephra
