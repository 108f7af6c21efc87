#include "mpm/NodeGrid.h"

#include "mpm/NodeRuns.h"

namespace tephra {

namespace {

// Below this many nodes a parallel region costs more than it saves.
constexpr long kMinParallelNodes = 4096;

// v.assign(n, zero) with the zero fill split among the OpenMP threads: the
// fill is a stream of stores with nothing to compute, so one thread cannot
// keep the memory busy; on two cores the serial fill was the part of
// P2G that did not scale (docs/performance.md, session 13).
template <class T>
void assign_zero(std::vector<T>& v, std::size_t n, const T& zero) {
  if (v.size() != n) {
    v.clear();
    v.resize(n);  // value-initialised storage; overwritten below
  }
  T* d = v.data();
  const long count = long(n);
#pragma omp parallel for schedule(static) if (count >= kMinParallelNodes)
  for (long i = 0; i < count; ++i) d[i] = zero;
}

// v = 0 over the runs only (v has count() entries already).
template <class T>
void zero_runs(std::vector<T>& v, const NodeRuns& r, const T& zero) {
  T* d = v.data();
  for_each_run_node(r, [&](std::size_t gi) { d[gi] = zero; }, kMinParallelNodes);
}

// fn(v, n, zero) for every node array with the size n reset() gives it.
template <class Fn>
void each_node_array(NodeGrid& g, Fn&& fn) {
  const std::size_t c = g.count();
  const Vec3 zero3 = Vec3::Zero();
  fn(g.mass, c, 0.0);
  fn(g.volume, c, 0.0);
  fn(g.velocity, c, zero3);
  fn(g.velocity_star, c, zero3);
  fn(g.acceleration, c, zero3);
  fn(g.external_force, c, zero3);
  fn(g.internal_force, c, zero3);
  fn(g.stress, g.node_stress ? c : 0, Mat3(Mat3::Zero()));
}

}  // namespace

void NodeGrid::reset() {
  bool sized = true;
  each_node_array(*this, [&](const auto& v, std::size_t n, const auto&) { sized = sized && v.size() == n; });
  if (restricted && sized) {
    // Outside the previous box every array holds 0 already (nothing writes
    // outside the active box, NodeGrid.h): the hull of both boxes is all to zero.
    const NodeRuns r = node_runs(*this, cleared.hull(active));
    cleared = active;
    each_node_array(*this, [&](auto& v, std::size_t n, const auto& zero) {
      if (n > 0) zero_runs(v, r, zero);
    });
    return;
  }
  cleared = NodeBox{IntVec3::Zero(), n};  // all of it zeroed below
  each_node_array(*this, [](auto& v, std::size_t n, const auto& zero) { assign_zero(v, n, zero); });
}

}  // namespace tephra
