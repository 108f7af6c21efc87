#pragma once
// The node-wise passes over NodeGrid::active_box() (mpm/NodeGrid.h) as runs
// of consecutive node indices (index i fastest): one run when the box spans
// the grid in x and y (the whole grid in one process: the loops are the
// whole-grid loops they replace), one per z plane when it spans x, else one
// per (j, k) row. Included by the .cpp files of the node passes only.
#include <cstddef>

#include "mpm/NodeGrid.h"

namespace tephra {

struct NodeRuns {
  std::size_t first = 0;   // node index where run 0 starts
  std::size_t length = 0;  // nodes per run
  long count = 0;          // runs
  long cy = 1;             // runs per z plane (general case: the box's j extent)
  std::size_t sy = 0, sz = 0;  // index steps between runs of consecutive j, k
  std::size_t begin(long r) const { return first + std::size_t(r % cy) * sy + std::size_t(r / cy) * sz; }
  std::size_t nodes() const { return std::size_t(count) * length; }
};

inline NodeRuns node_runs(const NodeGrid& g, const NodeBox& b) {
  NodeRuns r;
  if (b.empty()) return r;
  const std::size_t nx = std::size_t(g.n[0]), nxy = nx * std::size_t(g.n[1]);
  r.first = g.index(b.lo[0], b.lo[1], b.lo[2]);
  const bool full_x = b.lo[0] == 0 && b.hi[0] == g.n[0], full_y = b.lo[1] == 0 && b.hi[1] == g.n[1];
  if (full_x && full_y) {
    r.count = 1, r.length = nxy * std::size_t(b.hi[2] - b.lo[2]);
  } else if (full_x) {
    r.count = b.hi[2] - b.lo[2], r.length = nx * std::size_t(b.hi[1] - b.lo[1]), r.sz = nxy;
  } else {
    r.cy = b.hi[1] - b.lo[1];
    r.count = r.cy * long(b.hi[2] - b.lo[2]), r.length = std::size_t(b.hi[0] - b.lo[0]), r.sy = nx, r.sz = nxy;
  }
  return r;
}
inline NodeRuns node_runs(const NodeGrid& g) { return node_runs(g, g.active_box()); }

// fn(gi) for every node of the runs, shared among the threads of an enclosing
// parallel region (an orphaned `omp for`, static, with its barrier at the end;
// outside a parallel region: serial). fn must touch node gi only (then any
// split gives the same bits).
template <class Fn>
void for_each_run_node_here(const NodeRuns& r, Fn&& fn) {
  if (r.count == 1) {
    const long len = long(r.length);
    const std::size_t f = r.first;
#pragma omp for schedule(static)
    for (long n = 0; n < len; ++n) fn(f + std::size_t(n));
    return;
  }
  const long runs = r.count;
  const std::size_t len = r.length;
#pragma omp for schedule(static)
  for (long q = 0; q < runs; ++q) {
    const std::size_t b = r.begin(q);
    for (std::size_t gi = b; gi < b + len; ++gi) fn(gi);
  }
}

// The same in its own parallel region, threaded (OpenMP) above `min_parallel` nodes.
template <class Fn>
void for_each_run_node(const NodeRuns& r, Fn&& fn, long min_parallel = 4096) {
#pragma omp parallel if (long(r.nodes()) >= min_parallel)
  for_each_run_node_here(r, fn);
}

// fn(gi) for every node of g's active box (NodeGrid::active_box), threaded.
template <class Fn>
void for_each_active_node(const NodeGrid& g, Fn&& fn, long min_parallel = 4096) {
  for_each_run_node(node_runs(g), fn, min_parallel);
}

}  // namespace tephra
