#pragma once
// The comparisons the 1-rank vs N-rank tests share (tests/mpi/test_mpi_*.cpp):
// a relative field difference, Vec3 columns as flat values, and the particles
// a rank holds (count and ids) over every MPM material of a component.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <set>
#include <vector>

#include "core/base/Types.h"

namespace tephra::test {

// max |a - b| / max |a| (|a - b| when a is all zero); a size mismatch fails the test.
inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double scale = 0, diff = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return scale > 0 ? diff / scale : diff;
}

inline std::vector<double> flat(const std::vector<Vec3>& v) {
  std::vector<double> out;
  for (const Vec3& x : v) out.insert(out.end(), x.data(), x.data() + 3);
  return out;
}

// `materials`: MpmComponent::materials() (or MpmIceComponent::mpm().materials()).
template <class Materials>
std::size_t particles_here(const Materials& materials) {
  std::size_t n = 0;
  for (const auto& m : materials) n += m.particles.size();
  return n;
}

template <class Materials>
std::set<long long> own_ids(const Materials& materials) {
  std::set<long long> ids;
  for (const auto& m : materials) ids.insert(m.particles.id.begin(), m.particles.id.end());
  return ids;
}

}  // namespace tephra::test
