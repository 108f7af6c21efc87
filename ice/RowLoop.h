#pragma once
// Row kernels for the ICE hot loops: kernel(j, k) runs once per (j, k) row of
// a box and loops over i in [r.lo[0], r.hi[0]) itself. A row is contiguous in
// every grid field (core/grid/Fields.h, i fastest), so the kernel takes one
// pointer per field and row (row_ptr) and indexes it by i - lo: no index
// arithmetic per access, no per-cell call, loops the compiler can vectorize.
// Rows are shared among threads as for_each_cell (core/grid/Loop.h) shares
// its (k, j) pairs; a kernel writes only the entries of its own row, so the
// results do not depend on the thread count.
#include <cstddef>

#include "core/grid/Fields.h"
#include "core/grid/Loop.h"

namespace tephra {

template <class Kernel>
void for_each_row(const IndexRange& r, Kernel&& kernel) {
  const int k0 = r.lo[2], k1 = r.hi[2], j0 = r.lo[1], j1 = r.hi[1];
  if (r.empty()) return;
#pragma omp parallel for collapse(2) schedule(static) if (r.size() >= kMinCellsPerParallelLoop)
  for (int k = k0; k < k1; ++k)
    for (int j = j0; j < j1; ++j) kernel(j, k);
}

// Pointer to entry (i, j, k) of a field: the start of a row when i = r.lo[0].
template <class T>
T* row_ptr(GridArray<T>& a, int i, int j, int k) {
  return &a(i, j, k);
}
template <class T>
const T* row_ptr(const GridArray<T>& a, int i, int j, int k) {
  return &a(i, j, k);
}
template <class T>
const T* row_ptr(const GridArray<T>& a, const IntVec3& c) {
  return &a(c[0], c[1], c[2]);
}
template <class T>
T* row_ptr(GridArray<T>& a, const IntVec3& c) {
  return &a(c[0], c[1], c[2]);
}

}  // namespace tephra
