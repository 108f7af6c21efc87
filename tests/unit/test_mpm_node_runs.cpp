// The node-wise passes of an MPM step over a node box (session 23, issue 7:
// on MPI ranks each rank visits its own node box instead of the whole grid;
// mpm/NodeRuns.h, NodeGrid::active). Claims:
//  1. node_runs(g, box) visits exactly the nodes of the box, each once, in
//     ascending index order (against the brute-force triple loop), for the
//     whole grid, boxes spanning x and y, spanning x only, general and empty;
//  2. a restricted NodeGrid::reset zeroes the hull of the previous and the
//     current box: values written inside the previous box are gone although
//     the new box does not hold them;
//  3. the restricted P2G division, symmetry folds, grid BCs, integration and
//     a_g = (v* - v)/dt give, inside a box holding every node the particles
//     reach (closed under the symmetry mirror pairs), the whole-grid bits,
//     and 0 outside it.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeRuns.h"
#include "mpm/SymmetryFold.h"
#include "mpm/Transfers.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {
namespace {

NodeGrid small_grid() {
  NodeGrid g;
  g.h = Vec3(0.1, 0.1, 0.1);
  g.n = IntVec3(13, 11, 9);  // 10 x 8 x 6 cells + one extra cell per side
  g.extra = IntVec3(1, 1, 1);
  g.origin = -g.h;
  return g;
}

std::vector<std::size_t> brute_force(const NodeGrid& g, const NodeBox& b) {
  std::vector<std::size_t> v;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i)
        if (b.contains(i, j, k)) v.push_back(g.index(i, j, k));
  return v;
}

TEST(MpmNodeRuns, RunsVisitExactlyTheBoxNodesInIndexOrder) {
  const NodeGrid g = small_grid();
  const IntVec3 n = g.n;
  const NodeBox boxes[] = {
      {IntVec3::Zero(), n},                                  // whole grid: one run
      {IntVec3(0, 0, 2), IntVec3(n[0], n[1], 7)},            // spans x and y: one run
      {IntVec3(0, 3, 1), IntVec3(n[0], 8, 9)},               // spans x: one run per z plane
      {IntVec3(2, 0, 0), IntVec3(9, n[1], n[2])},            // general: one run per row
      {IntVec3(4, 2, 3), IntVec3(5, 3, 4)},                  // one node
      {IntVec3(4, 2, 3), IntVec3(4, 9, 8)},                  // empty
  };
  const long expected_runs[] = {1, 1, 8, 11 * 9, 1, 0};
  for (int c = 0; c < 6; ++c) {
    const NodeRuns r = node_runs(g, boxes[c]);
    std::vector<std::size_t> v;
    for (long q = 0; q < r.count; ++q)
      for (std::size_t gi = r.begin(q); gi < r.begin(q) + r.length; ++gi) v.push_back(gi);
    EXPECT_EQ(v, brute_force(g, boxes[c])) << "box " << c;
    EXPECT_EQ(r.count, expected_runs[c]) << "box " << c;
    EXPECT_EQ(r.nodes(), boxes[c].count()) << "box " << c;
    // The threaded visitor touches the same nodes once each.
    std::vector<int> hits(g.count(), 0);
    for_each_run_node(r, [&](std::size_t gi) { ++hits[gi]; }, 1);
    for (std::size_t gi = 0; gi < g.count(); ++gi) {
      const int i = int(gi % 13), j = int(gi / 13 % 11), k = int(gi / 143);
      EXPECT_EQ(hits[gi], boxes[c].contains(i, j, k) ? 1 : 0) << "box " << c << " node " << gi;
    }
  }
}

TEST(MpmNodeRuns, RestrictedResetZeroesThePreviousAndTheCurrentBox) {
  NodeGrid g = small_grid();
  g.reset();  // whole grid
  g.restricted = true;
  const NodeBox a{IntVec3(1, 1, 1), IntVec3(6, 5, 4)}, b{IntVec3(5, 4, 3), IntVec3(12, 10, 8)};
  g.active = a;
  g.reset();
  for (std::size_t gi : brute_force(g, a)) g.mass[gi] = 1.0, g.velocity[gi] = Vec3(1, 2, 3);
  g.active = b;
  g.reset();
  for (std::size_t gi = 0; gi < g.count(); ++gi) {
    ASSERT_EQ(g.mass[gi], 0.0) << gi;
    ASSERT_EQ(g.velocity[gi], Vec3::Zero()) << gi;
  }
  EXPECT_TRUE(g.cleared == b);
}

