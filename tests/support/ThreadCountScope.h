#pragma once
// The thread count set for one scope of a test: set_thread_count(n) on entry,
// the previous count put back on exit (so a failing assertion cannot leave a
// later test on the wrong count).
#include "core/grid/Loop.h"

namespace tephra {

struct ThreadCountScope {
  int saved = thread_count();
  explicit ThreadCountScope(int n) { set_thread_count(n); }
  ~ThreadCountScope() { set_thread_count(saved); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;
};

}  // namespace tephra
