// Triangulated surfaces (tri pieces): inside by ray parity compared with the
// analytic solid they bound, on lattices that put points exactly on faces,
// edges and vertices (the degenerate rays), and volume by counting.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <fstream>
#include <random>

#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "core/geometry/GeometryPiece.h"
#include "core/geometry/Primitives.h"
#include "core/geometry/TriMesh.h"
#include "tests/support/TestPaths.h"
#include "test_geometry_support.h"

using namespace tephra;

namespace {

// The unit cube [0,1]^3 as 12 outward-oriented triangles.
TriMeshData unit_cube_mesh() {
  TriMeshData m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

// The tetrahedron {x, y, z >= 0, x + y + z <= 1}.
TriMeshData unit_tetra_mesh() {
  TriMeshData m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

void write_mesh(const TriMeshData& m, const std::string& prefix) {
  std::ofstream pts(prefix + ".pts"), tri(prefix + ".tri");
  for (const auto& v : m.vertices) pts << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : m.triangles) tri << t[0] << " " << t[1] << " " << t[2] << "\n";
}

}  // namespace

TEST(GeometryTri, CubeMeshMatchesClosedCubeIncludingFacesEdgesVertices) {
  TriMeshPiece cube(unit_cube_mesh());
  EXPECT_DOUBLE_EQ(cube.enclosed_volume(), 1.0);
  // Lattice step 1/8 from -1/4 to 5/4: many points lie exactly on faces,
  // edges, vertices and on the triangles' diagonals; x-rays graze edges.
  for (int i = -2; i <= 10; ++i)
    for (int j = -2; j <= 10; ++j)
      for (int k = -2; k <= 10; ++k) {
        const Vec3 x(i / 8.0, j / 8.0, k / 8.0);
        const bool expect = (x.array() >= 0).all() && (x.array() <= 1).all();
        ASSERT_EQ(cube.inside(x), expect) << x.transpose();
      }
}

TEST(GeometryTri, TetrahedronMeshMatchesItsInequalities) {
  TriMeshPiece tet(unit_tetra_mesh());
  EXPECT_DOUBLE_EQ(tet.enclosed_volume(), 1.0 / 6.0);
  for (int i = -1; i <= 9; ++i)
    for (int j = -1; j <= 9; ++j)
      for (int k = -1; k <= 9; ++k) {
        const Vec3 x(i / 8.0, j / 8.0, k / 8.0);  // sums of multiples of 1/8 are exact
        const bool expect = x.minCoeff() >= 0 && x.sum() <= 1;
        ASSERT_EQ(tet.inside(x), expect) << x.transpose();
      }
}

TEST(GeometryTri, RotatedCubeMeshAgreesWithParallelepiped) {
  TriMeshData m = unit_cube_mesh();
  const Mat3 R = Eigen::AngleAxisd(0.6, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 t(0.3, -0.2, 0.1);
  for (auto& v : m.vertices) v = 0.8 * R * v + t;
  TriMeshPiece mesh(m);
  ParallelepipedPiece p(t, t + 0.8 * R.col(0), t + 0.8 * R.col(1), t + 0.8 * R.col(2));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.5);
  for (int n = 0; n < 20000; ++n) {
    const Vec3 x(u(rng), u(rng), u(rng));
    ASSERT_EQ(mesh.inside(x), p.inside(x)) << x.transpose();
  }
}

TEST(GeometryTri, CountedVolumeOfMeshes) {
  // Cube: V = 1, A = 6. Tetrahedron: V = 1/6, A = 3/2 + sqrt(3)/2.
  TriMeshPiece cube(unit_cube_mesh()), tet(unit_tetra_mesh());
  const Vec3 shift(0.37, 0.61, 0.29);
  for (double h : {0.1, 0.05, 0.025}) {
    EXPECT_LE(std::abs(test::counted_volume(cube, h, shift) - 1.0), std::sqrt(3.0) * 6 * h);
    EXPECT_LE(std::abs(test::counted_volume(tet, h, shift) - 1.0 / 6) * 6,
              std::sqrt(3.0) * (1.5 + std::sqrt(3.0) / 2) * h * 6);
  }
  EXPECT_LT(std::abs(test::counted_volume(tet, 0.01, shift) - 1.0 / 6) * 6, 0.02);
}

TEST(GeometryTri, OpenMeshIsRejected) {
  TriMeshData m = unit_cube_mesh();
  m.triangles.pop_back();
  EXPECT_NE(closed_surface_problem(m).find("not closed"), std::string::npos);
  EXPECT_THROW(TriMeshPiece{m}, std::invalid_argument);
}

TEST(GeometryTri, DeckTriReadsFilesBesideTheDeckWithScaleAndTranslation) {
  const std::string dir = test::scratch_dir("geometry_tri");
  write_mesh(unit_tetra_mesh(), dir + "/tet");
  const std::string xml =
      "<Uintah_specification>\n<geom_object>\n<tri label=\"t\">\n"
      "<file_name_prefix>tet</file_name_prefix>\n<scaling_factor>2</scaling_factor>\n"
      "<translation_vector>[1, 0, 0]</translation_vector>\n</tri>\n</geom_object>\n"
      "</Uintah_specification>\n";
  { std::ofstream(dir + "/deck.ups") << xml; }
  auto deck = load_deck(dir + "/deck.ups");
  GeometryRegistry reg;
  auto p = reg.parse_geom_object(deck->root.require_child("geom_object"));
  // x = 2 q + (1, 0, 0): the tetrahedron {x-1, y, z >= 0, (x-1) + y + z <= 2}.
  EXPECT_EQ(p->type(), "tri");
  EXPECT_EQ(p->bounding_box().lo, Vec3(1, 0, 0));
  EXPECT_EQ(p->bounding_box().hi, Vec3(3, 2, 2));
  EXPECT_TRUE(p->inside(Vec3(1.5, 0.5, 0.5)));
  EXPECT_TRUE(p->inside(Vec3(3, 0, 0)));
  EXPECT_FALSE(p->inside(Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(p->inside(Vec3(2, 0.6, 0.6)));
  EXPECT_NEAR(dynamic_cast<const TriMeshPiece&>(*p).enclosed_volume(), 8.0 / 6.0, 1e-14);
}

TEST(GeometryTri, BadMeshFilesAreDeckErrorsNamingTheFileLine) {
  const std::string dir = test::scratch_dir("geometry_tri_bad");
  write_mesh(unit_tetra_mesh(), dir + "/bad");
  { std::ofstream(dir + "/bad.tri", std::ios::app) << "0 1 7\n"; }  // index out of range
  const std::string xml =
      "<Uintah_specification>\n<geom_object>\n<tri>\n<file_name_prefix>bad</file_name_prefix>\n"
      "</tri>\n</geom_object>\n</Uintah_specification>\n";
  { std::ofstream(dir + "/deck.ups") << xml; }
  auto deck = load_deck(dir + "/deck.ups");
  GeometryRegistry reg;
  try {
    reg.parse_geom_object(deck->root.require_child("geom_object"));
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(std::string(e.what()).find("bad.tri:5"), std::string::npos) << e.what();
  }
  // Missing files.
  auto missing = load_deck_from_string(
      "<Uintah_specification>\n<tri><file_name_prefix>nothere</file_name_prefix></tri>\n"
      "</Uintah_specification>\n", "m.ups", dir);
  EXPECT_THROW(reg.parse_piece(missing->root.children.front()), DeckError);
}