TEST(MpmNodeRuns, RestrictedNodePassesGiveTheWholeGridBitsInTheBox) {
  NodeGrid g = small_grid();
  g.reset();
  // A block of 2 x 2 x 2 particles per cell touching the x- and z- symmetry
  // faces (its GIMP supports reach the extra nodes there) and ending inside
  // the domain elsewhere.
  Particles p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> s(-1.0, 1.0);
  long long id = 0;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 8; ++i) {
        const Vec3 x = 0.5 * g.h.cwiseProduct(Vec3(i + 0.5, j + 0.5 + 4.0, k + 0.5));
        p.add(x, Vec3(s(rng), s(rng), s(rng)), 1.0 + 0.1 * s(rng), 1.25e-4, 300.0, 0.0, id++,
              Mat3::Identity() * 0.5);
        p.stress.back() = Mat3::Identity() * (1e3 * s(rng));
      }
  GridBoundaryConditions bcs;
  bcs.face[0].kind = FaceVelocityBC::Kind::Symmetry;
  bcs.face[4].kind = FaceVelocityBC::Kind::Symmetry;
  bcs.face[3].kind = FaceVelocityBC::Kind::Velocity;  // y+: outside the box below
  bcs.face[3].value = Vec3(0.5, 0, 0);
  bcs.set_extra_nodes = true;
  Stencils st;
  ASSERT_EQ(compute_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st), -1);
  // The box: the nodes the stencils reach, one node more, and the layers
  // within 2 extra of the x- and z- faces (closed under the mirror pairs).
  NodeBox box{g.n, IntVec3::Zero()};
  for (std::size_t e = 0; e < st.node.size(); ++e) {
    if (st.w[e] == 0.0 && st.grad[e] == Vec3::Zero()) continue;  // padding entries
      const std::size_t gi = st.node[e];
      const IntVec3 c(int(gi % 13), int(gi / 13 % 11), int(gi / 143));
      box.lo = box.lo.cwiseMin(c - IntVec3::Ones());
      box.hi = box.hi.cwiseMax(c + 2 * IntVec3::Ones());
    }
  box.lo = box.lo.cwiseMax(IntVec3::Zero());
  box.hi = box.hi.cwiseMin(g.n);
  box.lo[0] = box.lo[2] = 0;
  ASSERT_LT(box.hi[1], g.n[1] - 1);  // the y+ face's nodes lie outside the box
  ASSERT_LT(box.hi[0], g.n[0]);      // a general box (one run per row)
  auto step = [&](NodeGrid& grid) {
    grid.reset();
    particles_to_grid_and_internal_force(p, st, Vec3(0, -9.8, 0), grid);
    fold_symmetry_particle_sums(bcs, grid);
    fold_symmetry_internal_force(bcs, grid);
    bcs.apply(grid, grid.velocity);
    integrate_grid_velocity(grid, 1e-4);
    bcs.apply(grid, grid.velocity_star);
    acceleration_from_velocities(grid, 1e-4);
  };
  NodeGrid whole = g, part = g;
  part.restricted = true;
  part.active = box;
  step(whole);
  step(part);
  const std::vector<std::size_t> in = brute_force(g, box);
  std::vector<char> inside(g.count(), 0);
  for (std::size_t gi : in) inside[gi] = 1;
  int compared = 0;
  for (std::size_t gi = 0; gi < g.count(); ++gi) {
    const auto same = [&](const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    if (inside[gi]) {
      ASSERT_TRUE(same(whole.mass[gi], part.mass[gi])) << gi;
      ASSERT_TRUE(same(whole.velocity[gi], part.velocity[gi])) << gi;
      ASSERT_TRUE(same(whole.velocity_star[gi], part.velocity_star[gi])) << gi;
      ASSERT_TRUE(same(whole.acceleration[gi], part.acceleration[gi])) << gi;
      ASSERT_TRUE(same(whole.internal_force[gi], part.internal_force[gi])) << gi;
      compared += whole.mass[gi] > 0.0;
    } else {
      ASSERT_EQ(whole.mass[gi], 0.0) << gi;  // no particle reaches it
      ASSERT_EQ(part.velocity_star[gi], Vec3::Zero()) << gi;
      ASSERT_EQ(part.acceleration[gi], Vec3::Zero()) << gi;
    }
  }
  EXPECT_GT(compared, 60);  // the nodes with mass (80: the block spans 4 x 3 x 3 cells)
}

}  // namespace
}  // namespace tephra
