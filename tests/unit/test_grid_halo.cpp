// Halo exchange on one process. Oracle: fill what each patch owns with a
// function f of the GLOBAL index, exchange, and every ghost must equal f at
// that index (wrapped into the domain in periodic directions); ghosts beyond
// the extra cells of a non-periodic face have no owner and keep their value.
// Node accumulation: each patch adds a known amount to its nodes; a node ends
// with that amount times the number of patch copies of it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/grid/Fields.h"
#include "core/grid/Grid.h"
#include "core/grid/HaloExchange.h"

using namespace tephra;

namespace {

constexpr double kUntouched = -12345.0;

Grid patched_grid(IntVec3 cells, IntVec3 patches, IntVec3 extra, IntVec3 periodic) {
  Grid g;
  g.cells = cells;
  g.extra_cells = extra;
  g.periodic = periodic;
  std::vector<int> cut[3];
  for (int d = 0; d < 3; ++d) cut[d] = split_evenly(cells[d], patches[d]);
  for (int pk = 0; pk < patches[2]; ++pk)
    for (int pj = 0; pj < patches[1]; ++pj)
      for (int pi = 0; pi < patches[0]; ++pi) {
        Patch p;
        p.id = int(g.patches.size());
        p.lo = IntVec3(cut[0][pi], cut[1][pj], cut[2][pk]);
        p.hi = IntVec3(cut[0][pi + 1], cut[1][pj + 1], cut[2][pk + 1]);
        g.patches.push_back(p);
      }
  g.set_patch_extra_cells();
  g.index_patches();
  return g;
}

int wrap(int c, int n) { return ((c % n) + n) % n; }

// The level index a stored index stands for, or false if it has no owner.
// Cells exist for -extra <= c < cells + extra; nodes up to cells + extra.
bool level_index(const Grid& g, const IntVec3& c, int node_extra, IntVec3& s) {
  for (int d = 0; d < 3; ++d) {
    if (g.periodic[d]) {
      s[d] = wrap(c[d], g.cells[d]);
    } else {
      if (c[d] < -g.extra_cells[d] || c[d] >= g.cells[d] + g.extra_cells[d] + node_extra) return false;
      s[d] = c[d];
    }
  }
  return true;
}

double f(const IntVec3& s) { return std::sin(0.3 * s[0] + 1.0) + 10.0 * s[1] + 1000.0 * s[2]; }
Vec3 fv(const IntVec3& s) { return Vec3(s[0], 10.0 * s[1] - 3.0, std::cos(0.7 * s[2])); }

template <class FieldT, class Fn>
void check_exchange(const Grid& g, int ghosts, int node_extra, Fn fn) {
  using T = typename FieldT::value_type;
  PatchFields<FieldT> pf(g, ghosts);
  const T untouched = fn(IntVec3(-100, -100, -100));
  for (auto& field : pf) {
    const IndexRange r = field.with_ghosts();
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) {
          IntVec3 s;
          const bool owned = field.with_extra().contains(i, j, k);
          // Owned entries hold f of the level index (periodic node `cells`
          // is node 0); the rest starts as a marker.
          field(i, j, k) = owned && level_index(g, IntVec3(i, j, k), node_extra, s) ? fn(s) : untouched;
        }
  }
  LocalHaloExchange halo(g);
  halo.exchange(pf);
  long long ghosts_filled = 0, ghosts_unowned = 0;
  for (auto& field : pf) {
    const IndexRange r = field.with_ghosts();
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) {
          const IntVec3 c(i, j, k);
          IntVec3 s;
          if (level_index(g, c, node_extra, s)) {
            ASSERT_EQ(field(c), fn(s)) << "patch " << field.patch_id() << " index " << c.transpose();
            if (!field.with_extra().contains(c)) ++ghosts_filled;
          } else {
            ASSERT_EQ(field(c), untouched) << "patch " << field.patch_id() << " index " << c.transpose();
            ++ghosts_unowned;
          }
        }
  }
  EXPECT_GT(ghosts_filled, 0);
  (void)ghosts_unowned;
}

}  // namespace

TEST(GridHalo, CellGhostsFromNeighbours2x2x2) {
  Grid g = patched_grid(IntVec3(8, 6, 5), IntVec3(2, 2, 2), IntVec3(1, 1, 1), IntVec3::Zero());
  check_exchange<CellField<double>>(g, 1, 0, f);
  check_exchange<CellField<double>>(g, 2, 0, f);  // ghosts beyond the extra cells stay untouched
  check_exchange<CellField<Vec3>>(g, 1, 0, fv);
  // The rate-stick layout (patches [4,1,1] of unequal length along x, two
  // ghost layers): a row's ghosts come from several patches in turn (the
  // exchange reuses a row's last owner while the index stays in its box).
  Grid rows = patched_grid(IntVec3(13, 3, 2), IntVec3(4, 1, 1), IntVec3(1, 1, 1), IntVec3::Zero());
  check_exchange<CellField<double>>(rows, 2, 0, f);
}

