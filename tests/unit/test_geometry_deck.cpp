// Geometry from deck XML: every piece's element and children, global labels
// reused by name, each error case located at file:line:element, missing
// features, and every geom_object of the shared Vaango decks.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "core/geometry/GeometryPiece.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

namespace {

std::unique_ptr<Deck> deck_of(const std::string& body) {
  return load_deck_from_string("<Uintah_specification>\n" + body + "</Uintah_specification>\n",
                               "geom.ups", ".");
}

std::vector<const DeckNode*> geom_objects(const DeckNode& n) {
  std::vector<const DeckNode*> out;
  if (n.name == "geom_object") out.push_back(&n);
  for (const auto& c : n.children) {
    auto sub = geom_objects(c);
    out.insert(out.end(), sub.begin(), sub.end());
  }
  return out;
}

// Parses every geom_object of `body` in order with one registry; returns the pieces.
std::vector<GeometryPieceP> parse_all(const std::string& body, GeometryRegistry& reg) {
  auto deck = deck_of(body);
  std::vector<GeometryPieceP> out;
  for (const DeckNode* g : geom_objects(deck->root)) out.push_back(reg.parse_geom_object(*g));
  return out;
}

// Expects a DeckError at `line` whose element path ends with `element` and
// whose message contains `words`.
void expect_deck_error(const std::string& body, int line, const std::string& element,
                       const std::string& words) {
  GeometryRegistry reg;
  try {
    parse_all(body, reg);
    ADD_FAILURE() << "expected a DeckError for:\n" << body;
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, "geom.ups");
    EXPECT_EQ(e.where().line, line) << e.what();
    const std::string& el = e.where().element;
    EXPECT_TRUE(el.size() >= element.size() && el.compare(el.size() - element.size(), element.size(), element) == 0)
        << el << " does not end with " << element;
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

void expect_missing_feature(const std::string& body, const std::string& words) {
  GeometryRegistry reg;
  try {
    parse_all(body, reg);
    ADD_FAILURE() << "expected a MissingFeature for:\n" << body;
  } catch (const MissingFeature& e) {
    EXPECT_EQ(e.code(), ExitCode::MissingFeature);
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(GeometryDeck, EveryPieceParsesWithSchemaNames) {
  GeometryRegistry reg;
  auto p = parse_all(
      "<geom_object><box><min>[0,0,0]</min><max>[1,1,1]</max></box></geom_object>\n"
      "<geom_object><sphere><origin>[0,0,0]</origin><radius>1</radius></sphere></geom_object>\n"
      "<geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0,0,2]</top><radius>0.5</radius>"
      "</cylinder></geom_object>\n"
      "<geom_object><cone><bottom>[0,0,0]</bottom><bottom_radius>1</bottom_radius><top>[0,0,1]</top>"
      "<top_radius>0</top_radius></cone></geom_object>\n"
      "<geom_object><ellipsoid><origin>[0,0,0]</origin><r1>3</r1><r2>2</r2><r3>1</r3>"
      "<v1>[0,1,0]</v1><v2>[0,0,1]</v2></ellipsoid></geom_object>\n"
      "<geom_object><parallelepiped><p1>[0,0,0]</p1><p2>[1,0,0]</p2><p3>[1,1,0]</p3><p4>[0,0,1]</p4>"
      "</parallelepiped></geom_object>\n"
      "<geom_object><torus><center>[0,0,0]</center><axis_vector>[0,0,2]</axis_vector>"
      "<major_radius>2</major_radius><minor_radius>0.5</minor_radius></torus></geom_object>\n"
      "<geom_object><intersection><sphere><origin>[0,0,0]</origin><radius>1</radius></sphere>"
      "<box><min>[0,0,0]</min><max>[2,2,2]</max></box></intersection></geom_object>\n",
      reg);
  ASSERT_EQ(p.size(), 8u);
  const char* types[] = {"box", "sphere", "cylinder", "cone", "ellipsoid", "parallelepiped", "torus",
                         "intersection"};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(p[i]->type(), types[i]);
  // Ellipsoid: semi-axis r1 = 3 along v1 = y, r2 = 2 along z, r3 = 1 along v3 = v1 x v2 = x.
  EXPECT_TRUE(p[4]->inside(Vec3(0, 3, 0)));
  EXPECT_FALSE(p[4]->inside(Vec3(0, 3.01, 0)));
  EXPECT_TRUE(p[4]->inside(Vec3(0, 0, 2)));
  EXPECT_TRUE(p[4]->inside(Vec3(1, 0, 0)));
  EXPECT_FALSE(p[4]->inside(Vec3(1.01, 0, 0)));
  // Parallelepiped from p1 with adjacent corners (1,0,0), (1,1,0), (0,0,1): a sheared box.
  EXPECT_TRUE(p[5]->inside(Vec3(1.5, 0.9, 0.5)));   // p1 + 0.6 e1 + 0.9 e2 + 0.5 e3
  EXPECT_FALSE(p[5]->inside(Vec3(0.5, 0.9, 0.5)));  // c1 = 0.9 but c0 = -0.4
  // Torus around z: the tube centre circle at radius 2.
  EXPECT_TRUE(p[6]->inside(Vec3(0, 2.5, 0)));
  EXPECT_FALSE(p[6]->inside(Vec3(0, 0, 0)));
  // Intersection of the unit sphere and the positive octant box.
  EXPECT_TRUE(p[7]->inside(Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(p[7]->inside(Vec3(-0.5, 0.5, 0.5)));
}

TEST(GeometryDeck, EllipsoidSpellingsAgree) {
  // Vaango's code reads semi-axis vectors v1, v2, v3 (lengths = radii) or
  // axis-aligned rx, ry, rz; the schema names r1, r2, r3 with directions.
  GeometryRegistry reg;
  auto p = parse_all(
      "<geom_object><ellipsoid><origin>[1,0,0]</origin><v1>[0,2,0]</v1><v2>[0,0,1]</v2>"
      "<v3>[0.5,0,0]</v3></ellipsoid></geom_object>\n"
      "<geom_object><ellipsoid><origin>[1,0,0]</origin><rx>0.5</rx><ry>2</ry><rz>1</rz>"
      "</ellipsoid></geom_object>\n"
      "<geom_object><ellipsoid><origin>[1,0,0]</origin><r1>0.5</r1><r2>2</r2><r3>1</r3>"
      "</ellipsoid></geom_object>\n",
      reg);
  for (double x = 0.4; x <= 1.6; x += 0.05)
    for (double y = -2.1; y <= 2.1; y += 0.1)
      for (double z : {-0.5, 0.0, 0.3, 0.9}) {
        const Vec3 q(x, y, z);
        // ((x-1)/0.5)^2 + (y/2)^2 + z^2 <= 1
        const double f = std::pow((x - 1) / 0.5, 2) + std::pow(y / 2, 2) + z * z;
        if (std::abs(f - 1) < 1e-9) continue;
        for (const auto& e : p) EXPECT_EQ(e->inside(q), f <= 1) << q.transpose();
      }
}

TEST(GeometryDeck, LabelsAreReusedAcrossGeomObjects) {
  GeometryRegistry reg;
  auto p = parse_all(
      "<geom_object><box label=\"piston\"><min>[0,0,0]</min><max>[1,1,1]</max></box>"
      "<res>[2,2,2]</res><velocity>[0,0,0]</velocity><temperature>300</temperature>"
      "</geom_object>\n"
      "<geom_object><box label=\"piston\"/></geom_object>\n"
      "<geom_object><difference><box><min>[-1,-1,-1]</min><max>[2,2,2]</max></box>"
      "<union><box label = \"piston\"> </box><cylinder label=\"rod\"><bottom>[0,0,1]</bottom>"
      "<top>[0,0,2]</top><radius>0.1</radius></cylinder></union></difference>"
      "<density>1.2</density><pressure>101325</pressure></geom_object>\n"
      "<geom_object><cylinder label=\"rod\"></cylinder></geom_object>\n"
      // The same definition again (written differently) is the same piece.
      "<geom_object><box label=\"piston\"><min>[0.0, 0.0, 0.0]</min><max>[1,1,1.0]</max></box>"
      "</geom_object>\n",
      reg);
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0].get(), p[1].get());
  EXPECT_EQ(p[0].get(), p[4].get());
  EXPECT_EQ(p[0]->label, "piston");
  EXPECT_EQ(reg.find("piston").get(), p[0].get());
  EXPECT_EQ(p[3]->label, "rod");
  EXPECT_EQ(p[3].get(), reg.find("rod").get());
  EXPECT_EQ(reg.find("nothing"), nullptr);
  EXPECT_FALSE(p[2]->inside(Vec3(0.5, 0.5, 0.5)));  // in the piston: removed
  EXPECT_FALSE(p[2]->inside(Vec3(0, 0, 1.5)));      // in the rod: removed
  EXPECT_TRUE(p[2]->inside(Vec3(1.5, 1.5, 1.5)));
}

TEST(GeometryDeck, SeveralPiecesInOneGeomObjectAreTheirUnion) {
  GeometryRegistry reg;
  auto p = parse_all(
      "<geom_object><sphere><origin>[0,0,0]</origin><radius>1</radius></sphere>"
      "<sphere><origin>[5,0,0]</origin><radius>1</radius></sphere></geom_object>\n",
      reg);
  EXPECT_EQ(p[0]->type(), "union");
  EXPECT_TRUE(p[0]->inside(Vec3(5, 0, 0.9)));
  EXPECT_TRUE(p[0]->inside(Vec3(0, 0.9, 0)));
  EXPECT_FALSE(p[0]->inside(Vec3(2.5, 0, 0)));
}

TEST(GeometryDeck, ErrorsNameFileLineAndElement) {
  expect_deck_error("<geom_object>\n<box label=\"ghost\"/>\n</geom_object>\n", 3,
                    "geom_object/box", "'ghost' is used before it is defined");
  expect_deck_error(
      "<geom_object>\n<box label=\"a\"><min>[0,0,0]</min><max>[1,1,1]</max></box>\n</geom_object>\n"
      "<geom_object>\n<box label=\"a\"><min>[0,0,0]</min><max>[2,1,1]</max></box>\n</geom_object>\n",
      6, "geom_object/box", "already defined at geom.ups:3");
  expect_deck_error(
      "<geom_object>\n<box label=\"a\"><min>[0,0,0]</min><max>[1,1,1]</max></box>\n</geom_object>\n"
      "<geom_object>\n<sphere label=\"a\"/>\n</geom_object>\n",
      6, "geom_object/sphere", "refers to a <box>");
  expect_deck_error(
      "<geom_object>\n<difference>\n<box><min>[0,0,0]</min><max>[1,1,1]</max></box>\n"
      "</difference>\n</geom_object>\n",
      3, "geom_object/difference", "at least two pieces");
  expect_deck_error(
      "<geom_object>\n<sphere><origin>[0,0,0]</origin>\n<radius>0</radius></sphere>\n"
      "</geom_object>\n",
      4, "sphere/radius", "must be > 0");
  expect_deck_error(
      "<geom_object>\n<cylinder><bottom>[0,0,0]</bottom><top>[0,0,1]</top>\n<radius>-1</radius>"
      "</cylinder>\n</geom_object>\n",
      4, "cylinder/radius", "must be > 0");
  expect_deck_error(
      "<geom_object>\n<torus><center>[0,0,0]</center><axis_vector>[0,0,1]</axis_vector>"
      "<major_radius>1</major_radius>\n<minor_radius>0</minor_radius></torus>\n</geom_object>\n",
      4, "torus/minor_radius", "must be > 0");
  expect_deck_error(
      "<geom_object>\n<box>\n<min>[0,0,0]</min><max>[1,0,1]</max></box>\n</geom_object>\n", 3,
      "geom_object/box", "degenerate box");
  expect_deck_error(
      "<geom_object>\n<sphere>\n<origin>[0,0,0]</origin></sphere>\n</geom_object>\n", 3,
      "geom_object/sphere", "missing required element <radius>");
  expect_deck_error("<geom_object>\n<box/>\n</geom_object>\n", 3, "geom_object/box",
                    "no values and no label");
  expect_deck_error(
      "<geom_object>\n<box><min>[0,0,0]</min>\n<maxx>[1,1,1]</maxx></box>\n</geom_object>\n", 4,
      "box/maxx", "did you mean <max>");
  expect_deck_error("<geom_object>\n<sphear/>\n</geom_object>\n", 3, "geom_object/sphear",
                    "did you mean <sphere>");
  expect_deck_error("<geom_object>\n<res>[2,2,2]</res>\n</geom_object>\n", 2, "geom_object",
                    "no geometry piece");
  expect_deck_error(
      "<geom_object>\n<parallelepiped><p1>[0,0,0]</p1><p2>[1,0,0]</p2><p3>[0,1,0]</p3>"
      "<p4>[1,1,0]</p4>\n</parallelepiped>\n</geom_object>\n",
      3, "geom_object/parallelepiped", "coplanar");
  expect_deck_error(
      "<geom_object>\n<ellipsoid><origin>[0,0,0]</origin><r1>1</r1><r2>1</r2><r3>1</r3>"
      "<v1>[1,0,0]</v1><v2>[1,1,0]</v2>\n</ellipsoid>\n</geom_object>\n",
      3, "geom_object/ellipsoid", "not orthogonal");
}

TEST(GeometryDeck, UnsupportedPiecesAreMissingFeatures) {
  for (const char* piece : {"sphere_membrane", "sphere_shell", "cylinder_shell", "plane_shell",
                            "smoothcyl", "smooth_sphere", "abaqus_mesh"})
    expect_missing_feature(std::string("<geom_object><") + piece + "><radius>1</radius></" + piece +
                               "></geom_object>\n",
                           std::string("<") + piece + ">");
  expect_missing_feature("<geom_object><image><name>a.raw</name></image></geom_object>\n",
                         "<geom_object><image>");
}

// Every geom_object of the shared Vaango decks parses (labels, nested
// difference/union, references to labels defined in earlier materials).
TEST(GeometryDeck, AllSharedDecksParse) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(test::shared_dir()) / "decks";
  ASSERT_TRUE(fs::exists(root)) << root;
  int decks = 0, objects = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".ups") continue;
    {
      // Skip git symlink placeholders (a file holding only a relative path,
      // e.g. orderAccuracy/MPM/AA.ups -> ../../../StandAlone/inputs/MPM/AA.ups).
      std::ifstream in(entry.path());
      char first = 0;
      in >> first;
      if (first != '<') continue;
    }
    std::unique_ptr<Deck> deck;
    try {
      deck = load_deck(entry.path().string());
    } catch (const TephraError& e) {
      ADD_FAILURE() << "deck does not load: " << e.what();
      continue;
    }
    ++decks;
    GeometryRegistry reg;
    for (const DeckNode* g : geom_objects(deck->root)) {
      try {
        auto p = reg.parse_geom_object(*g);
        ASSERT_NE(p, nullptr);
        ++objects;
      } catch (const TephraError& e) {
        ADD_FAILURE() << e.what();
      }
    }
  }
  std::printf("  %d decks, %d geom_objects parsed\n", decks, objects);
  EXPECT_GT(decks, 20);
  EXPECT_GT(objects, 40);
}
