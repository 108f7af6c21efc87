// The band reduce of mpm/PatchBand.h is collective on ranks (one
// MPI_Allgatherv per scatter): every rank must call it at every scatter,
// whether it has particles, patches or work to do (issue 7: with fewer
// patches than ranks, a deck hung on 4 ranks when one rank left a band
// scatter early while the others waited in the gather).
//
// The MUSL scatter of the needed nodes (updated_particle_grid_velocity_at,
// mpm/UpdatedGridVelocity.h) decides "no needed node: nothing to do" on each
// rank's own flags. The flags come from V_g, which a rank holds summed over
// the ranks inside its node box and as 0 outside. A rank whose box is the
// whole grid (its particles fill it) can have no needed node while a rank
// without patches (empty box: V_g = 0 everywhere) needs every node.
//
// Set-up here, on 1, 2 and 4 ranks: a 8 x 4 x 4 cell level cut into [2,1,1]
// patches, owner(P) = min(P, max(size - 2, 0)): on 2 ranks both patches on
// rank 0 and rank 1 empty; on 4 ranks one patch on each of ranks 0 and 1,
// ranks 2 and 3 empty. Each rank keeps its patches' particles of a random
// cloud. Needed flags as the runs give them in that case: none on a rank that
// owns a patch (filled box), all on a rank without one.
// Expected: the call returns on every rank (ctest mpi_np4_band has a 120 s
// TIMEOUT: before the fix the patch owners returned at once and the empty
// ranks waited in the gather for ever), and the result is the one-process
// answer, v = 0 at every node: no particle reaches a needed node anywhere
// (the owners need none; the empty ranks have no particles), so every sum,
// band sums included, is 0 + 0 + ... = 0.
// A second call on the same band, with the needed flags of a normal step
// (all nodes on every rank), checks that the ranks stayed in step: its band
// sums equal the one-process band run bit for bit at every band node. The
// exchange carries only the pairs that hold a non-zero value: none in the
// first call, some (at most the band's pairs) in the second.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/parallel/Ranks.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/PatchBand.h"
#include "mpm/UpdatedGridVelocity.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {
namespace {

Grid two_patch_level() {
  Grid L;
  L.lower = Vec3(0.0, 0.0, 0.0);
  L.dx = Vec3(0.125, 0.125, 0.125);
  L.cells = IntVec3(8, 4, 4);
  L.upper = L.lower + Vec3(1.0, 0.5, 0.5);
  L.extra_cells = IntVec3(1, 1, 1);
  for (int a = 0; a < 2; ++a) {
    Patch p;
    p.id = a;
    p.lo = IntVec3(4 * a, 0, 0);
    p.hi = IntVec3(4 * (a + 1), 4, 4);
    L.patches.push_back(p);
  }
  L.set_patch_extra_cells();
  L.index_patches();
  return L;
}

NodeGrid node_grid(const Grid& L) {
  NodeGrid g;
  g.origin = L.lower - L.dx;
  g.h = L.dx;
  g.n = L.cells + IntVec3(3, 3, 3);
  g.extra = IntVec3(1, 1, 1);
  g.reset();
  return g;
}

// The patch of the nearest interior cell (MpmComponent::patch_of).
int patch_of(const Grid& L, const Vec3& x) {
  IntVec3 c;
  for (int d = 0; d < 3; ++d) c[d] = std::clamp(int(std::floor((x[d] - L.lower[d]) / L.dx[d])), 0, L.cells[d] - 1);
  return L.patch_owning_cell(c);
}

// 400 particles over the interior (every rank draws the same cloud), those of
// the patches `keep` accepts.
template <class Keep>
Particles cloud(const Grid& L, Keep&& keep) {
  Particles p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 400; ++i) {
    const Vec3 x = L.lower + Vec3((0.5 + 7 * u(rng)) * L.dx[0], (0.5 + 3 * u(rng)) * L.dx[1], (0.5 + 3 * u(rng)) * L.dx[2]);
    const Vec3 v(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
    const double m = 0.5 + u(rng);
    if (keep(patch_of(L, x))) p.add(x, v, m, 1e-3, 300.0, 0.0, 100 + i, Mat3::Identity() * 0.5);
  }
  return p;
}

struct Band {
  Stencils s;
  PatchBand band;
};

void build(const Particles& p, const NodeGrid& g, const Grid& L, Band& b) {
  ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, b.s));
  b.s.order.sort_blocks_by_id(p.id.data());
  b.band.prepare(L, g, 3);  // gimp: the reach MpmComponent::prepare_band uses (span 3, minus 1, plus 1)
  ASSERT_TRUE(b.band.active());
}

TEST(MpiBandCollective, MuslScatterWithoutNeededNodesStillTakesPartInTheBandReduce) {
  const Ranks r = world_ranks();
  const Grid L = two_patch_level();
  NodeGrid g = node_grid(L);
  for (std::size_t n = 0; n < g.count(); ++n) {
    g.mass[n] = 1.0 + 0.01 * double(n % 7);  // m_g > 0: v = (m v)_g / m_g at needed nodes
    g.acceleration[n] = Vec3(0.1, -0.2, 0.3);
  }
  const std::vector<int> owner = {0, std::min(1, std::max(r.size - 2, 0))};
  const bool owns = owner[0] == r.rank || owner[1] == r.rank;
  const Particles mine = cloud(L, [&](int P) { return owner[std::size_t(P)] == r.rank; });
  Band b;
  build(mine, g, L, b);
  if (r.size > 1) b.band.set_ranks(owner, r.rank, [](const std::vector<double>& v) { return all_gather(v); });
  const double dt = 1e-3;

  // 1. The hang case: owners need no node, ranks without patches need all.
  std::vector<unsigned char> needed(g.count(), owns ? 0 : 1);
  std::vector<Vec3> out;
  updated_particle_grid_velocity_at(mine, b.s, g, dt, needed, out, &b.band);
  double largest = 0;
  for (const Vec3& v : out) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  EXPECT_EQ(largest, 0.0) << "no particle reaches a needed node: v = 0 everywhere (rank " << r.rank << ")";
  // The exchange sends only pairs with a non-zero value (PatchBand::reduce): none here.
  EXPECT_EQ(b.band.sent_records(), 0u);

  // 2. Still in step: every node needed on every rank; the band nodes hold the
  //    ordered sums of all patches = the one-process band run's bits.
  std::fill(needed.begin(), needed.end(), 1);
  updated_particle_grid_velocity_at(mine, b.s, g, dt, needed, out, &b.band);
  const Particles all = cloud(L, [](int) { return true; });
  Band one;
  build(all, g, L, one);
  std::vector<Vec3> ref;
  updated_particle_grid_velocity_at(all, one.s, g, dt, needed, ref, &one.band);
  std::size_t differ = 0;
  for (std::size_t gi : b.band.band_node_index()) differ += out[gi] != ref[gi];
  EXPECT_GT(b.band.band_nodes(), 0u);
  EXPECT_EQ(differ, 0u) << "band nodes whose ordered sum differs from the one-process run (rank " << r.rank << ")";
  // Now the owners' particles reach band nodes: records travel (on ranks),
  // fewer than the band's pairs (only the reached ones).
  double sent = 0;
  for (double n : all_gather({double(b.band.sent_records())})) sent += n;
  if (r.size > 1) {
    EXPECT_GT(sent, 0.0);
    EXPECT_LE(sent, double(b.band.pairs()));
  }
}

}  // namespace
}  // namespace tephra
