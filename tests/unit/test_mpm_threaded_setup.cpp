// The serial set-up parts of P2G and the deformation-gradient phase, threaded
// in session 13 (docs/performance.md), against reference loops written here:
//   * ScatterOrder::finish (per-thread counting sort + prefix sums) equals the
//     stable sort of the particle indices by key (std::stable_sort), with the
//     same blocks, colours and `displaced` count, for 1, 2 and 3 threads;
//   * usl_needed_nodes marks exactly the nodes with V_g < limit V_cell or on a
//     node plane within 2 extra of a face (the definition in
//     UpdatedGridVelocity.h, evaluated node by node here) and returns the
//     under-filled count, for 1, 2 and 3 threads;
//   * NodeGrid::reset zeroes every array, sized to count(), for 1 and 2 threads;
//   * velocity_gradients_and_first_order_F (one pass) gives the bits of
//     velocity_gradients + update_deformation_gradients(FirstOrder), for the
//     flat and per-axis (linear, gimp) stencils, with 1 and 2 threads, and
//     first_order_F (no L column, session 24) the same F bits;
//   * particles_to_grid_and_internal_force (one pass) gives the bits of
//     particles_to_grid + compute_internal_force on a reset grid, with and
//     without g.stressFS, for the same stencil forms, with 1 and 2 threads;
//   * P2G without f_ext,g sums when every f_ext,p and b are zero (session 23):
//     f_ext,g = +0, and one forced particle's f S at its nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/grid/Loop.h"
#include "mpm/DeformationGradient.h"
#include "mpm/NodeGrid.h"
#include "mpm/Transfers.h"
#include "mpm/UpdatedGridVelocity.h"
#include "mpm/shape/AxisStencils.h"
#include "mpm/shape/ScatterOrder.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

