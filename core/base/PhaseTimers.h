#pragma once
// Wall time per named phase of a step ("MPM: interpolate particles to grid",
// "output", ...). The table printed at the end of a run shows what ran.
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
  };

  size_t index_of(const std::string& name);
  void add(size_t index, double seconds);
  const std::vector<Entry>& entries() const { return entries_; }
  std::string table(double total_seconds) const;  // formatted, one line per phase

 private:
  std::vector<Entry> entries_;
};

// The process-wide timers of the running simulation.
PhaseTimers& phase_timers();

}  // namespace tephra
