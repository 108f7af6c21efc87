#pragma once
// A box of node indices [lo, hi) of a node grid (mpm/NodeGrid.h), empty when
// any hi <= lo. Used for a rank's node box (mpm/RankNodeSums.h: the nodes its
// particles' stencils can reach) and for the node range the node-wise passes
// of a step visit (NodeGrid::active).
#include <cstddef>

#include "core/base/Types.h"

namespace tephra {

struct NodeBox {
  IntVec3 lo = IntVec3::Zero();
  IntVec3 hi = IntVec3::Zero();
  bool empty() const { return (hi.array() <= lo.array()).any(); }
  bool contains(int i, int j, int k) const {
    return i >= lo[0] && i < hi[0] && j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2];
  }
  NodeBox intersect(const NodeBox& o) const {
    return {lo.cwiseMax(o.lo), hi.cwiseMin(o.hi)};
  }
  // The smallest box holding both (an empty box adds nothing).
  NodeBox hull(const NodeBox& o) const {
    if (empty()) return o;
    if (o.empty()) return *this;
    return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)};
  }
  bool operator==(const NodeBox& o) const { return lo == o.lo && hi == o.hi; }
  std::size_t count() const {
    return empty() ? 0 : std::size_t(hi[0] - lo[0]) * std::size_t(hi[1] - lo[1]) * std::size_t(hi[2] - lo[2]);
  }
  // Position of node (i,j,k) in the box, i fastest.
  std::size_t offset(int i, int j, int k) const {
    return std::size_t(i - lo[0]) + std::size_t(hi[0] - lo[0]) * (std::size_t(j - lo[1]) + std::size_t(hi[1] - lo[1]) * std::size_t(k - lo[2]));
  }
};

}  // namespace tephra
