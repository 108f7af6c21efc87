// Node sums in ascending patch order (mpm/PatchBand.h, issue 7).
//
// Claims, on a 12 x 8 x 6 cell level cut into 3 x 2 x 1 patches, with
// random particles (gimp and linear per-axis stencils, flat cpdi):
//   * the band P2G + internal force and the band MUSL momentum equal, bit
//     for bit at every node, the reference
//         x_n = ( ... ((0 + X_{0,n}) + X_{1,n}) + ... + X_{5,n} ),
//         X_{P,n} = sum over patch P's particles, in the (colour, block, id)
//                   scatter order, of the kernel's term (m S, V S, m v S,
//                   f S, -V (sigma - q I) grad S, V sigma S),
//     formed here with the kernels' expressions, and v_g = (m v)_g / m_g,
//     sigma_g = (V sigma)_g / V_g after the sum;
//   * the same sums in DESCENDING patch order differ in the last bits at
//     some band node (the mutation the test must catch: the order matters);
//   * the band result does not depend on the storage order of the particles
//     (shuffled, as migration appends arrivals) nor on the thread count;
//   * the band lies where two patches' reach boxes meet (a closed count);
//   * PatchBand::boxes(n) (the node-box test that lets a per-axis stencil
//     skip tag(), mpm/BandTag.h) answers, at every node b, exactly "no band
//     node in [b, b + n - 1] per axis" (brute force over the box), n = 2, 3.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

#include "core/grid/Loop.h"
#include "mpm/PatchBand.h"
#include "mpm/Transfers.h"
#include "mpm/UpdatedGridVelocity.h"
#include "mpm/shape/AxisStencils.h"

