// Particles listed in a file (<geom_object><file>, core/geometry/ParticleFile.h,
// Vaango's FileGeometryPiece): the columns named by <var>, the pfs split
// files (usePFS), seeding one particle per point with m = rho0 V, and the
// errors that name the data file and line.
#include <gtest/gtest.h>

#include <fstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "core/geometry/GeometryPiece.h"
#include "core/geometry/ParticleFile.h"
#include "mpm/ParticleSeeding.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

void write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::unique_ptr<Deck> deck_of(const std::string& file_element) {
  return load_deck_from_string("<Uintah_specification>\n<geom_object>\n" + file_element +
                                   "\n<res>[2,2,2]</res>\n<velocity>[1,0,0]</velocity>\n"
                                   "<temperature>300</temperature>\n</geom_object>\n</Uintah_specification>\n",
                               "file.ups", ".");
}

GeometryPieceP parse(const std::string& file_element) {
  auto deck = deck_of(file_element);
  GeometryRegistry reg;
  return reg.parse_geom_object(*deck->root.child("geom_object"));
}

// Unit cube, 4 cells per side (cell volume 1/64).
Grid unit_grid() {
  Grid g;
  g.lower = Vec3::Zero();
  g.upper = Vec3::Ones();
  g.cells = IntVec3::Constant(4);
  g.dx = Vec3::Constant(0.25);
  return g;
}

TEST(MpmParticleFile, ColumnsAndSeeding) {
  const std::string dir = test::scratch_dir("particle_file_columns");
  write(dir + "/pts.txt",
        "# x y z volume temperature color\n"
        "0.1 0.2 0.3  1e-3 310 2\n"
        "\n"
        "0.5 0.5 0.5  2e-3 320 3\n"
        "0.9 0.8 0.7  4e-3 330 4\n");
  const GeometryPieceP piece =
      parse("<file><name>" + dir + "/pts.txt</name><var>p.volume</var><var>p.temperature</var>"
            "<var>p.color</var><usePFS>false</usePFS></file>");
  const auto* f = dynamic_cast<const ParticleFilePiece*>(piece.get());
  ASSERT_NE(f, nullptr);
  ASSERT_EQ(f->data().x.size(), 3u);
  EXPECT_EQ(f->data().where(2), dir + "/pts.txt:5");
  // inside(): the bounding box of the points widened by 1e-5 (Vaango).
  EXPECT_TRUE(piece->inside(Vec3(0.1 - 0.9e-5, 0.5, 0.5)));
  EXPECT_FALSE(piece->inside(Vec3(0.1 - 1.1e-5, 0.5, 0.5)));
  EXPECT_NEAR(piece->bounding_box().hi[0], 0.9 + 1e-5, 1e-15);

  Particles p;
  long long id = 0;
  ParticleSource src;
  src.piece = piece;
  src.velocity = Vec3(1, 0, 0);
  src.temperature = 300;
  seed_particles(unit_grid(), {src}, 2000.0, p, id);
  ASSERT_EQ(p.size(), 3u);
  const double V[3] = {1e-3, 2e-3, 4e-3}, T[3] = {310, 320, 330}, C[3] = {2, 3, 4};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(p.volume[i], V[i]);
    EXPECT_EQ(p.mass[i], 2000.0 * V[i]);  // m = rho0 V
    EXPECT_EQ(p.temperature[i], T[i]);
    EXPECT_EQ(p.color[i], C[i]);
    EXPECT_EQ(p.v[i], Vec3(1, 0, 0));  // the geom_object's velocity (no p.velocity column)
  }
  EXPECT_EQ(p.x[1], Vec3(0.5, 0.5, 0.5));
}

