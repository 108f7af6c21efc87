#include "core/base/PhaseTimers.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace tephra {

namespace {
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
}  // namespace

bool PhaseTimers::cpu_timing() {
  static const bool on = [] {
    const char* e = std::getenv("TEPHRA_PHASE_CPU");
    return e && std::strcmp(e, "1") == 0;
  }();
  return on;
}

PhaseTimers::Scope::Scope(PhaseTimers& t, const std::string& name)
    : timers_(t), index_(t.index_of(name)), start_(std::chrono::steady_clock::now()) {
  if (cpu_timing()) cpu_start_ = thread_cpu_seconds();
}

PhaseTimers::Scope::~Scope() {
  std::chrono::duration<double> d = std::chrono::steady_clock::now() - start_;
  timers_.add(index_, d.count(), cpu_timing() ? thread_cpu_seconds() - cpu_start_ : 0.0);
}

size_t PhaseTimers::index_of(const std::string& name) {
  for (size_t i = 0; i < entries_.size(); ++i)
    if (entries_[i].name == name) return i;
  entries_.push_back({name, 0.0, 0});
  return entries_.size() - 1;
}

void PhaseTimers::add(size_t index, double seconds, double cpu_seconds) {
  entries_[index].seconds += seconds;
  entries_[index].calls += 1;
  entries_[index].cpu_seconds += cpu_seconds;
}

std::string PhaseTimers::table(double total) const {
  std::string out;
  char buf[256];
  const bool cpu = cpu_timing();
  std::snprintf(buf, sizeof buf, "%-44s %12s %8s %10s%s\n", "phase", "wall [s]", "share", "calls",
                cpu ? "    cpu [s]" : "");
  out += buf;
  for (const auto& e : entries_) {
    double share = total > 0 ? 100.0 * e.seconds / total : 0.0;
    std::snprintf(buf, sizeof buf, "%-44s %12.4f %7.1f%% %10lld", e.name.c_str(), e.seconds, share, e.calls);
    out += buf;
    if (cpu) {
      std::snprintf(buf, sizeof buf, " %11.4f", e.cpu_seconds);
      out += buf;
    }
    out += "\n";
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
