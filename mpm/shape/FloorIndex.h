#pragma once
// floor for the node-index arithmetic of the shape functions, without
// std::floor: on the x86-64 baseline (no SSE4.1 roundsd; -march=native is not
// used) GCC expands std::floor into a 12-instruction sequence per call.
//
// floor_index(x) = floor(x) as an int, for -2^31 < x < 2^31 (every node index
// of a grid, and more; NaN or x outside that range is undefined, as the
// static_cast<int>(std::floor(x)) it replaces). Proof: the conversion t =
// (int)x truncates toward zero, so t = floor(x) for x >= 0 (and for x = -0)
// and for negative integers, and t = floor(x) + 1 > x for negative
// non-integers -- exactly the case (double)t > x, where 1 is taken off
// ((double)t is exact: |t| < 2^31 < 2^53).
//
// floor_value(x, floor_index(x)) = std::floor(x) bit for bit in the same range:
// the magnitude is |floor_index(x)|, and floor(x) carries the sign of x for
// every x (floor(+-0) = +-0, floor(x) >= +0 for x > 0, <= -1 for x < 0), which
// copysign restores (the int has no -0).
// Test: tests/unit/test_mpm_floor_index.cpp.
#include <cmath>

namespace tephra {

inline int floor_index(double x) {
  const int t = static_cast<int>(x);
  return t - (x < static_cast<double>(t) ? 1 : 0);
}

inline double floor_value(double x, int floor_index_of_x) {
  return std::copysign(static_cast<double>(floor_index_of_x), x);
}

}  // namespace tephra
