// The loop helper visits every index of a range exactly once, with one thread
// and with two.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/base/Errors.h"
#include "core/grid/Loop.h"

using namespace tephra;

namespace {

void expect_each_index_once(int threads) {
  set_thread_count(threads);
  EXPECT_EQ(thread_count(), threads);
  const IndexRange r{IntVec3(-2, 3, -1), IntVec3(27, 31, 14)};  // 29 x 28 x 15, negative starts too
  ASSERT_GE(r.size(), kMinCellsPerParallelLoop);              // large enough to run in parallel
  const IntVec3 e = r.extent();
  std::vector<std::atomic<int>> visits(static_cast<size_t>(r.size()));
  for (auto& v : visits) v = 0;
  std::atomic<int> max_thread{0};
  for_each_cell(r, [&](int i, int j, int k) {
    ASSERT_TRUE(r.contains(i, j, k));
    visits[(size_t(k - r.lo[2]) * e[1] + size_t(j - r.lo[1])) * e[0] + size_t(i - r.lo[0])]++;
#ifdef _OPENMP
    int t = omp_get_thread_num(), m = max_thread.load();
    while (t > m && !max_thread.compare_exchange_weak(m, t)) {
    }
#endif
  });
  for (const auto& v : visits) ASSERT_EQ(v.load(), 1);
#ifdef _OPENMP
  // 420 (k,j) pairs shared statically among the threads: each thread gets some.
  EXPECT_EQ(max_thread.load(), threads - 1);
#endif
}

}  // namespace

TEST(GridLoop, VisitsEachCellOnceWithOneThread) { expect_each_index_once(1); }
TEST(GridLoop, VisitsEachCellOnceWithTwoThreads) { expect_each_index_once(2); }

TEST(GridLoop, EmptyRangeRunsNothingAndBadThreadCountIsUsageError) {
  int calls = 0;
  for_each_cell(IndexRange{IntVec3(0, 0, 0), IntVec3(3, 0, 3)}, [&](int, int, int) { ++calls; });
  EXPECT_EQ(calls, 0);
  EXPECT_THROW(set_thread_count(0), UsageError);
}

TEST(GridLoop, SmallRangesRunOnTheCallingThread) {
  set_thread_count(2);
  bool all_on_master = true;
  for_each_cell(IndexRange{IntVec3(0, 0, 0), IntVec3(10, 10, 10)}, [&](int, int, int) {
#ifdef _OPENMP
    if (omp_get_thread_num() != 0) all_on_master = false;
#endif
  });
  EXPECT_TRUE(all_on_master);
}
