// The node fill of the MUSL/USL choice in axisymmetric MPM (session 25;
// mpm/Axisymmetric.h axisymmetric_full_node_volumes, mpm/UpdatedGridVelocity.h).
//
// Claims:
// * V_full(i) = J(|r_i|) h_z / 2, J(r) = int N_i(s) s ds over the clipped hat
//   (r h_r off the axis, h_r^2/6 on it), is the node volume sum_p V_p S_gp of
//   a body that covers the node's whole support, per hoop node plane: exact
//   for GIMP at every node (the axis node included) and for the linear hat
//   at the nodes off the axis (2 particles per cell: sum_p r_p N(r_p) h/2 =
//   r_i h).
// * usl_needed_nodes with these volumes flags a node holding a tenth of a
//   full node's material at r = 0.9 m (fill 0.1 < the limit 0.218 at Courant
//   number 0.7); with the Cartesian reference h_x h_y h_z (the code before
//   session 25) the same node reads fill 0.1 r / (2 h_z) = 0.9 and keeps USL.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpm/Axisymmetric.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/UpdatedGridVelocity.h"

namespace tephra {
namespace {

// Axis at node i = 1 (one extra layer at r = -h_r), two hoop node planes k = 1, 2.
NodeGrid axis_grid() {
  NodeGrid g;
  g.h = Vec3(0.1, 0.25, 0.05);
  g.origin = Vec3(-0.1, -0.25, -0.05);
  g.n = IntVec3(13, 10, 3);
  g.extra = IntVec3(1, 1, 1);
  g.reset();
  return g;
}

// 2 x 2 particles per cell filling r in [0, 1.0], z in [0.25, 2.0], per-radian
// volumes V_p = A_p r_p (A_p = h_r h_z / 4), GIMP half-size h/4.
Particles filled_body(const NodeGrid& g) {
  Particles p;
  const double hr = g.h[0], hz = g.h[1];
  long id = 0;
  for (int a = 0; a < 20; ++a)
    for (int b = 0; b < 14; ++b) {
      const Vec3 x((a + 0.5) * hr / 2, 0.25 + (b + 0.5) * hz / 2, 0.025);
      const double V = hr * hz / 4 * x[0];
      p.add(x, Vec3::Zero(), V, V, 300.0, 0.0, id++, Vec3(0.5, 0.5, 1.0).asDiagonal());
    }
  return p;
}

std::vector<double> node_volumes(const Particles& p, const NodeGrid& g, InterpolatorKind kind) {
  Stencils s;
  EXPECT_EQ(compute_axisymmetric_stencils(p, g, kind, s), -1);
  std::vector<double> V(g.count(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t e = i * s.width; e < (i + 1) * s.width; ++e) V[s.node[e]] += p.volume[i] * s.w[e];
  return V;
}

TEST(AxisymmetricNodeFill, FullNodeVolumeIsTheFilledBodysNodeVolume) {
  const NodeGrid g = axis_grid();
  const Particles p = filled_body(g);
  const std::vector<double> full = axisymmetric_full_node_volumes(g);
  ASSERT_EQ(full.size(), std::size_t(g.n[0]));
  // Closed forms: the axis node h_r^2/6 h_z/2, node r_i = 0.5 m r_i h_r h_z/2.
  EXPECT_NEAR(full[1], 0.1 * 0.1 / 6 * 0.25 / 2, 1e-17);
  EXPECT_NEAR(full[6], 0.5 * 0.1 * 0.25 / 2, 1e-16);
  EXPECT_DOUBLE_EQ(full[0], full[2]);  // the extra node at r = -h_r: its mirror's
  for (InterpolatorKind kind : {InterpolatorKind::Gimp, InterpolatorKind::Linear}) {
    const std::vector<double> V = node_volumes(p, g, kind);
    double worst = 0;
    int checked = 0;
    // Nodes whose whole support lies in the body: r_i = 0 .. 0.9 m (i = 1 .. 10),
    // z_j = 0.5 .. 1.75 m (j = 3 .. 8); both hoop planes.
    for (int i = kind == InterpolatorKind::Gimp ? 1 : 2; i <= 10; ++i)
      for (int j = 3; j <= 8; ++j)
        for (int k = 1; k <= 2; ++k) {
          worst = std::max(worst, std::abs(V[g.index(i, j, k)] / full[std::size_t(i)] - 1.0));
          ++checked;
        }
    EXPECT_GT(checked, 100);
    EXPECT_LT(worst, 1e-13) << (kind == InterpolatorKind::Gimp ? "gimp" : "linear");
  }
}

TEST(AxisymmetricNodeFill, LightNodeFarFromTheAxisKeepsTheUpdatedParticleVelocity) {
  NodeGrid g = axis_grid();
  const std::vector<double> full = axisymmetric_full_node_volumes(g);
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) g.volume[g.index(i, j, k)] = full[std::size_t(i)];
  const std::size_t light = g.index(10, 5, 1);  // r = 0.9 m, a tenth of a full node
  g.volume[light] = 0.1 * full[10];
  const double limit = usl_fill_limit(0.7);
  EXPECT_NEAR(limit, 2 * 0.49 / 4.49, 1e-15);
  std::vector<unsigned char> needed;
  // With the full-node volumes only the light node is below the limit (the
  // return value; the node planes near the faces are flagged besides).
  EXPECT_EQ(usl_needed_nodes(g, limit, 0.0, needed, &full), 1u);
  EXPECT_EQ(needed[light], 1);
  // keep_stable_usl_nodes: v*_g only where the fill passes.
  std::vector<Vec3> v_star(g.count(), Vec3(1, 2, 0)), v(g.count(), Vec3::Zero());
  keep_stable_usl_nodes(g, limit, 0.0, v_star, v, &full);
  EXPECT_EQ(v[light], Vec3::Zero());
  EXPECT_EQ(v[g.index(9, 5, 1)], Vec3(1, 2, 0));  // a full node beside it keeps USL
  // The Cartesian reading h_x h_y h_z (before session 25): fill 0.1 * 0.9 / (2 * 0.05)
  // = 0.9 >= limit, so the light node kept v*_g.
  const double cell_volume = g.h[0] * g.h[1] * g.h[2];
  EXPECT_NEAR(g.volume[light] / cell_volume, 0.9, 1e-12);
  std::vector<Vec3> v_old(g.count(), Vec3::Zero());
  keep_stable_usl_nodes(g, limit, cell_volume, v_star, v_old);
  EXPECT_EQ(v_old[light], Vec3(1, 2, 0));
}

}  // namespace
}  // namespace tephra
