// The scatter order of the threaded P2G (mpm/shape/ScatterOrder.h) for the
// per-axis stencils (linear, gimp, 3rdorderBS) and the flat ones (gimp and
// cpdi through compute_stencils). Claims, checked from the stencils' nodes:
//   * index is a permutation of the particles, ascending inside each block,
//     and every particle sits in the block of its lowest (y, z) node rows,
//     block = (floor(y0 / w_y), floor(z0 / w_z));
//   * w = footprint - 1 (1 for linear, 2 for gimp / 3rdorderBS, from the
//     largest footprint for cpdi);
//   * the invariant the threading rests on: no node is touched by two
//     blocks of the same colour;
//   * P2G with 1, 2 and 3 threads gives the same bits (cpdi included).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <random>
#include <set>

#include "core/grid/Loop.h"
#include "mpm/Transfers.h"
#include "mpm/shape/AxisStencils.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

struct Cloud {
  NodeGrid g;
  Particles p;
  Cloud() {
    g.origin = Vec3(-1.0, 0.5, 0.0);
    g.h = Vec3(0.1, 0.2, 0.15);
    g.n = IntVec3(14, 16, 18);
    g.reset();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < 6000; ++i) {
      // Nodes 2 .. n-3: every support (cpdi with a sheared domain included) stays on the grid.
      const Vec3 x = g.origin + Vec3((2 + 9 * u(rng)) * g.h[0], (2 + 11 * u(rng)) * g.h[1], (2 + 13 * u(rng)) * g.h[2]);
      Mat3 size = Mat3::Identity() * 0.5;
      size(1, 2) = 0.4 * s(rng);  // cpdi: a sheared domain, footprints up to 4 rows
      p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3 * (0.5 + u(rng)), 300.0, 0.0, i, size);
      p.stress.back() = Mat3::Identity() * 1e3 * s(rng);
    }
  }
};

// Node rows (y, z) of node n.
std::pair<int, int> rows(const NodeGrid& g, std::size_t n) {
  return {int((n / g.n[0]) % g.n[1]), int(n / (std::size_t(g.n[0]) * g.n[1]))};
}

void check_order(const Cloud& c, const Stencils& s, int expected_w_y, int expected_w_z) {
  const ScatterOrder& o = s.order;
  const std::size_t np = c.p.size();
  ASSERT_TRUE(o.built_for(np));
  EXPECT_EQ(o.width_y, expected_w_y);
  EXPECT_EQ(o.width_z, expected_w_z);
  // Permutation, ascending within a block.
  std::vector<int> seen(np, 0);
  for (std::uint32_t i : o.index) ++seen[i];
  for (std::size_t i = 0; i < np; ++i) ASSERT_EQ(seen[i], 1) << "particle " << i;
  ASSERT_EQ(o.colour[0], 0u);
  ASSERT_EQ(o.colour[4] + 1, o.block.size());
  // node -> (colour -> blocks touching it)
  std::map<std::size_t, std::map<int, std::set<long>>> touched;
  visit_stencils(s, [&](const auto& view) {
    for (int colour = 0; colour < 4; ++colour)
      for (std::uint32_t b = o.colour[colour]; b < o.colour[colour + 1]; ++b) {
        long block_id = -1;
        for (std::uint32_t j = o.block[b]; j < o.block[b + 1]; ++j) {
          const std::size_t i = o.index[j];
          if (j > o.block[b]) ASSERT_LT(o.index[j - 1], o.index[j]);
          int y0 = c.g.n[1], z0 = c.g.n[2];
          view.weights(i, [&](std::size_t n, double) {
            y0 = std::min(y0, rows(c.g, n).first);
            z0 = std::min(z0, rows(c.g, n).second);
          });
          const int by = y0 / o.width_y, bz = z0 / o.width_z;
          ASSERT_EQ(by % 2 + 2 * (bz % 2), colour);
          const long id = long(bz) * 100000 + by;
          if (block_id < 0) block_id = id;
          ASSERT_EQ(id, block_id) << "all particles of a block share its (by, bz)";
          view.weights(i, [&](std::size_t n, double) { touched[n][colour].insert(id); });
        }
      }
  });
  std::size_t shared = 0;
  for (const auto& [n, per_colour] : touched)
    for (const auto& [colour, blocks] : per_colour) {
      EXPECT_EQ(blocks.size(), 1u) << "node " << n << " colour " << colour;
      shared += blocks.size() > 1;
    }
  EXPECT_EQ(shared, 0u);
}

