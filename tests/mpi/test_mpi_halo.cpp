// MpiHaloExchange gives LocalHaloExchange's fields bit for bit (issue 7): the
// one-process exchange on all patches is the reference, computed on every
// rank; the MPI exchange runs on each rank's own patches (round-robin owners,
// so every patch face is a rank boundary) and every stored entry is compared
// with EXPECT_EQ. Cells and nodes, double and Vec3, ghost widths 1 and 2,
// with and without a periodic direction; node accumulation (MPM P2G sums)
// must add the copies in the one-process order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "core/grid/HaloExchange.h"
#include "core/grid/Loop.h"
#include "core/grid/MpiHaloExchange.h"
#include "core/parallel/Ranks.h"

namespace tephra {
namespace {

Grid test_grid(bool periodic_x) {
  Grid g;
  g.cells = IntVec3(8, 6, 4);
  g.dx = Vec3::Constant(0.1);
  g.extra_cells = IntVec3(periodic_x ? 0 : 1, 1, 1);
  g.periodic = IntVec3(periodic_x ? 1 : 0, 0, 0);
  int id = 0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {  // 3 x 2 patches of uneven widths 3, 3, 2 and 3, 3
      const int x0[4] = {0, 3, 6, 8};
      g.patches.push_back(Patch{id++, IntVec3(x0[i], 3 * j, 0), IntVec3(x0[i + 1], 3 * j + 3, 4)});
    }
  g.set_patch_extra_cells();
  g.index_patches();
  return g;
}

// A value that depends on everything that names an entry.
double code(int patch, int i, int j, int k, int c) {
  std::uint64_t h = 1469598103934665603ull;
  for (int v : {patch, i, j, k, c}) h = (h ^ std::uint64_t(v + 1000)) * 1099511628211ull;
  return double(h % 1000003) / 7.0 - 5e4;
}
void set(double& v, double a, double, double) { v = a; }
void set(Vec3& v, double a, double b, double c) { v = Vec3(a, b, c); }

template <class FieldT>
void fill(PatchFields<FieldT>& pf, bool ghosts_too) {
  for (size_t n = 0; n < pf.size(); ++n) {
    FieldT& f = pf[n];
    const int p = pf.patch_index(n);
    const IndexRange all = f.with_ghosts(), own = f.with_extra();
    for (int k = all.lo[2]; k < all.hi[2]; ++k)
      for (int j = all.lo[1]; j < all.hi[1]; ++j)
        for (int i = all.lo[0]; i < all.hi[0]; ++i) {
          // Owned entries: a function of the level index only (what the
          // owner computed); ghosts: junk that depends on the patch.
          const bool owned = own.contains(i, j, k) && !ghosts_too;
          const int tag = owned ? -1 : p;
          set(f(i, j, k), code(tag, i, j, k, 0), code(tag, i, j, k, 1), code(tag, i, j, k, 2));
        }
  }
}

template <class FieldT>
void expect_same(const PatchFields<FieldT>& mine, const PatchFields<FieldT>& reference) {
  for (size_t n = 0; n < mine.size(); ++n) {
    const FieldT& f = mine[n];
    const FieldT& ref = reference[size_t(mine.patch_index(n))];
    ASSERT_EQ(f.size(), ref.size());
    int bad = 0;
    for (size_t e = 0; e < f.size(); ++e)
      if (!(f.data()[e] == ref.data()[e])) ++bad;
    EXPECT_EQ(bad, 0) << "patch " << mine.patch_index(n) << " differs in " << bad << " of " << f.size()
                      << " entries";
  }
}

template <class FieldT>
void check(bool periodic_x, int ghosts, bool accumulate) {
  const Grid g = test_grid(periodic_x);
  const Ranks r = world_ranks();
  std::vector<int> owner(g.patches.size());
  for (size_t p = 0; p < owner.size(); ++p) owner[p] = int(p) % r.size;
  MpiHaloExchange mpi(g, owner);
  LocalHaloExchange local(g);
  PatchFields<FieldT> all(g, ghosts);
  PatchFields<FieldT> mine(g, ghosts, mpi.own_patches());
  fill(all, accumulate);
  fill(mine, accumulate);
  if constexpr (FieldT::location == FieldLocation::Node) {
    if (accumulate) {
      local.accumulate(all);
      mpi.accumulate(mine);
      expect_same(mine, all);
      mpi.accumulate(mine);  // second call reuses the plan
      local.accumulate(all);
      expect_same(mine, all);
      return;
    }
  }
  local.exchange(all);
  mpi.exchange(mine);
  expect_same(mine, all);
}

TEST(MpiHalo, CellExchangeEqualsOneProcess) {
  for (bool periodic : {false, true})
    for (int gw : {1, 2}) {
      SCOPED_TRACE(::testing::Message() << "periodic " << periodic << " ghosts " << gw);
      check<CellField<double>>(periodic, gw, false);
      check<CellField<Vec3>>(periodic, gw, false);
    }
}

TEST(MpiHalo, NodeExchangeEqualsOneProcess) {
  for (bool periodic : {false, true})
    for (int gw : {1, 2}) {
      SCOPED_TRACE(::testing::Message() << "periodic " << periodic << " ghosts " << gw);
      check<NodeField<double>>(periodic, gw, false);
      check<NodeField<Vec3>>(periodic, gw, false);
    }
}

TEST(MpiHalo, NodeAccumulateEqualsOneProcessBitForBit) {
  for (bool periodic : {false, true})
    for (int gw : {1, 2}) {
      SCOPED_TRACE(::testing::Message() << "periodic " << periodic << " ghosts " << gw);
      check<NodeField<double>>(periodic, gw, true);
      check<NodeField<Vec3>>(periodic, gw, true);
    }
}

// A batch of three cell fields (two ghost widths, double and Vec3) filled by
// one begin/finish: the ghosts equal LocalHaloExchange's field by field, bit
// for bit; the batch is one message round (one call in the traffic counter,
// at most one message per peer rank, against three calls field by field);
// owned values overwritten between begin and finish do not reach the ghosts
// (they were sent at begin). Mutations: unpacking the fields in the reverse
// order, or packing at finish, fail it.
TEST(MpiHalo, CellBatchEqualsOneProcessInOneMessageRound) {
  for (bool periodic : {false, true})
    for (int gw : {1, 2}) {
      SCOPED_TRACE(::testing::Message() << "periodic " << periodic << " ghosts " << gw);
      const Grid g = test_grid(periodic);
      const Ranks r = world_ranks();
      std::vector<int> owner(g.patches.size());
      for (size_t p = 0; p < owner.size(); ++p) owner[p] = int(p) % r.size;
      MpiHaloExchange mpi(g, owner);
      LocalHaloExchange local(g);
      PatchFields<CellField<double>> a_all(g, gw), b_all(g, 1), a(g, gw, mpi.own_patches()), b(g, 1, mpi.own_patches());
      PatchFields<CellField<Vec3>> v_all(g, gw), v(g, gw, mpi.own_patches());
      fill(a_all, false), fill(b_all, false), fill(v_all, false), fill(a, false), fill(b, false), fill(v, false);
      // b differs from a: scale its owned values (the same on both sides).
      for (auto* pf : {&b_all, &b})
        for (size_t n = 0; n < pf->size(); ++n)
          for (size_t e = 0; e < (*pf)[n].size(); ++e) (*pf)[n].data()[e] *= 3.0;
      local.exchange(a_all), local.exchange(b_all), local.exchange(v_all);
      const PatchFields<CellField<double>> a_begin = a;  // the owned values at begin
      const MpiHaloExchange::Traffic t0 = MpiHaloExchange::traffic();
      CellHaloBatch batch;
      batch.add(a).add(v).add(b);
      mpi.begin_exchange(batch);
      for (size_t n = 0; n < a.size(); ++n)  // work between begin and finish writes owned values
        for_each_cell_serial(a[n].with_extra(), [&](int i, int j, int k) { a[n](i, j, k) = -1.0; });
      mpi.finish_exchange(batch);
      const MpiHaloExchange::Traffic t1 = MpiHaloExchange::traffic();
      EXPECT_EQ(t1.calls - t0.calls, 1);
      EXPECT_LE(t1.messages - t0.messages, r.size - 1);
      // Put the owned values back, then every entry must be the reference's.
      for (size_t n = 0; n < a.size(); ++n) {
        const IndexRange own = a[n].with_extra();
        for_each_cell_serial(own, [&](int i, int j, int k) { a[n](i, j, k) = a_begin[n](i, j, k); });
      }
      expect_same(a, a_all);
      expect_same(b, b_all);
      expect_same(v, v_all);
    }
}

}  // namespace
}  // namespace tephra
