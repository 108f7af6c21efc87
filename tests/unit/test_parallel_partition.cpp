// Patch-to-rank assignment and the ordered global sum on one process
// (core/parallel; issue 7). The multi-rank checks are in tests/mpi/.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include "core/parallel/LoadBalancer.h"
#include "core/parallel/OrderedReduction.h"

namespace tephra {
namespace {

// Brute-force optimum of the contiguous min-max partition: every way of
// cutting n weights (in order) into at most `ranks` non-empty runs.
double best_max_run(const std::vector<double>& w, int ranks) {
  const int n = static_cast<int>(w.size());
  double best = 1e300;
  // cut mask: bit k set = a run ends after element k (k < n-1)
  for (int mask = 0; mask < (1 << (n - 1)); ++mask) {
    if (__builtin_popcount(mask) + 1 > ranks) continue;
    double run = 0.0, worst = 0.0;
    for (int k = 0; k < n; ++k) {
      run += w[k];
      if (k == n - 1 || (mask >> k & 1)) {
        worst = std::max(worst, run);
        run = 0.0;
      }
    }
    best = std::min(best, worst);
  }
  return best;
}

TEST(LoadBalancer, ContiguousPartitionIsOptimalAndGivesEveryRankAPatch) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.1, 10.0);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + trial % 12;
    const int ranks = 1 + trial % 4;
    std::vector<double> w(n);
    for (double& x : w) x = u(gen);
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    const std::vector<int> owner = partition_contiguous(w, order, ranks);
    std::vector<double> cost(ranks, 0.0);
    for (int k = 0; k < n; ++k) {
      cost[owner[k]] += w[k];
      if (k > 0) {  // contiguous and non-decreasing along the order
        EXPECT_GE(owner[k], owner[k - 1]);
        EXPECT_LE(owner[k], owner[k - 1] + 1);
      }
    }
    EXPECT_EQ(owner[0], 0);
    if (n >= ranks) EXPECT_EQ(owner[n - 1], ranks - 1) << "a rank without a patch";
    const double worst = *std::max_element(cost.begin(), cost.end());
    // The bisection stops at a relative capacity gap of 1e-12.
    EXPECT_LE(worst, best_max_run(w, ranks) * (1 + 1e-9)) << "trial " << trial;
  }
}

Grid patch_grid(int px, int py, int pz, int cells_per_patch) {
  Grid g;
  g.cells = IntVec3(px, py, pz) * cells_per_patch;
  int id = 0;
  for (int k = 0; k < pz; ++k)
    for (int j = 0; j < py; ++j)
      for (int i = 0; i < px; ++i) {
        const IntVec3 lo = IntVec3(i, j, k) * cells_per_patch;
        g.patches.push_back(Patch{id++, lo, lo + IntVec3::Constant(cells_per_patch)});
      }
  return g;
}

TEST(LoadBalancer, MortonOrderVisitsOctantsInZOrder) {
  const Grid g = patch_grid(2, 2, 2, 4);  // patch ids are x-fastest, as Morton at this level
  const std::vector<int> order = morton_patch_order(g);
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  const Grid h = patch_grid(4, 1, 1, 2);  // along x only: 0,1,2,3
  EXPECT_EQ(morton_patch_order(h), (std::vector<int>{0, 1, 2, 3}));
  // 4 x 4 in the plane: Z-order visits the 2x2 quadrant (ids 0,1,4,5) first.
  const Grid q = patch_grid(4, 4, 1, 2);
  const std::vector<int> oq = morton_patch_order(q);
  EXPECT_EQ(std::vector<int>(oq.begin(), oq.begin() + 4), (std::vector<int>{0, 1, 4, 5}));
}

TEST(LoadBalancer, ParticlesWeighThePatchesTheyFill) {
  // 8 equal patches of 64 cells; all particles in patch 0. With a particle
  // weight of 1 cell and 448 particles, patch 0 costs 512 and the other seven
  // 448 together: the best two-rank split is {0} | {1..7} (max 512, mean 480).
  const Grid g = patch_grid(2, 2, 2, 4);
  std::vector<long long> particles(8, 0);
  particles[0] = 448;
  const RankAssignment a = assign_patches(g, particles, 2, LoadWeights{1.0, 1.0});
  EXPECT_EQ(a.owner, (std::vector<int>{0, 1, 1, 1, 1, 1, 1, 1}));
  EXPECT_DOUBLE_EQ(a.rank_cost[0], 512.0);
  EXPECT_DOUBLE_EQ(a.rank_cost[1], 448.0);
  EXPECT_NEAR(a.imbalance(), 512.0 / 480.0, 1e-15);
  // Cells only: 4 and 4 patches, perfectly balanced.
  const RankAssignment b = assign_patches(g, {}, 2);
  EXPECT_EQ(b.owner, (std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_DOUBLE_EQ(b.imbalance(), 1.0);
}

TEST(OrderedReduction, SumsInPatchIdOrderWhateverTheInputOrder) {
  // Addition order matters for these values: ((1e16 + 1) + 1) - 1e16 = 0 but
  // the id order 0,1,2,3 below gives (((1e16) + 1) + -1e16) + 1 = 1.
  std::vector<PatchPartial> parts{{0, {1e16}}, {1, {1.0}}, {2, {-1e16}}, {3, {1.0}}};
  const double in_id_order = ((1e16 + 1.0) + -1e16) + 1.0;
  std::vector<int> perm{0, 1, 2, 3};
  do {
    std::vector<PatchPartial> shuffled;
    for (int i : perm) shuffled.push_back(parts[i]);
    EXPECT_EQ(ordered_patch_sum(shuffled, 1)[0], in_id_order);
  } while (std::next_permutation(perm.begin(), perm.end()));
  EXPECT_EQ(patch_max(parts, 1)[0], 1e16);
  EXPECT_EQ(patch_min(parts, 1)[0], -1e16);
}

TEST(OrderedReduction, RejectsMismatchedWidthsAndDuplicatePatches) {
  EXPECT_THROW(ordered_patch_sum({{0, {1.0, 2.0}}}, 1), std::invalid_argument);
  EXPECT_THROW(ordered_patch_sum({{0, {1.0}}, {0, {2.0}}}, 1), std::invalid_argument);
  EXPECT_EQ(ordered_patch_sum({}, 2), (std::vector<double>{0.0, 0.0}));
}

}  // namespace
}  // namespace tephra