// usePFS (Vaango's default): <name>.0, <name>.1, ... each opening with the
// bounding-box line; without p.volume, V = cell volume / (res0 res1 res2).
TEST(MpmParticleFile, PfsSplitFilesAndDefaultVolume) {
  const std::string dir = test::scratch_dir("particle_file_pfs");
  write(dir + "/pts.0", "0 0 0 1 1 1\n0.1 0.1 0.1 0 0 -1\n0.2 0.2 0.2 0 0 -2\n");
  write(dir + "/pts.1", "0 0 0 1 1 1\n0.7 0.7 0.7 5 0 0\n");
  const GeometryPieceP piece = parse("<file><name>" + dir + "/pts</name><var>p.velocity</var></file>");
  const auto& d = dynamic_cast<const ParticleFilePiece&>(*piece).data();
  ASSERT_EQ(d.x.size(), 3u);
  EXPECT_EQ(d.where(2), dir + "/pts.1:2");
  Particles p;
  long long id = 0;
  ParticleSource src;
  src.piece = piece;
  src.res = IntVec3(2, 2, 2);
  seed_particles(unit_grid(), {src}, 1000.0, p, id);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_DOUBLE_EQ(p.volume[0], 0.25 * 0.25 * 0.25 / 8.0);
  EXPECT_EQ(p.v[1], Vec3(0, 0, -2));
  EXPECT_EQ(p.v[2], Vec3(5, 0, 0));
  EXPECT_EQ(id, 3);
}

void expect_row_error(const std::string& rows, int line, const std::string& words) {
  const std::string dir = test::scratch_dir("particle_file_bad");
  write(dir + "/bad.txt", rows);
  try {
    parse("<file><name>" + dir + "/bad.txt</name><var>p.volume</var><usePFS>false</usePFS></file>");
    ADD_FAILURE() << "expected a DeckError for\n" << rows;
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, dir + "/bad.txt");
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(MpmParticleFile, BadRowsNameTheFileAndLine) {
  expect_row_error("0 0 0 1\n0 0 0\n", 2, "row has 3 numbers, expected 4");
  expect_row_error("0 0 0 1\n\n0 0 0 1 5\n", 3, "expected 4");
  expect_row_error("0 0 0 1\n0 0 zero 1\n", 2, "'zero' is not a number");
  expect_row_error("0 0 0 1\n0 0 0 -1\n", 2, "p.volume must be > 0");
  expect_row_error("0 0 0 nan\n", 1, "non-finite");
}

TEST(MpmParticleFile, PointOutsideTheDomainNamesItsLine) {
  const std::string dir = test::scratch_dir("particle_file_outside");
  write(dir + "/pts.txt", "0.5 0.5 0.5\n1.5 0.5 0.5\n");
  ParticleSource src;
  src.piece = parse("<file><name>" + dir + "/pts.txt</name><usePFS>false</usePFS></file>");
  Particles p;
  long long id = 0;
  try {
    seed_particles(unit_grid(), {src}, 1.0, p, id);
    ADD_FAILURE() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, dir + "/pts.txt");
    EXPECT_EQ(e.where().line, 2);
  }
}

TEST(MpmParticleFile, DeckErrorsAndMissingFeatures) {
  const std::string dir = test::scratch_dir("particle_file_errors");
  write(dir + "/pts.txt", "0.5 0.5 0.5\n");
  // Missing file: located at the <name> element of the deck.
  try {
    parse("<file>\n<name>" + dir + "/none.txt</name><usePFS>false</usePFS></file>");
    ADD_FAILURE();
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, "file.ups");
    EXPECT_EQ(e.where().line, 4);
  }
  // usePFS defaults to true: pts.txt.0 is expected.
  EXPECT_THROW(parse("<file><name>" + dir + "/pts.txt</name></file>"), DeckError);
  EXPECT_THROW(parse("<file><name>" + dir + "/pts.txt</name><format>bin</format><usePFS>false</usePFS></file>"),
               MissingFeature);
  EXPECT_THROW(parse("<file><name>" + dir + "/pts.txt</name><var>p.rvec1</var><usePFS>false</usePFS></file>"),
               MissingFeature);
  EXPECT_THROW(parse("<file><name>" + dir + "/pts.txt</name><var>p.volum</var><usePFS>false</usePFS></file>"),
               DeckError);
  EXPECT_THROW(parse("<file><name>" + dir + "/pts.txt</name><usePFS>false</usePFS></file>\n<box><min>[0,0,0]</min>"
                     "<max>[1,1,1]</max></box>"),
               DeckError);  // the file must be the only piece
}

}  // namespace
}  // namespace tephra
