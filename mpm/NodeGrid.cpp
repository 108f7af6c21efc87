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

}  // namespace

void NodeGrid::reset() {
  const std::size_t c = count();
  const bool sized = mass.size() == c && volume.size() == c && velocity.size() == c && velocity_star.size() == c &&
                     acceleration.size() == c && external_force.size() == c && internal_force.size() == c &&
                     stress.size() == (node_stress ? c : 0);
  if (restricted && sized) {
    // Outside the previous box every array holds 0 already (nothing writes
    // outside the active box, NodeGrid.h): the hull of both boxes is all to zero.
    const NodeBox z = cleared.hull(active);
    cleared = active;
    const NodeRuns r = node_runs(*this, z);
    zero_runs(mass, r, 0.0);
    zero_runs(volume, r, 0.0);
    zero_runs(velocity, r, Vec3(Vec3::Zero()));
    zero_runs(velocity_star, r, Vec3(Vec3::Zero()));
    zero_runs(acceleration, r, Vec3(Vec3::Zero()));
    zero_runs(external_force, r, Vec3(Vec3::Zero()));
    zero_runs(internal_force, r, Vec3(Vec3::Zero()));
    if (node_stress) zero_runs(stress, r, Mat3(Mat3::Zero()));
    return;
  }
  cleared = NodeBox{IntVec3::Zero(), n};  // all of it zeroed below
  assign_zero(mass, c, 0.0);
  assign_zero(volume, c, 0.0);
  assign_zero(velocity, c, Vec3(Vec3::Zero()));
  assign_zero(velocity_star, c, Vec3(Vec3::Zero()));
  assign_zero(acceleration, c, Vec3(Vec3::Zero()));
  assign_zero(external_force, c, Vec3(Vec3::Zero()));
  assign_zero(internal_force, c, Vec3(Vec3::Zero()));
  assign_zero(stress, node_stress ? c : 0, Mat3(Mat3::Zero()));
}

}  // namespace tephra
