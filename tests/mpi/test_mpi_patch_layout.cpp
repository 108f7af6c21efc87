// core/parallel/PatchLayout and gather_patch_blocks (issue 7): the
// collectives behind ICE's output, checkpoints and reductions on ranks.
// Run under `mpirun -np 1` and `-np 2` (label mpi).
#include <gtest/gtest.h>

#include <cmath>

#include "core/parallel/PatchLayout.h"
#include "core/parallel/Ranks.h"

namespace tephra {
namespace {

// Block of patch p: p + 1 values (uneven sizes; patch 0 empty-free), each
// identifying (p, position).
std::vector<double> block_of(int p) {
  std::vector<double> b;
  for (int k = 0; k <= p; ++k) b.push_back(1000.0 * p + k + 0.25);
  return b;
}

TEST(MpiPatchLayout, GatherPatchBlocksGivesEveryRankEveryBlockInPatchOrder) {
  const Ranks r = world_ranks();
  const int patches = 7;
  std::vector<int> owner(patches), own;
  for (int p = 0; p < patches; ++p) owner[p] = (p * 3) % r.size;  // scattered owners
  std::vector<std::vector<double>> mine;
  for (int p = 0; p < patches; ++p)
    if (owner[p] == r.rank) {
      own.push_back(p);
      mine.push_back(block_of(p));
    }
  const auto all = gather_patch_blocks(owner, own, mine);
  ASSERT_EQ(all.size(), std::size_t(patches));
  for (int p = 0; p < patches; ++p) EXPECT_EQ(all[p], block_of(p)) << "patch " << p << " on rank " << r.rank;
}

TEST(MpiPatchLayout, WorldLayoutSumsAndDecidesAsTheWholeLevel) {
  const Ranks r = world_ranks();
  Grid g;
  g.cells = IntVec3(8, 4, 4);
  for (int i = 0; i < 4; ++i) {
    Patch p;
    p.id = i;
    p.lo = IntVec3(2 * i, 0, 0);
    p.hi = IntVec3(2 * i + 2, 4, 4);
    g.patches.push_back(p);
  }
  g.set_patch_extra_cells();
  g.index_patches();
  const PatchLayout whole = PatchLayout::whole(g), world = PatchLayout::over_world_ranks(g);
  EXPECT_EQ(world.distributed, r.size > 1);
  EXPECT_EQ(world.own_grid().patches.size(), world.own.size());
  // Order-sensitive partials (1e16 cancels only in patch order).
  auto partial = [](int p) { return PatchPartial{p, {(p % 2 ? -1e16 : 1e16) + 0.1 * p, std::sin(p + 1.0)}}; };
  std::vector<PatchPartial> all, mine;
  for (int p = 0; p < 4; ++p) all.push_back(partial(p));
  for (int p : world.own) mine.push_back(partial(p));
  const std::vector<double> a = whole.ordered_sum(all, 2), b = world.ordered_sum(mine, 2);
  EXPECT_EQ(a, b);
  // Serial reference: ((0 + x0) + x1) + x2 + x3.
  double s0 = 0;
  for (int p = 0; p < 4; ++p) s0 += partial(p).values[0];
  EXPECT_EQ(a[0], s0);
  // min / max / any: the same on every rank.
  EXPECT_EQ(world.min(1.0 + r.rank), 1.0);
  EXPECT_EQ(world.max(1.0 + r.rank), double(r.size));
  EXPECT_EQ(world.any(r.rank == r.size - 1), true);
  EXPECT_EQ(world.any(false), false);
}

}  // namespace
}  // namespace tephra