NodeGrid p2g(const Cloud& c, const Stencils& s, int threads) {
  ThreadCountScope t(threads);
  NodeGrid g = c.g;
  particles_to_grid(c.p, s, Vec3(0.0, 0.0, -9.81), g);
  compute_internal_force(c.p, s, g);
  return g;
}

void check_threads(const Cloud& c, const Stencils& s) {
  const NodeGrid g1 = p2g(c, s, 1), g2 = p2g(c, s, 2), g3 = p2g(c, s, 3);
  for (const NodeGrid* g : {&g2, &g3}) {
    EXPECT_EQ(g1.mass, g->mass);
    EXPECT_EQ(g1.volume, g->volume);
    EXPECT_EQ(g1.velocity, g->velocity);
    EXPECT_EQ(g1.external_force, g->external_force);
    EXPECT_EQ(g1.stress, g->stress);
    EXPECT_EQ(g1.internal_force, g->internal_force);
  }
}

TEST(MpmScatterOrder, AxisStencils) {
  const Cloud c;
  for (auto [kind, w] : {std::pair{InterpolatorKind::Linear, 1}, std::pair{InterpolatorKind::Gimp, 2},
                         std::pair{InterpolatorKind::QuadraticBspline, 2}}) {
    SCOPED_TRACE(interpolator_name(kind));
    Stencils s;
    ASSERT_TRUE(compute_axis_stencils(c.p, c.g, {kind, 1e10}, s));
    check_order(c, s, w, w);
    check_threads(c, s);
  }
}

TEST(MpmScatterOrder, FlatStencils) {
  const Cloud c;
  {
    SCOPED_TRACE("gimp");
    Stencils s;
    ASSERT_EQ(compute_stencils(c.p, c.g, {InterpolatorKind::Gimp, 1e10}, s), -1);
    check_order(c, s, 2, 2);
    check_threads(c, s);
  }
  {
    SCOPED_TRACE("cpdi");
    Stencils s;
    ASSERT_EQ(compute_stencils(c.p, c.g, {InterpolatorKind::Cpdi, 1e10}, s), -1);
    // The largest footprint over the particles, from the entries themselves.
    int span_y = 1, span_z = 1;
    const std::size_t W = s.width;
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      int ylo = 1 << 30, yhi = -1, zlo = 1 << 30, zhi = -1;
      for (std::size_t k = i * W; k < (i + 1) * W; ++k) {
        const auto [y, z] = rows(c.g, s.node[k]);
        ylo = std::min(ylo, y), yhi = std::max(yhi, y), zlo = std::min(zlo, z), zhi = std::max(zhi, z);
      }
      span_y = std::max(span_y, yhi - ylo + 1);
      span_z = std::max(span_z, zhi - zlo + 1);
    }
    EXPECT_GE(span_y, 3);  // the sheared domains reach beyond the gimp footprint
    check_order(c, s, span_y - 1, span_z - 1);
    check_threads(c, s);
  }
}

}  // namespace
}  // namespace tephra