TEST(MpmThreadedSetup, ScatterOrderFinishIsTheStableSort) {
  const int ny = 23, nz = 19;
  const std::size_t np = 20011;  // > 4096: the threaded path
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> y(0, ny - 3), z(0, nz - 3);
  std::vector<int> y0(np), z0(np);
  for (std::size_t i = 0; i < np; ++i) y0[i] = y(rng), z0[i] = z(rng);
  // A run of particles already in block order at the start (some not displaced).
  for (int span : {2, 3}) {
    SCOPED_TRACE(span);
    ScatterOrder ref_keys;
    ref_keys.prepare(np, ny, nz, span, span);
    std::vector<std::uint32_t> key(np);
    for (std::size_t i = 0; i < np; ++i) key[i] = ref_keys.block_key(y0[i], z0[i]);
    // Reference: indices stably sorted by key; blocks = the starts of the non-empty keys.
    std::vector<std::uint32_t> ref(np);
    std::iota(ref.begin(), ref.end(), 0u);
    std::stable_sort(ref.begin(), ref.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    std::size_t ref_displaced = 0;
    for (std::size_t j = 0; j < np; ++j) ref_displaced += ref[j] != j;
    std::vector<std::uint32_t> ref_block;
    for (std::size_t j = 0; j < np; ++j)
      if (j == 0 || key[ref[j]] != key[ref[j - 1]]) ref_block.push_back(std::uint32_t(j));
    ref_block.push_back(std::uint32_t(np));
    for (int threads : {1, 2, 3}) {
      SCOPED_TRACE(threads);
      ThreadCountScope t(threads);
      ScatterOrder o;
      o.prepare(np, ny, nz, span, span);
      o.key = key;
      o.finish();
      ASSERT_TRUE(o.built_for(np));
      EXPECT_EQ(o.index, ref);
      EXPECT_EQ(o.block, ref_block);
      EXPECT_EQ(o.displaced, ref_displaced);
      // Colour c's blocks: the blocks whose key's colour (key / (blocks_y blocks_z)) is c.
      const std::uint32_t per_colour = std::uint32_t(o.blocks_y * o.blocks_z);
      for (int c = 0; c < 4; ++c)
        for (std::uint32_t b = o.colour[c]; b < o.colour[c + 1]; ++b)
          EXPECT_EQ(key[o.index[o.block[b]]] / per_colour, std::uint32_t(c));
      EXPECT_EQ(o.colour[4] + 1, o.block.size());
    }
  }
}

TEST(MpmThreadedSetup, UslNeededNodesIsTheDefinition) {
  NodeGrid g;
  g.h = Vec3(0.1, 0.2, 0.3);
  g.n = IntVec3(21, 17, 15);  // 5355 nodes > 4096: the threaded path
  g.extra = IntVec3(1, 2, 1);
  g.reset();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double cell_volume = g.h.prod();
  for (double& v : g.volume) v = u(rng) < 0.3 ? 0.0 : cell_volume * 1.2 * u(rng);
  for (double limit : {0.0, 0.4}) {
    SCOPED_TRACE(limit);
    // The definition, node by node.
    std::vector<unsigned char> ref(g.count(), 0);
    std::size_t ref_weak = 0;
    for (int k = 0; k < g.n[2]; ++k)
      for (int j = 0; j < g.n[1]; ++j)
        for (int i = 0; i < g.n[0]; ++i) {
          const IntVec3 c(i, j, k);
          const std::size_t n = g.index(c);
          const bool weak = !(g.volume[n] >= limit * cell_volume);
          ref_weak += weak;
          bool layer = false;
          for (int d = 0; d < 3; ++d) layer = layer || c[d] <= 2 * g.extra[d] || c[d] >= g.n[d] - 1 - 2 * g.extra[d];
          ref[n] = weak || layer;
        }
    if (ref_weak == 0) std::fill(ref.begin(), ref.end(), 0);  // nothing needed: USL everywhere
    for (int threads : {1, 2, 3}) {
      SCOPED_TRACE(threads);
      ThreadCountScope t(threads);
      std::vector<unsigned char> needed(3, 7);  // stale content must not survive
      EXPECT_EQ(usl_needed_nodes(g, limit, cell_volume, needed), ref_weak);
      EXPECT_EQ(needed, ref);
    }
  }
}

TEST(MpmThreadedSetup, ResetZeroesEveryArray) {
  for (int threads : {1, 2}) {
    ThreadCountScope t(threads);
    NodeGrid g;
    g.n = IntVec3(20, 18, 16);
    g.reset();
    for (double& v : g.mass) v = 1.5;
    for (Vec3& v : g.velocity) v = Vec3(1, 2, 3);
    for (Vec3& v : g.internal_force) v = Vec3(-1, 2, 3);
    for (Mat3& s : g.stress) s = Mat3::Ones();
    g.reset();
    const std::size_t n = g.count();
    ASSERT_EQ(g.mass.size(), n);
    ASSERT_EQ(g.stress.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_EQ(g.mass[i], 0.0);
      EXPECT_EQ(g.volume[i], 0.0);
      EXPECT_EQ(g.velocity[i], Vec3::Zero());
      EXPECT_EQ(g.velocity_star[i], Vec3::Zero());
      EXPECT_EQ(g.acceleration[i], Vec3::Zero());
      EXPECT_EQ(g.external_force[i], Vec3::Zero());
      EXPECT_EQ(g.internal_force[i], Vec3::Zero());
      EXPECT_EQ(g.stress[i], Mat3::Zero());
    }
    g.node_stress = false;
    g.reset();
    EXPECT_TRUE(g.stress.empty());
    g.n = IntVec3(3, 3, 3);  // shrinking
    g.reset();
    EXPECT_EQ(g.velocity.size(), 27u);
  }
}

TEST(MpmThreadedSetup, FusedVelocityGradientAndFIsTheTwoPasses) {
  NodeGrid g;
  g.origin = Vec3(-1.0, 0.5, 0.0);
  g.h = Vec3(0.1, 0.2, 0.15);
  g.n = IntVec3(14, 16, 18);
  g.reset();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  for (Vec3& v : g.velocity_star) v = Vec3(s(rng), s(rng), s(rng));
  Particles p;
  std::vector<Mat3> F_old;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 x = g.origin + Vec3((2 + 9 * u(rng)) * g.h[0], (2 + 11 * u(rng)) * g.h[1], (2 + 13 * u(rng)) * g.h[2]);
    p.add(x, Vec3::Zero(), 1.0, 1e-3, 300.0, 0.0, i, Mat3::Identity() * 0.5);
    F_old.push_back(Mat3::Identity() + 0.1 * Mat3::Random());
  }
  const double dt = 0.01;
  for (int form = 0; form < 3; ++form) {
    SCOPED_TRACE(form);
    Stencils st;
    if (form == 0) ASSERT_EQ(compute_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st), -1);
    if (form == 1) ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Linear, 1e10}, st));
    if (form == 2) ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st));
    std::vector<Mat3> L_ref, F_ref;
    velocity_gradients(st, g, L_ref);
    update_deformation_gradients(DeformationGradientAlgorithm::FirstOrder, 1, dt, L_ref, F_old, F_ref);
    for (int threads : {1, 2}) {
      ThreadCountScope t(threads);
      std::vector<Mat3> L, F;
      velocity_gradients_and_first_order_F(st, g, dt, L, F_old, F);
      ASSERT_EQ(L.size(), L_ref.size());
      ASSERT_EQ(F.size(), F_ref.size());
      for (std::size_t i = 0; i < L.size(); ++i) {
        ASSERT_EQ(L[i], L_ref[i]) << i;
        ASSERT_EQ(F[i], F_ref[i]) << i;
      }
      // Without the L column (a model that does not read L): the same F bits.
      std::vector<Mat3> F_only;
      first_order_F(st, g, dt, F_old, F_only);
      ASSERT_EQ(F_only.size(), F_ref.size());
      for (std::size_t i = 0; i < F_only.size(); ++i) ASSERT_EQ(F_only[i], F_ref[i]) << i;
    }
  }
}

