#include "mpm/NodeGrid.h"

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

}  // namespace

void NodeGrid::reset() {
  const std::size_t c = count();
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