namespace tephra {
namespace {

constexpr int kPatches[3] = {3, 2, 1};

Grid level() {
  Grid L;
  L.lower = Vec3(-0.6, 0.0, 0.1);
  L.dx = Vec3(0.1, 0.1, 0.1);
  L.cells = IntVec3(12, 8, 6);
  L.upper = L.lower + Vec3(1.2, 0.8, 0.6);
  L.extra_cells = IntVec3(1, 1, 1);
  int id = 0;
  for (int b = 0; b < kPatches[1]; ++b)
    for (int a = 0; a < kPatches[0]; ++a) {
      Patch p;
      p.id = id++;
      p.lo = IntVec3(4 * a, 4 * b, 0);
      p.hi = IntVec3(4 * (a + 1), 4 * (b + 1), 6);
      L.patches.push_back(p);
    }
  L.set_patch_extra_cells();
  L.index_patches();
  return L;
}

NodeGrid nodes(const Grid& L) {
  NodeGrid g;
  g.origin = L.lower - L.dx;  // one extra cell per side
  g.h = L.dx;
  g.n = L.cells + IntVec3(3, 3, 3);
  g.extra = IntVec3(1, 1, 1);
  g.reset();
  return g;
}

Particles cloud(const Grid& L, int count, unsigned seed) {
  Particles p;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  for (int i = 0; i < count; ++i) {
    // Cells 0.5 .. n - 0.5 of the interior: every support stays on the node grid.
    const Vec3 x = L.lower + Vec3((0.5 + 11 * u(rng)) * L.dx[0], (0.5 + 7 * u(rng)) * L.dx[1],
                                  (0.5 + 5 * u(rng)) * L.dx[2]);
    Mat3 size = Mat3::Identity() * 0.5;
    size(0, 1) = 0.3 * s(rng);  // cpdi: a sheared domain
    p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3 * (0.5 + u(rng)), 300.0, 0.0, 1000 + 7 * i, size);
    p.stress.back() = Mat3::Identity() * 1e3 * s(rng);
    p.stress.back()(0, 2) = p.stress.back()(2, 0) = 2e2 * s(rng);
    p.external_force.back() = Vec3(s(rng), 0.0, s(rng));
    p.q.back() = 10.0 * u(rng);
  }
  return p;
}

// MpmComponent::patch_of: the patch of the nearest interior cell.
int patch_of(const Grid& L, const Vec3& x) {
  IntVec3 c;
  for (int d = 0; d < 3; ++d) c[d] = std::clamp(int(std::floor((x[d] - L.lower[d]) / L.dx[d])), 0, L.cells[d] - 1);
  return L.patch_owning_cell(c);
}

// Stencils, ordered (colour, block, id), and the band with the reach MpmComponent::prepare_band uses.
void stencils(const Particles& p, const NodeGrid& g, InterpolatorKind kind, const Grid& L, Stencils& s,
              PatchBand& band) {
  if (kind == InterpolatorKind::Cpdi) ASSERT_LT(compute_stencils(p, g, {kind, 1e10}, s), 0);
  else ASSERT_TRUE(compute_axis_stencils(p, g, {kind, 1e10}, s));
  s.order.sort_blocks_by_id(p.id.data());
  band.prepare(L, g, s.axis_nodes ? s.order.span - 1 : s.order.span);
  ASSERT_TRUE(band.active());
}

// The reference node sums, patch by patch in the given order: 20 doubles per
// node (m, V, m v, f_ext, f_int, V sigma) and, for MUSL, 3 (m v^{n+1}).
struct Reference {
  std::vector<double> p2g, musl;
};

Reference reference(const Particles& p, const Stencils& s, const NodeGrid& g, const Grid& L, const Vec3& b,
                    double dt, const std::vector<Vec3>& acc, bool descending) {
  const std::size_t nn = g.count(), np = p.size();
  std::vector<int> order(L.patches.size());
  std::iota(order.begin(), order.end(), 0);
  if (descending) std::reverse(order.begin(), order.end());
  Reference r{std::vector<double>(nn * 20, 0.0), std::vector<double>(nn * 3, 0.0)};
  std::vector<double> X(nn * 20), Y(nn * 3);
  visit_stencils(s, [&](const auto& view) {
    for (int P : order) {
      std::fill(X.begin(), X.end(), 0.0);
      std::fill(Y.begin(), Y.end(), 0.0);
      for (std::size_t j = 0; j < np; ++j) {  // the scatter order, this patch's particles only
        const std::size_t i = s.order.index[j];
        if (patch_of(L, p.x[i]) != P) continue;
        const double mp = p.mass[i], vp = p.volume[i];
        const Vec3 momentum = mp * p.v[i];
        const Vec3 force = p.external_force[i] + mp * b;
        const Mat3 vol_stress = vp * p.stress[i];
        const Mat3 force_stress = vp * (p.stress[i] - p.q[i] * Mat3::Identity());
        view.entries(i, [&](std::size_t gi, double wk, const Vec3& gr) {
          double* q = &X[gi * 20];
          q[0] += mp * wk;
          q[1] += vp * wk;
          Eigen::Map<Vec3>(q + 2) += momentum * wk;
          Eigen::Map<Vec3>(q + 5) += force * wk;
          Eigen::Map<Vec3>(q + 8) -= force_stress * gr;
          Eigen::Map<Mat3>(q + 11) += vol_stress * wk;
        });
        Vec3 a = Vec3::Zero();
        view.weights(i, [&](std::size_t gi, double wk) { a += wk * acc[gi]; });
        const Vec3 mv = mp * (p.v[i] + dt * a);
        view.weights(i, [&](std::size_t gi, double wk) { Eigen::Map<Vec3>(&Y[gi * 3]) += wk * mv; });
      }
      for (std::size_t k = 0; k < X.size(); ++k) r.p2g[k] += X[k];
      for (std::size_t k = 0; k < Y.size(); ++k) r.musl[k] += Y[k];
    }
  });
  return r;
}

// Bits of the band run against the reference: the count of differing doubles.
std::size_t differences(const NodeGrid& g, const std::vector<Vec3>& musl, const Reference& r) {
  std::size_t bad = 0;
  for (std::size_t n = 0; n < g.count(); ++n) {
    const double* q = &r.p2g[n * 20];
    const double m = q[0], V = q[1];
    Vec3 v = Eigen::Map<const Vec3>(q + 2);
    if (m > 0.0) v /= m;
    Mat3 sig = Eigen::Map<const Mat3>(q + 11);
    if (V > 0.0) sig /= V;
    bad += g.mass[n] != m;
    bad += g.volume[n] != V;
    for (int d = 0; d < 3; ++d) {
      bad += g.velocity[n][d] != v[d];
      bad += g.external_force[n][d] != q[5 + d];
      bad += g.internal_force[n][d] != q[8 + d];
      const Vec3 mv = Eigen::Map<const Vec3>(&r.musl[n * 3]);
      bad += musl[n][d] != (m > 0.0 ? Vec3(mv / m)[d] : 0.0);
    }
    for (int k = 0; k < 9; ++k) bad += g.stress[n](k) != sig(k);
  }
  return bad;
}

struct BandRun {
  NodeGrid g;
  std::vector<Vec3> musl;
};

BandRun band_run(const Particles& p, const Stencils& s, const Grid& L, const Vec3& b, double dt,
             const std::vector<Vec3>& acc, PatchBand& band) {
  BandRun r{nodes(L), {}};
  particles_to_grid_and_internal_force(p, s, b, r.g, &band);
  r.g.acceleration = acc;
  updated_particle_grid_velocity(p, s, r.g, dt, nullptr, r.musl, &band);
  return r;
}

std::vector<Vec3> accelerations(const NodeGrid& g) {
  std::vector<Vec3> a(g.count());
  for (std::size_t n = 0; n < a.size(); ++n) a[n] = Vec3(std::sin(0.1 * n), std::cos(0.3 * n), 0.5);
  return a;
}

class PatchBandKinds : public ::testing::TestWithParam<InterpolatorKind> {};

TEST_P(PatchBandKinds, EqualsPerPatchOrderedSumAndDescendingDiffers) {
  const Grid L = level();
  const Particles p = cloud(L, 5000, 11);
  const NodeGrid g0 = nodes(L);
  Stencils s;
  PatchBand band;
  stencils(p, g0, GetParam(), L, s, band);
  const Vec3 b(0.0, -9.81, 0.0);
  const double dt = 1e-3;
  const std::vector<Vec3> acc = accelerations(g0);
  const BandRun run = band_run(p, s, L, b, dt, acc, band);
  EXPECT_EQ(differences(run.g, run.musl, reference(p, s, run.g, L, b, dt, acc, false)), 0u);
  // The mutation: descending patch order changes bits at band nodes.
  EXPECT_GT(differences(run.g, run.musl, reference(p, s, run.g, L, b, dt, acc, true)), 0u);
  // The band scatter without a band (one sequence over all particles) is another sum too.
  NodeGrid plain = nodes(L);
  particles_to_grid_and_internal_force(p, s, b, plain, nullptr);
  std::size_t differ = 0;
  for (std::size_t n = 0; n < plain.count(); ++n) differ += plain.mass[n] != run.g.mass[n];
  EXPECT_GT(differ, 0u);
}

INSTANTIATE_TEST_SUITE_P(Kinds, PatchBandKinds,
                         ::testing::Values(InterpolatorKind::Linear, InterpolatorKind::Gimp, InterpolatorKind::Cpdi));

TEST(PatchBand, IndependentOfStorageOrderAndThreads) {
  const Grid L = level();
  const Particles p = cloud(L, 6000, 5);
  const NodeGrid g0 = nodes(L);
  const Vec3 b(0.0, -9.81, 0.0);
  const double dt = 1e-3;
  const std::vector<Vec3> acc = accelerations(g0);
  Stencils s;
  PatchBand band;
  stencils(p, g0, InterpolatorKind::Gimp, L, s, band);
  const BandRun one = band_run(p, s, L, b, dt, acc, band);
  // Storage shuffled (as MPI migration appends arriving particles), ids kept.
  std::vector<std::uint32_t> perm(p.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(9));
  Particles q;
  for (std::uint32_t i : perm) {
    q.add(p.x[i], p.v[i], p.mass[i], p.volume[i], 300.0, 0.0, p.id[i], p.psize[i]);
    q.stress.back() = p.stress[i];
    q.external_force.back() = p.external_force[i];
    q.q.back() = p.q[i];
  }
  Stencils t;
  PatchBand band2;
  stencils(q, g0, InterpolatorKind::Gimp, L, t, band2);
  const int saved = thread_count();
  for (int threads : {1, 2}) {
    set_thread_count(threads);
    const BandRun two = band_run(q, t, L, b, dt, acc, band2);
    std::size_t bad = 0;
    for (std::size_t n = 0; n < g0.count(); ++n) {
      bad += one.g.mass[n] != two.g.mass[n] || one.g.volume[n] != two.g.volume[n];
      bad += one.g.velocity[n] != two.g.velocity[n] || one.g.internal_force[n] != two.g.internal_force[n];
      bad += one.g.external_force[n] != two.g.external_force[n] || one.g.stress[n] != two.g.stress[n];
      bad += one.musl[n] != two.musl[n];
    }
    EXPECT_EQ(bad, 0u) << threads << " threads";
  }
  set_thread_count(saved);
}

// The band of a [3,2,1] cut with reach R: node x-planes within R of the cuts
// x = 4, 8 (node index 5, 9 with one extra cell) and y-planes within R of the
// cut y = 4 (node 5); a node is in the band when two reach boxes
// [c_lo - R, c_hi + R] hold it: |i - cut| <= R in x or |j - cut| <= R in y.
TEST(PatchBand, BandIsWhereReachBoxesMeet) {
  const Grid L = level();
  const NodeGrid g = nodes(L);
  PatchBand band;
  for (int R : {1, 2}) {
    band.prepare(L, g, R);
    std::size_t expected = 0;
    for (int k = 0; k < g.n[2]; ++k)
      for (int j = 0; j < g.n[1]; ++j)
        for (int i = 0; i < g.n[0]; ++i) {
          const bool in = std::abs(i - 5) <= R || std::abs(i - 9) <= R || std::abs(j - 5) <= R;
          expected += in;
          EXPECT_EQ(band.slot(g.index(i, j, k)) >= 0, in) << i << " " << j << " " << k << " R " << R;
        }
    EXPECT_EQ(band.band_nodes(), expected);
  }
}

// boxes(n) against a brute-force scan of each node's n x n x n box (clipped
// to the grid): a wrong answer "clear" would send a band particle down the
// plain path (wrong sums), "not clear" only costs a tag().
TEST(PatchBand, NodeBoxTestIsTheBruteForceScan) {
  const Grid L = level();
  const NodeGrid g = nodes(L);
  for (int n : {2, 3}) {
    PatchBand band;
    band.prepare(L, g, 1);  // reach 1: narrow enough that some boxes miss the band
    ASSERT_TRUE(band.active());
    band.boxes(n);
    std::size_t clear = 0, wrong = 0;
    for (int k = 0; k < g.n[2]; ++k)
      for (int j = 0; j < g.n[1]; ++j)
        for (int i = 0; i < g.n[0]; ++i) {
          bool hit = false;
          for (int c = k; c < std::min(k + n, g.n[2]); ++c)
            for (int b = j; b < std::min(j + n, g.n[1]); ++b)
              for (int a = i; a < std::min(i + n, g.n[0]); ++a) hit = hit || band.slot(g.index(a, b, c)) >= 0;
          const bool said = band.box_clear(g.index(i, j, k));
          wrong += said == hit;
          clear += said;
        }
    EXPECT_EQ(wrong, 0u) << "n = " << n;
    // Both answers occur (the test sees both branches): the 3 x 2 patches of
    // 4 x 4 cells leave nodes whose boxes miss the band, and the band itself.
    EXPECT_GT(clear, 0u) << "n = " << n;
    EXPECT_LT(clear, g.count()) << "n = " << n;
  }
}

}  // namespace
}  // namespace tephra