// Every node array of a and b bit for bit (EXPECT_EQ: no tolerance).
void expect_same_nodes(const NodeGrid& a, const NodeGrid& b) {
  ASSERT_EQ(a.count(), b.count());
  ASSERT_EQ(a.stress.size(), b.stress.size());
  ASSERT_EQ(a.mass.size(), a.count());
  for (std::size_t gi = 0; gi < a.count(); ++gi) {
    ASSERT_EQ(a.mass[gi], b.mass[gi]) << gi;
    ASSERT_EQ(a.volume[gi], b.volume[gi]) << gi;
    ASSERT_EQ(a.velocity[gi], b.velocity[gi]) << gi;
    ASSERT_EQ(a.external_force[gi], b.external_force[gi]) << gi;
    ASSERT_EQ(a.internal_force[gi], b.internal_force[gi]) << gi;
    if (!a.stress.empty()) ASSERT_EQ(a.stress[gi], b.stress[gi]) << gi;
  }
}

TEST(MpmThreadedSetup, FusedP2GAndInternalForceIsTheTwoPasses) {
  NodeGrid g;
  g.origin = Vec3(-1.0, 0.5, 0.0);
  g.h = Vec3(0.1, 0.2, 0.15);
  g.n = IntVec3(14, 16, 18);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  Particles p;
  for (int i = 0; i < 6000; ++i) {  // > 4096: the threaded scatter
    const Vec3 x = g.origin + Vec3((2 + 9 * u(rng)) * g.h[0], (2 + 11 * u(rng)) * g.h[1], (2 + 13 * u(rng)) * g.h[2]);
    p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3 * (0.5 + u(rng)), 300.0, 0.0, i,
          Mat3::Identity() * 0.5);
    p.stress.back() = 1e6 * Mat3::Random();
    p.external_force.back() = Vec3(s(rng), s(rng), s(rng));
  }
  for (double& q : p.q) q = 1e5 * u(rng);  // artificial viscosity enters the force only
  const Vec3 gravity(0.0, -9.81, 1.0);
  for (int form = 0; form < 3; ++form)
    for (bool node_stress : {false, true}) {
      SCOPED_TRACE(testing::Message() << "form " << form << " node_stress " << node_stress);
      Stencils st;
      if (form == 0) ASSERT_EQ(compute_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st), -1);
      if (form == 1) ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Linear, 1e10}, st));
      if (form == 2) ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st));
      NodeGrid ref = g;
      ref.node_stress = node_stress;
      ref.reset();
      particles_to_grid(p, st, gravity, ref);
      compute_internal_force(p, st, ref);
      double fmax = 0.0;
      for (const Vec3& f : ref.internal_force) fmax = std::max(fmax, f.norm());
      ASSERT_GT(fmax, 0.0);  // the comparison below is not of zeros
      for (int threads : {1, 2}) {
        ThreadCountScope t(threads);
        NodeGrid fused = g;
        fused.node_stress = node_stress;
        fused.reset();
        particles_to_grid_and_internal_force(p, st, gravity, fused);
        expect_same_nodes(ref, fused);
      }
    }
}

