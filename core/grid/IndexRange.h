#pragma once
// A box of (i,j,k) indices [lo, hi) -- hi exclusive in every direction. Used
// for cell, node and face index sets alike; what the indices mean is in the
// field type that hands the range out.
#include "core/base/Types.h"

namespace tephra {

struct IndexRange {
  IntVec3 lo = IntVec3::Zero();
  IntVec3 hi = IntVec3::Zero();  // exclusive

  IntVec3 extent() const { return (hi - lo).cwiseMax(0); }
  long long size() const {
    const IntVec3 e = extent();
    return 1LL * e[0] * e[1] * e[2];
  }
  bool empty() const { return size() == 0; }
  bool contains(int i, int j, int k) const {
    return i >= lo[0] && i < hi[0] && j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2];
  }
  bool contains(const IntVec3& c) const { return contains(c[0], c[1], c[2]); }
  // The range grown by g on every side (g may be negative).
  IndexRange grown(int g) const { return {lo - IntVec3::Constant(g), hi + IntVec3::Constant(g)}; }
  IndexRange intersect(const IndexRange& o) const { return {lo.cwiseMax(o.lo), hi.cwiseMin(o.hi)}; }
  bool operator==(const IndexRange& o) const { return lo == o.lo && hi == o.hi; }
};

}  // namespace tephra
