// Rank-count independence of the global sums and the patch assignment
// (issue 7 item 2). Run by ctest under `mpirun -np 1` and `-np 2` (label mpi):
// every rank must get the bits of the serial answer.
#include <gtest/gtest.h>

#include <cmath>

#include "core/parallel/LoadBalancer.h"
#include "core/parallel/OrderedReduction.h"
#include "core/parallel/Ranks.h"

namespace tephra {
namespace {

// Order-sensitive per-patch values: alternating huge and tiny terms, so any
// other summation order rounds differently.
std::vector<double> patch_values(int id) {
  const double big = (id % 3 == 0) ? 1e16 : (id % 3 == 1 ? -1e16 : 0.0);
  return {big + 0.1 * id, std::sin(1.0 + id) * 1e-3, double(id)};
}

TEST(MpiReductions, OrderedSumIsTheSerialSumOnAnyRankCount) {
  const Ranks r = world_ranks();
  const int patches = 37;
  std::vector<double> serial(3, 0.0);
  for (int id = 0; id < patches; ++id)
    for (int k = 0; k < 3; ++k) serial[k] += patch_values(id)[k];
  // Round-robin ownership (the worst case for order: neighbours on other ranks).
  std::vector<PatchPartial> mine;
  for (int id = patches - 1; id >= 0; --id)
    if (id % r.size == r.rank) mine.push_back({id, patch_values(id)});
  const std::vector<double> global = ordered_patch_sum(mine, 3);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(global[k], serial[k]) << "component " << k << " rank " << r.rank;
}

TEST(MpiReductions, EveryRankComputesTheSameAssignment) {
  const Ranks r = world_ranks();
  Grid g;
  g.cells = IntVec3(8, 4, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j)
      g.patches.push_back(Patch{int(g.patches.size()), IntVec3(2 * i, 2 * j, 0), IntVec3(2 * i + 2, 2 * j + 2, 4)});
  std::vector<long long> particles(g.patches.size());
  for (std::size_t p = 0; p < particles.size(); ++p) particles[p] = 10 * (long long)(p * p);
  const RankAssignment a = assign_patches(g, particles, r.size, LoadWeights{1.0, 0.5});
  std::vector<double> owners(a.owner.begin(), a.owner.end());
  const std::vector<double> all = all_gather(owners);
  ASSERT_EQ(all.size(), owners.size() * r.size);
  for (int q = 0; q < r.size; ++q)
    for (std::size_t p = 0; p < owners.size(); ++p) EXPECT_EQ(all[q * owners.size() + p], owners[p]);
  // Each rank owns at least one patch.
  for (int q = 0; q < r.size; ++q)
    EXPECT_NE(std::count(a.owner.begin(), a.owner.end(), q), 0) << "rank " << q;
}

TEST(MpiReductions, LaunchedRankCountMatchesTheWorld) {
  EXPECT_EQ(launched_rank_count(), world_ranks().size);
}

}  // namespace
}  // namespace tephra