namespace tephra {
namespace {

// reduce() without a partial() since the buffer was last zeroed takes a
// shortcut (no buffer read): it must make the same calls with +0 sums as the
// full pass. Sequence: reduce untouched (all +0, every band node once), write
// one patch's partial of one node, reduce (+0 + 0.5), reduce again (zeroed: all +0, not -0).
TEST(PatchBand, ReduceWithoutPartialsGivesPositiveZeros) {
  const Grid L = level();
  const NodeGrid g = nodes(L);
  PatchBand band;
  band.prepare(L, g, 1);
  ASSERT_TRUE(band.active());
  auto collect = [&](int width) {
    // reduce() calls sum from several threads (one band node each): a slot per node, then the map.
    std::vector<std::vector<double>> at(g.count());
    band.reduce(width, [&](std::size_t gi, const double* s) { at[gi].assign(s, s + width); });
    std::map<std::size_t, std::vector<double>> got;
    for (std::size_t gi = 0; gi < at.size(); ++gi)
      if (!at[gi].empty()) got[gi] = at[gi];
    return got;
  };
  auto all_positive_zero = [](const std::map<std::size_t, std::vector<double>>& got) {
    for (const auto& [gi, s] : got)
      for (double v : s)
        if (v != 0.0 || std::signbit(v)) return false;
    return true;
  };
  auto first = collect(3);
  EXPECT_EQ(first.size(), band.band_nodes());
  EXPECT_TRUE(all_positive_zero(first));
  // The lowest band node and the patch of the cell above it (that patch's
  // reach box holds the node; tag() >= 0 since the cell's reach cube holds it).
  const std::size_t gi = band.band_node_index().front();
  const int k = band.slot(gi);
  const int i0 = int(gi % std::size_t(g.n[0])), j0 = int((gi / std::size_t(g.n[0])) % std::size_t(g.n[1])),
            k0 = int(gi / (std::size_t(g.n[0]) * std::size_t(g.n[1])));
  const int P = band.tag(g.origin + Vec3((i0 + 0.5) * g.h[0], (j0 + 0.5) * g.h[1], (k0 + 0.5) * g.h[2]));
  ASSERT_GE(P, 0);
  band.partial(k, P)[1] = 0.5;
  auto second = collect(3);
  EXPECT_EQ(second.size(), band.band_nodes());
  EXPECT_EQ(second[gi][1], 0.5);  // the one partial, summed from +0
  EXPECT_EQ(second[gi][0], 0.0);
  auto third = collect(3);
  EXPECT_EQ(third.size(), band.band_nodes());
  EXPECT_TRUE(all_positive_zero(third));
}

}  // namespace
}  // namespace tephra