TEST(GridHalo, CellGhostsWithPeriodicWrap) {
  // Periodic in x and z (no extra cells there), walls with extra cells in y.
  Grid g = patched_grid(IntVec3(6, 4, 5), IntVec3(2, 2, 2), IntVec3(0, 1, 0), IntVec3(1, 0, 1));
  check_exchange<CellField<double>>(g, 2, 0, f);
  check_exchange<CellField<Vec3>>(g, 1, 0, fv);
  // One patch: the periodic images come from the patch itself.
  Grid one = patched_grid(IntVec3(5, 3, 4), IntVec3(1, 1, 1), IntVec3::Zero(), IntVec3(1, 1, 1));
  check_exchange<CellField<double>>(one, 2, 0, f);
}

TEST(GridHalo, NodeGhostsFromNeighbours) {
  Grid g = patched_grid(IntVec3(8, 6, 5), IntVec3(2, 2, 2), IntVec3(1, 1, 1), IntVec3::Zero());
  check_exchange<NodeField<double>>(g, 1, 1, f);
  check_exchange<NodeField<Vec3>>(g, 2, 1, fv);
  Grid per = patched_grid(IntVec3(6, 4, 5), IntVec3(2, 2, 2), IntVec3(0, 1, 0), IntVec3(1, 0, 1));
  check_exchange<NodeField<double>>(per, 2, 1, f);
}

namespace {

// Copies of node n along one direction: the number of (patch, stored index)
// pairs whose index stands for n. Patch slabs [b_s, b_{s+1}] hold nodes
// b_s - g .. b_{s+1} + g; in a periodic direction index m stands for m mod N.
int copies_1d(const std::vector<int>& cut, int n, int g, bool periodic, int N) {
  int count = 0;
  for (size_t s = 0; s + 1 < cut.size(); ++s)
    for (int m = cut[s] - g; m <= cut[s + 1] + g; ++m)
      if (periodic ? wrap(m, N) == n : m == n) ++count;
  return count;
}

void check_accumulate(IntVec3 cells, IntVec3 patches, IntVec3 periodic, int ghosts, bool add_to_ghosts) {
  Grid g = patched_grid(cells, patches, IntVec3::Zero(), periodic);
  PatchFields<NodeField<double>> m(g, ghosts);
  PatchFields<NodeField<Vec3>> p(g, ghosts);
  m.fill(0.0);
  p.fill(Vec3::Zero());
  for (size_t n = 0; n < m.size(); ++n) {
    const IndexRange r = add_to_ghosts ? m[n].with_ghosts() : m[n].interior();
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) {
          m[n](i, j, k) += 1.0;
          p[n](i, j, k) += Vec3(1, -2, 0.5);
        }
  }
  LocalHaloExchange halo(g);
  halo.accumulate(m);
  halo.accumulate(p);
  std::vector<int> cut[3];
  for (int d = 0; d < 3; ++d) cut[d] = split_evenly(cells[d], patches[d]);
  const int gw = add_to_ghosts ? ghosts : 0;
  for (size_t n = 0; n < m.size(); ++n) {
    const IndexRange r = m[n].with_ghosts();
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) {
          const IntVec3 c(i, j, k);
          IntVec3 s;
          if (!level_index(g, c, 1, s)) continue;  // beyond the domain: no node
          // Copies factor per direction (tensor-product patch layout).
          double expected = 1.0;
          for (int d = 0; d < 3; ++d) expected *= copies_1d(cut[d], s[d], gw, periodic[d], cells[d]);
          ASSERT_EQ(m[n](c), expected) << "patch " << n << " node " << c.transpose();
          ASSERT_EQ(p[n](c), expected * Vec3(1, -2, 0.5));
        }
  }
}

}  // namespace

TEST(GridHalo, NodeAccumulationCountsPatchesSharingANode) {
  // Each patch adds 1 to its nodes lo..hi: a node on a patch boundary ends
  // with the number of patches touching it (2 on a face, 4 on an edge, 8 at
  // a corner of a 2x2x2 layout), every other node with 1.
  check_accumulate(IntVec3(6, 5, 4), IntVec3(2, 2, 2), IntVec3::Zero(), 1, false);
  {
    Grid g = patched_grid(IntVec3(6, 5, 4), IntVec3(2, 2, 2), IntVec3::Zero(), IntVec3::Zero());
    PatchFields<NodeField<double>> m(g, 0);
    m.fill(0.0);
    for (auto& field : m) field.fill(1.0);
    LocalHaloExchange(g).accumulate(m);
    // The node at the centre cut (3, 3, 2) is a corner of all 8 patches.
    for (auto& field : m) EXPECT_EQ(field(3, 3, 2), 8.0);
    EXPECT_EQ(m[0](0, 0, 0), 1.0);
    EXPECT_EQ(m[0](3, 0, 0), 2.0);
    EXPECT_EQ(m[0](3, 3, 0), 4.0);
  }
}

TEST(GridHalo, NodeAccumulationWithPeriodicImagesAndGhostContributions) {
  // Periodic x: node 0 and node `cells` are one node, touched from both ends.
  check_accumulate(IntVec3(6, 5, 4), IntVec3(2, 1, 2), IntVec3(1, 0, 0), 1, false);
  check_accumulate(IntVec3(6, 5, 4), IntVec3(1, 1, 1), IntVec3(1, 1, 1), 0, false);
  // Contributions scattered into ghost nodes reach the owning nodes.
  check_accumulate(IntVec3(6, 5, 4), IntVec3(2, 2, 1), IntVec3::Zero(), 1, true);
  check_accumulate(IntVec3(7, 5, 4), IntVec3(3, 1, 2), IntVec3(1, 0, 1), 2, true);
}
