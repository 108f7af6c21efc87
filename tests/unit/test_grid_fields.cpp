// Field indexing identities: global (i,j,k) <-> storage position is a
// bijection; node ranges have one more entry than cells; face ranges one more
// along their direction; ghost and extra layers have the stated width.
#include <gtest/gtest.h>

#include <set>

#include "core/grid/Fields.h"
#include "core/grid/Grid.h"

using namespace tephra;

namespace {

// An 8x6x4 grid, 2x2x1 patches, extraCells 1 in x only, built by hand.
Grid test_grid() {
  Grid g;
  g.cells = IntVec3(8, 6, 4);
  g.extra_cells = IntVec3(1, 0, 0);
  int id = 0;
  for (int pj = 0; pj < 2; ++pj)
    for (int pi = 0; pi < 2; ++pi) {
      Patch p;
      p.id = id++;
      p.lo = IntVec3(4 * pi, 3 * pj, 0);
      p.hi = IntVec3(4 * pi + 4, 3 * pj + 3, 4);
      g.patches.push_back(p);
    }
  g.set_patch_extra_cells();
  g.index_patches();
  return g;
}

template <class F>
void expect_bijective_storage(F& f) {
  // Every stored index maps to a distinct position in [0, size), and the
  // value written through (i,j,k) is read back at that position.
  std::set<size_t> seen;
  const IndexRange r = f.with_ghosts();
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      for (int i = r.lo[0]; i < r.hi[0]; ++i) {
        const size_t o = f.offset(i, j, k);
        ASSERT_LT(o, f.size());
        ASSERT_TRUE(seen.insert(o).second);
        f(i, j, k) = 1000000.0 * k + 1000.0 * j + i;
        ASSERT_EQ(f.data()[o], 1000000.0 * k + 1000.0 * j + i);
      }
  EXPECT_EQ(seen.size(), f.size());
  EXPECT_EQ(static_cast<long long>(f.size()), r.size());
}

}  // namespace

TEST(GridFields, CellFieldRangesAndIndexing) {
  Grid g = test_grid();
  const Patch& p = g.patches[0];  // cells [0,4)x[0,3)x[0,4), touches x- (extra cell at i = -1)
  CellField<double> f(p, 2);
  EXPECT_EQ(f.interior(), (IndexRange{IntVec3(0, 0, 0), IntVec3(4, 3, 4)}));
  EXPECT_EQ(f.with_extra(), (IndexRange{IntVec3(-1, 0, 0), IntVec3(4, 3, 4)}));
  EXPECT_EQ(f.with_ghosts(), (IndexRange{IntVec3(-2, -2, -2), IntVec3(6, 5, 6)}));
  EXPECT_EQ(f.ghost_width(), 2);
  expect_bijective_storage(f);
  f.fill(3.5);
  EXPECT_EQ(f(-2, -2, -2), 3.5);
  EXPECT_EQ(f(5, 4, 5), 3.5);
}

TEST(GridFields, NodeFieldHasOneMoreNodeThanCells) {
  Grid g = test_grid();
  for (const Patch& p : g.patches) {
    NodeField<double> n(p, 0);
    // nodes lo..hi inclusive: extent = cells + 1 in every direction
    EXPECT_EQ(n.interior().extent(), p.num_cells() + IntVec3::Ones());
    EXPECT_EQ(n.interior().lo, p.lo);
    expect_bijective_storage(n);
  }
  NodeField<double> n1(g.patches[1], 1);  // x+ patch: extra cell at i = 8, so nodes up to 9
  EXPECT_EQ(n1.with_extra(), (IndexRange{IntVec3(4, 0, 0), IntVec3(10, 4, 5)}));
  EXPECT_EQ(n1.with_ghosts(), (IndexRange{IntVec3(3, -1, -1), IntVec3(10, 5, 6)}));
}

TEST(GridFields, FaceFieldsHaveOneMoreFaceAlongTheirDirection) {
  Grid g = test_grid();
  const Patch& p = g.patches[3];
  FaceField<double, 0> fx(p, 1);
  FaceField<double, 1> fy(p, 1);
  FaceField<double, 2> fz(p, 1);
  EXPECT_EQ(fx.interior().extent(), p.num_cells() + IntVec3(1, 0, 0));
  EXPECT_EQ(fy.interior().extent(), p.num_cells() + IntVec3(0, 1, 0));
  EXPECT_EQ(fz.interior().extent(), p.num_cells() + IntVec3(0, 0, 1));
  EXPECT_EQ((FaceField<double, 1>::location), FieldLocation::FaceY);
  expect_bijective_storage(fx);
  expect_bijective_storage(fy);
  expect_bijective_storage(fz);
}

TEST(GridFields, PatchFieldsHoldOneFieldPerPatch) {
  Grid g = test_grid();
  PatchFields<CellField<Vec3>> v(g, 1);
  ASSERT_EQ(v.size(), g.patches.size());
  v.fill(Vec3(1, 2, 3));
  long long interior = 0;
  for (size_t n = 0; n < v.size(); ++n) {
    EXPECT_EQ(v[n].patch_id(), g.patches[n].id);
    EXPECT_EQ(v[n].interior(), g.patches[n].cells());
    interior += v[n].interior().size();
    EXPECT_EQ(v[n](g.patches[n].lo), Vec3(1, 2, 3));
  }
  EXPECT_EQ(interior, g.num_interior_cells());
}
