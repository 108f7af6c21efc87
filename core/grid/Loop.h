#pragma once
// The one loop helper every grid kernel goes through, so threading (and later
// GPU offload) lives in one place (DESIGN.md §2.5, AMReX's ParallelFor).
//
//   for_each_cell(field.interior(), [&](int i, int j, int k) { ... });
//
// The range may be any index box (cells, nodes or faces). The kernel runs once
// per (i,j,k), k outermost and i innermost (unit stride in our fields). The
// (k,j) pairs are shared among OpenMP threads, so a kernel must only write
// entries that belong to its own (i,j,k), or reduce through its own storage.
#include "core/grid/IndexRange.h"

namespace tephra {

// Number of threads the loop helper uses (the `--threads N` option). n >= 1.
void set_thread_count(int n);
int thread_count();

// Below this many cells a parallel region costs more than it saves (measured:
// a 250-cell shock tube ran 2x slower with two threads), so small boxes run
// on the calling thread.
inline constexpr long long kMinCellsPerParallelLoop = 8192;

template <class Kernel>
void for_each_cell(const IndexRange& r, Kernel&& kernel) {
  const int k0 = r.lo[2], k1 = r.hi[2], j0 = r.lo[1], j1 = r.hi[1], i0 = r.lo[0], i1 = r.hi[0];
  const long long cells = 1LL * (k1 - k0) * (j1 - j0) * (i1 - i0);
#pragma omp parallel for collapse(2) schedule(static) if (cells >= kMinCellsPerParallelLoop)
  for (int k = k0; k < k1; ++k)
    for (int j = j0; j < j1; ++j)
      for (int i = i0; i < i1; ++i) kernel(i, j, k);
}

// Serial twin of for_each_cell for work that must run in index order.
template <class Kernel>
void for_each_cell_serial(const IndexRange& r, Kernel&& kernel) {
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      for (int i = r.lo[0]; i < r.hi[0]; ++i) kernel(i, j, k);
}

}  // namespace tephra