// P2G leaves the f_ext,g sums out when every f_ext,p and b are zero
// (Transfers.cpp, has_external_force): the node values must be what the sums
// give. Closed forms: with all terms +-0 (S >= 0) every f_ext,g is +0 (a
// positive zero: the reset +0 plus +-0 terms); with one particle k carrying
// f = (1, 2, 4) (exact multiples of S) and all others +-0, f_ext,g = f S_gk
// at k's stencil nodes and +0 elsewhere; a NaN force reaches k's nodes (a NaN
// is not zero). Particles_to_grid and the fused pass, three stencil forms,
// 1 and 2 threads.
TEST(MpmThreadedSetup, P2GExternalForceSumsWithZeroAndOneForcedParticle) {
  NodeGrid g;
  g.origin = Vec3(-1.0, 0.5, 0.0);
  g.h = Vec3(0.1, 0.2, 0.15);
  g.n = IntVec3(14, 16, 18);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  Particles p;
  for (int i = 0; i < 6000; ++i) {  // > 4096: the threaded scatter and scan
    const Vec3 x = g.origin + Vec3((2 + 9 * u(rng)) * g.h[0], (2 + 11 * u(rng)) * g.h[1], (2 + 13 * u(rng)) * g.h[2]);
    p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3 * (0.5 + u(rng)), 300.0, 0.0, i,
          Mat3::Identity() * 0.5);
    p.stress.back() = 1e6 * Mat3::Random();
    const double z = i % 2 ? -0.0 : 0.0;
    p.external_force.back() = Vec3(z, -z, z);
  }
  const Vec3 no_gravity(0.0, -0.0, 0.0);
  const std::size_t k = 4321;
  for (int form = 0; form < 3; ++form) {
    Stencils st;
    if (form == 0) ASSERT_EQ(compute_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st), -1);
    if (form == 1) ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Linear, 1e10}, st));
    if (form == 2) ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st));
    // S_gk of particle k (the stencil's weights; entries may repeat a node with weight 0).
    std::vector<double> S_k(g.count(), 0.0);
    std::vector<char> in_k(g.count(), 0);  // a node of k's stencil (NaN * 0 is NaN there)
    visit_stencils(st, [&](const auto& view) {
      view.weights(k, [&](std::size_t gi, double w) { S_k[gi] += w, in_k[gi] = 1; });
    });
    for (int variant = 0; variant < 3; ++variant)  // all zero, f_k = (1, 2, 4), f_k = NaN
      for (int fused : {0, 1})
        for (int threads : {1, 2}) {
          SCOPED_TRACE(testing::Message() << "form " << form << " variant " << variant << " fused " << fused
                                          << " threads " << threads);
          ThreadCountScope t(threads);
          Particles q = p;
          if (variant == 1) q.external_force[k] = Vec3(1.0, 2.0, 4.0);
          if (variant == 2) q.external_force[k] = Vec3(std::nan(""), 0.0, 0.0);
          NodeGrid n = g;
          n.node_stress = false;
          n.reset();
          if (fused) particles_to_grid_and_internal_force(q, st, no_gravity, n);
          else particles_to_grid(q, st, no_gravity, n);
          int reached = 0;
          for (std::size_t gi = 0; gi < n.count(); ++gi) {
            const Vec3& f = n.external_force[gi];
            if (variant == 2 && in_k[gi]) {
              ASSERT_TRUE(std::isnan(f[0])) << gi;
              ++reached;
              continue;
            }
            const Vec3 expect = variant == 1 ? Vec3(S_k[gi], 2.0 * S_k[gi], 4.0 * S_k[gi]) : Vec3::Zero();
            for (int d = 0; d < 3; ++d) {
              ASSERT_EQ(f[d], expect[d]) << gi << " " << d;
              ASSERT_FALSE(std::signbit(f[d])) << gi << " " << d;  // +0, not -0
            }
            reached += expect[0] > 0.0;
          }
          // k's nodes were checked: its nodes with S > 0 (variant 1), all its stencil nodes (NaN).
          const long positive = std::count_if(S_k.begin(), S_k.end(), [](double w) { return w > 0.0; });
          if (variant == 1) ASSERT_EQ(reached, positive);
          if (variant == 2) ASSERT_EQ(reached, std::count(in_k.begin(), in_k.end(), 1));
          ASSERT_GE(positive, 8);
        }
  }
}

}  // namespace
}  // namespace tephra
