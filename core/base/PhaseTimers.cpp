#include "core/base/PhaseTimers.h"

#include <cstdio>
#include <ctime>

namespace tephra {

namespace {
double cpu_clock(clockid_t id) {
  timespec ts{};
  clock_gettime(id, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
}  // namespace

PhaseTimers::Scope::Scope(PhaseTimers& t, const std::string& name)
    : timers_(t),
      index_(t.index_of(name)),
      start_(std::chrono::steady_clock::now()),
      cpu_start_(cpu_clock(CLOCK_PROCESS_CPUTIME_ID)),
      thread_cpu_start_(cpu_clock(CLOCK_THREAD_CPUTIME_ID)) {}

PhaseTimers::Scope::~Scope() {
  std::chrono::duration<double> d = std::chrono::steady_clock::now() - start_;
  timers_.add(index_, d.count(), cpu_clock(CLOCK_PROCESS_CPUTIME_ID) - cpu_start_,
              cpu_clock(CLOCK_THREAD_CPUTIME_ID) - thread_cpu_start_);
}

size_t PhaseTimers::index_of(const std::string& name) {
  for (size_t i = 0; i < entries_.size(); ++i)
    if (entries_[i].name == name) return i;
  entries_.push_back({name, 0.0, 0});
  return entries_.size() - 1;
}

void PhaseTimers::add(size_t index, double seconds, double cpu_seconds, double thread_cpu_seconds) {
  entries_[index].seconds += seconds;
  entries_[index].calls += 1;
  entries_[index].cpu_seconds += cpu_seconds;
  entries_[index].thread_cpu_seconds += thread_cpu_seconds;
}

std::string PhaseTimers::table(double total) const {
  std::string out;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%-44s %12s %8s %10s %10s %10s\n", "phase", "wall [s]", "share", "calls",
                "CPU [s]", "main [s]");
  out += buf;
  for (const auto& e : entries_) {
    double share = total > 0 ? 100.0 * e.seconds / total : 0.0;
    std::snprintf(buf, sizeof buf, "%-44s %12.4f %7.1f%% %10lld %10.4f %10.4f\n", e.name.c_str(), e.seconds, share,
                  e.calls, e.cpu_seconds, e.thread_cpu_seconds);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "%-44s %12.4f\n", "total", total);
  out += buf;
  return out;
}

PhaseTimers& phase_timers() {
  static PhaseTimers timers;
  return timers;
}

}  // namespace tephra
