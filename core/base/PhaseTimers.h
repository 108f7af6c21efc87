#pragma once
// Wall time per named phase of a step ("MPM: interpolate particles to grid",
// "output", ...). The table printed at the end of a run shows what ran.
// Also the CPU time of the process (all threads) and of the thread that
// opened the phase (the main thread) per phase: with OMP_WAIT_POLICY=passive
// (waiting threads sleep instead of spinning), process CPU over the main
// thread's CPU tells how much of a phase the other threads did (T for a
// phase that splits evenly over T threads, 1 for a serial one), and the
// process CPU with T threads over that with one thread is the extra work a
// phase costs when threaded (memory traffic, false sharing): both are read
// on a loaded machine, where wall times are not (docs/performance.md).
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
    double cpu_seconds = 0.0;          // process CPU (all threads)
    double thread_cpu_seconds = 0.0;   // CPU of the thread that opened the scope
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
    double cpu_start_, thread_cpu_start_;
  };

  size_t index_of(const std::string& name);
  void add(size_t index, double seconds, double cpu_seconds = 0.0, double thread_cpu_seconds = 0.0);
  const std::vector<Entry>& entries() const { return entries_; }
  std::string table(double total_seconds) const;  // formatted, one line per phase

 private:
  std::vector<Entry> entries_;
};

// The process-wide timers of the running simulation.
PhaseTimers& phase_timers();

}  // namespace tephra