namespace tephra {
namespace {

// ScatterOrder::sort_blocks_by_id against a reference: inside each block of
// finish()'s order, std::stable_sort by id; displaced = #{j : index[j] != j}.
// Cases cover its shortcut (a block already ascending in id, with and without
// finish() leaving index[j] == j) and the insertion-sort path.
void check_sort_blocks(const std::vector<std::uint32_t>& keys, const std::vector<long long>& id, int threads) {
  ThreadCountScope t(threads);
  ScatterOrder o;
  o.prepare(keys.size(), 8, 8, 2, 2);  // w = 1: 8 x 8 blocks, keys < 4 * 64
  o.key = keys;
  o.finish();
  std::vector<std::uint32_t> expect = o.index;
  for (std::size_t b = 0; b + 1 < o.block.size(); ++b)
    std::stable_sort(expect.begin() + o.block[b], expect.begin() + o.block[b + 1],
                     [&](std::uint32_t a, std::uint32_t c) { return id[a] < id[c]; });
  std::size_t moved = 0;
  for (std::size_t j = 0; j < expect.size(); ++j) moved += expect[j] != j;
  o.sort_blocks_by_id(id.data());
  EXPECT_EQ(o.index, expect);
  EXPECT_EQ(o.displaced, moved);
}

TEST(MpmScatterOrder, SortBlocksByIdIsTheStableSortPerBlock) {
  const std::size_t np = 6000;  // >= 4096: the threaded loop runs with 2 threads
  std::mt19937 rng(11);
  std::vector<std::uint32_t> sorted_keys(np), random_keys(np);
  for (std::size_t i = 0; i < np; ++i) sorted_keys[i] = std::uint32_t(i * 256 / np);  // ascending: index stays identity
  for (auto& k : random_keys) k = std::uint32_t(rng() % 256);
  std::vector<long long> ascending(np), shuffled(np), one_swap(np);
  for (std::size_t i = 0; i < np; ++i) ascending[i] = shuffled[i] = one_swap[i] = 10 + 3 * (long long)i;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  std::swap(one_swap[np / 2], one_swap[np / 2 + 1]);  // one block out of order, the rest ascending
  for (int th : {1, 2}) {
    check_sort_blocks(sorted_keys, ascending, th);   // identity, all ascending: nothing moves
    check_sort_blocks(sorted_keys, one_swap, th);    // identity, one block to sort
    check_sort_blocks(sorted_keys, shuffled, th);    // identity, every block to sort
    check_sort_blocks(random_keys, ascending, th);   // displaced, blocks ascending
    check_sort_blocks(random_keys, shuffled, th);    // displaced, blocks to sort
  }
}

// ScatterOrder::run_start, the threads' split of a colour (session 25). With
// the colour's block starts s_0 < s_1 < ... < s_B (s_B its end) and n
// particles, thread u of T runs [R_u, R_{u+1}) with R_0 = s_0, R_T = s_B and,
// for 0 < u < T, R_u the start nearest to t_u = s_0 + floor(n u / T) (a tie:
// the lower). Claims: (1) the runs tile the colour (every slot, hence every
// block, in exactly one run: R_u non-decreasing, from s_0 to s_B); (2) each
// R_u is a block start; (3) |R_u - t_u| = min_k |s_k - t_u| (nearest); (4)
// for T = 2 the longer run exceeds n/2 by at most half the block holding
// t_1, plus 1/2 for the floor.
void check_runs(const ScatterOrder& o) {
  for (int c = 0; c < 4; ++c) {
    const std::vector<std::uint32_t> starts(o.block.begin() + o.colour[c], o.block.begin() + o.colour[c + 1] + 1);
    const std::size_t s0 = starts.front(), n = starts.back() - s0;
    for (int T = 1; T <= 5; ++T) {
      EXPECT_EQ(o.run_start(c, 0, T), s0);
      EXPECT_EQ(o.run_start(c, T, T), starts.back());
      for (int u = 1; u <= T; ++u) EXPECT_LE(o.run_start(c, u - 1, T), o.run_start(c, u, T)) << c << " " << u << "/" << T;
      for (int u = 1; u < T; ++u) {
        const std::uint32_t R = o.run_start(c, u, T);
        EXPECT_TRUE(std::binary_search(starts.begin(), starts.end(), R)) << "not a block start";
        const long target = long(s0 + n * std::size_t(u) / std::size_t(T));
        long best = -1, best_d = -1;
        for (std::uint32_t st : starts)  // the first of the nearest (ascending starts: a tie keeps the lower)
          if (best_d < 0 || std::labs(long(st) - target) < best_d) best = st, best_d = std::labs(long(st) - target);
        EXPECT_EQ(long(R), best) << "colour " << c << " u " << u << "/" << T << " target " << target;
      }
    }
    // T = 2: the balance bound.
    const std::size_t target = s0 + n / 2;
    std::size_t holding = 0;  // the block holding the target (0 when the target is a start)
    for (std::size_t k = 0; k + 1 < starts.size(); ++k)
      if (starts[k] < target && target < starts[k + 1]) holding = starts[k + 1] - starts[k];
    const std::size_t R = o.run_start(c, 1, 2);
    const double longer = double(std::max(R - s0, starts.back() - R));
    EXPECT_LE(longer, 0.5 * double(n) + 0.5 * double(holding) + 0.5) << "colour " << c;
  }
}

TEST(MpmScatterOrder, RunStartsAreTheNearestBlockStarts) {
  // Hand-made: colour 0 blocks of 55, 20, 45 particles (starts 0, 55, 75; end
  // 120); T = 2: target 60, nearest start 55 (the first start >= 60, 75, gave
  // runs of 75 and 45); colour 1 empty; colour 2 one block of 7; colour 3
  // blocks 10, 10 (target 127 + 10 = 137 is a start: runs of 10 and 10).
  ScatterOrder o;
  o.block = {0, 55, 75, 120, 127, 137, 147};  // the last entry: np
  o.colour = {0, 3, 3, 4, 6};
  o.particles = 147;
  o.index.resize(147);
  for (std::uint32_t j = 0; j < 147; ++j) o.index[j] = j;
  EXPECT_EQ(o.run_start(0, 1, 2), 55u);
  EXPECT_EQ(o.run_start(1, 1, 2), 120u);  // empty colour: both runs empty
  EXPECT_EQ(o.run_start(2, 1, 2), 120u);  // one block: target 123.5 -> 123, nearer 120 than 127
  EXPECT_EQ(o.run_start(3, 1, 2), 137u);
  // A tie: blocks 50, 20, 50 (starts 0, 50, 70; end 120): target 60, 50 and 70 at 10: the lower.
  ScatterOrder tie;
  tie.block = {0, 50, 70, 120};
  tie.colour = {0, 3, 3, 3, 3};
  tie.particles = 120;
  EXPECT_EQ(tie.run_start(0, 1, 2), 50u);
  check_runs(o);
  check_runs(tie);
  // Random block sizes (1 .. 2000, some colours with one block), and the
  // orders of the cloud's stencils (linear, gimp).
  std::mt19937 rng(25);
  for (int trial = 0; trial < 200; ++trial) {
    ScatterOrder r;
    std::uint32_t at = 0;
    for (int c = 0; c < 4; ++c) {
      r.colour[std::size_t(c)] = std::uint32_t(r.block.size());
      const int blocks = int(rng() % (trial % 7 == 0 ? 2 : 40));
      for (int b = 0; b < blocks; ++b) {
        r.block.push_back(at);
        at += 1 + std::uint32_t(rng() % 2000);
      }
    }
    r.colour[4] = std::uint32_t(r.block.size());
    r.block.push_back(at);
    r.particles = at;
    check_runs(r);
  }
  Cloud cloud;
  Stencils s;
  for (InterpolatorKind k : {InterpolatorKind::Linear, InterpolatorKind::Gimp}) {
    InterpolatorSpec spec;
    spec.kind = k;
    ASSERT_TRUE(compute_axis_stencils(cloud.p, cloud.g, spec, s));
    check_runs(s.order);
  }
}

}  // namespace
}  // namespace tephra
