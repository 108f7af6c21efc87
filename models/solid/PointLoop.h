#pragma once
// The loop of a model's update() over its points (DESIGN.md §2.3: one virtual
// call per material per step, the concrete loop inside), split among the
// OpenMP threads of the run (set_thread_count / --threads).
//
// `point(i)` updates point i only (reads the inputs of i, writes the outputs
// of i) and returns false when the state of i is inadmissible. Every point is
// computed by the same code whatever the thread count, so the results are
// bit-for-bit independent of it. Returns the LOWEST failing index (what a
// serial loop stopping at the first failure returns), or -1.
#include <algorithm>
#include <cstddef>

namespace tephra {

// Below this many points a parallel region costs more than it saves.
inline constexpr long kMinPointsPerParallelLoop = 4096;

template <class PointUpdate>
long for_each_point(std::size_t n, PointUpdate&& point) {
  const long count = static_cast<long>(n);
  long bad = count;
#pragma omp parallel for schedule(static) reduction(min : bad) if (count >= kMinPointsPerParallelLoop)
  for (long i = 0; i < count; ++i)
    if (!point(static_cast<std::size_t>(i))) bad = std::min(bad, i);
  return bad < count ? bad : -1;
}

}  // namespace tephra
