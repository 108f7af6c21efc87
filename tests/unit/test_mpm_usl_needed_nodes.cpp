// Step 9 computes v_g^{n+1} (MUSL, mpm/UpdatedGridVelocity.h) only where
// keep_stable_usl_nodes keeps it. Claim: after the grid BCs and
// keep_stable_usl_nodes, the restricted computation
// (usl_needed_nodes + updated_particle_grid_velocity_at) gives the same bits
// as the full one at every node, for any fill limit (none, some or all nodes
// under-filled), with GIMP supports on the extra-cell nodes mirrored by
// symmetry faces, and in either stencil form.
#include <gtest/gtest.h>

#include <random>

#include "mpm/GridBoundaryConditions.h"
#include "mpm/Transfers.h"
#include "mpm/UpdatedGridVelocity.h"

namespace tephra {
namespace {

TEST(MpmUslNeededNodes, RestrictedMuslEqualsTheFullOne) {
  NodeGrid g;
  g.h = Vec3(0.1, 0.1, 0.1);
  g.n = IntVec3(13, 11, 9);  // 10 x 8 x 6 cells + one extra cell per side
  g.extra = IntVec3(1, 1, 1);
  g.origin = -g.h;
  g.reset();
  // A block of 2 x 2 x 2 particles per cell touching the x- and z- faces and
  // ending inside the domain elsewhere (free surfaces: under-filled nodes).
  Particles p;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> s(-1.0, 1.0);
  long long id = 0;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 12; ++i) {
        const Vec3 x = 0.5 * g.h.cwiseProduct(Vec3(i + 0.5, j + 0.5 + 2.0, k + 0.5));
        p.add(x, Vec3(s(rng), s(rng), s(rng)), 1.0 + 0.1 * s(rng), 1.25e-4, 300.0, 0.0, id++,
              Mat3::Identity() * 0.5);
      }
  GridBoundaryConditions bcs;
  bcs.face[0].kind = FaceVelocityBC::Kind::Symmetry;
  bcs.face[4].kind = FaceVelocityBC::Kind::Symmetry;
  bcs.face[3].kind = FaceVelocityBC::Kind::Velocity;
  bcs.face[3].value = Vec3(0.5, 0, 0);
  bcs.set_extra_nodes = true;
  const double cell_volume = g.h.prod(), dt = 1e-3;
  for (const bool axis : {false, true}) {
    Stencils st;
    if (axis) ASSERT_TRUE(compute_axis_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st));
    else ASSERT_EQ(compute_stencils(p, g, {InterpolatorKind::Gimp, 1e10}, st), -1);
    NodeGrid grid = g;
    particles_to_grid(p, st, Vec3::Zero(), grid);
    for (std::size_t n = 0; n < grid.count(); ++n) {
      grid.acceleration[n] = grid.mass[n] > 0.0 ? Vec3(s(rng), s(rng), s(rng)) : Vec3::Zero();
      grid.velocity_star[n] = grid.mass[n] > 0.0 ? Vec3(s(rng), s(rng), s(rng)) : Vec3::Zero();
    }
    bcs.apply(grid, grid.velocity_star);
    std::size_t weak_counts[3] = {};
    int c = 0;
    for (const double limit : {0.0, 0.3, 2.0}) {  // no node, the surface nodes, every node under-filled
      std::vector<Vec3> full, part;
      updated_particle_grid_velocity(p, st, grid, dt, nullptr, full);
      bcs.apply(grid, full);
      keep_stable_usl_nodes(grid, limit, cell_volume, grid.velocity_star, full);
      std::vector<unsigned char> needed;
      weak_counts[c++] = usl_needed_nodes(grid, limit, cell_volume, needed);
      updated_particle_grid_velocity_at(p, st, grid, dt, needed, part);
      bcs.apply(grid, part);
      keep_stable_usl_nodes(grid, limit, cell_volume, grid.velocity_star, part);
      ASSERT_EQ(full.size(), part.size());
      for (std::size_t n = 0; n < full.size(); ++n) EXPECT_EQ(full[n], part[n]) << "node " << n << " limit " << limit;
    }
    // The three cases are what they say: none, some, all nodes under-filled.
    EXPECT_EQ(weak_counts[0], 0u);
    EXPECT_GT(weak_counts[1], 0u);
    EXPECT_LT(weak_counts[1], g.count());
    EXPECT_EQ(weak_counts[2], g.count());
  }
}

}  // namespace
}  // namespace tephra
