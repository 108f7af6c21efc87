// Boundary-condition descriptions: what the deck says is what is stored
// (face, material, kind, label, value), lookups prefer an exact material id
// over id="all", and bad input is an error at the element.
#include <gtest/gtest.h>

#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "core/grid/BoundaryConditions.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

namespace {

std::unique_ptr<Deck> bc_deck(const std::string& body) {
  return load_deck_from_string("<Uintah_specification>\n<Grid>\n<BoundaryConditions>\n" + body +
                                   "</BoundaryConditions>\n</Grid>\n</Uintah_specification>\n",
                               "inline.ups", ".");
}

BoundaryConditions parse(const std::string& body) {
  auto deck = bc_deck(body);
  return parse_boundary_conditions(deck->root.require_child("Grid"));
}

void expect_error_at(const std::string& body, int line, const std::string& element_suffix) {
  auto deck = bc_deck(body);
  try {
    parse_boundary_conditions(deck->root.require_child("Grid"));
    FAIL() << "expected a DeckError for\n" << body;
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().line, line) << e.what();
    const std::string& el = e.where().element;
    ASSERT_GE(el.size(), element_suffix.size()) << e.what();
    EXPECT_EQ(el.substr(el.size() - element_suffix.size()), element_suffix) << e.what();
  }
}

}  // namespace

TEST(GridBCs, StoresWhatTheDeckSays) {
  BoundaryConditions bcs = parse(
      "<Face side=\"x-\">\n"
      "  <BCType id=\"all\" var=\"Dirichlet\" label=\"Velocity\"><value>[1.5, 0, -2]</value></BCType>\n"
      "  <BCType id=\"1\" var=\"Neumann\" label=\"Velocity\"><value>[0,0,0]</value></BCType>\n"
      "  <BCType id=\"0\" var=\"Neumann\" label=\"Pressure\"><value> 0. </value></BCType>\n"
      "  <BCType id=\"0\" var=\"computeFromDensity\" label=\"SpecificVol\"><value>0.0</value></BCType>\n"
      "</Face>\n"
      "<Face side=\"z+\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"> </BCType></Face>\n"
      "<Face circle=\"y-\" origin=\"[0.5, 0, 0.5]\" radius=\"0.1\">\n"
      "  <BCType id=\"0\" var=\"Dirichlet\" label=\"Temperature\"><value>600</value></BCType>\n"
      "</Face>\n");
  ASSERT_EQ(bcs.list.size(), 6u);

  const BoundaryCondition* v0 = bcs.find(GridFace::XMinus, 0, "Velocity");
  ASSERT_NE(v0, nullptr);
  EXPECT_EQ(v0->material, kAllMaterials);  // material 0 has no own entry: id="all" applies
  EXPECT_EQ(v0->kind, BCKind::Dirichlet);
  EXPECT_TRUE(v0->has_value);
  EXPECT_TRUE(v0->is_vector);
  EXPECT_EQ(v0->vector, Vec3(1.5, 0, -2));
  EXPECT_EQ(v0->where.file, "inline.ups");
  EXPECT_EQ(v0->where.line, 5);

  const BoundaryCondition* v1 = bcs.find(GridFace::XMinus, 1, "Velocity");
  ASSERT_NE(v1, nullptr);
  EXPECT_EQ(v1->material, 1);  // its own entry wins over id="all"
  EXPECT_EQ(v1->kind, BCKind::Neumann);

  const BoundaryCondition* p = bcs.find(GridFace::XMinus, 0, "Pressure");
  ASSERT_NE(p, nullptr);
  EXPECT_FALSE(p->is_vector);
  EXPECT_EQ(p->scalar, 0.0);
  EXPECT_EQ(bcs.find(GridFace::XMinus, 1, "Pressure"), nullptr);  // only material 0 has one
  EXPECT_EQ(bcs.find(GridFace::XPlus, 0, "Velocity"), nullptr);

  const BoundaryCondition* sym = bcs.find(GridFace::ZPlus, 3, "Symmetric");
  ASSERT_NE(sym, nullptr);
  EXPECT_EQ(sym->kind, BCKind::Symmetry);
  EXPECT_FALSE(sym->has_value);

  // A circle on y- is a region, not the whole face: find() skips it, on_face() lists it.
  EXPECT_EQ(bcs.find(GridFace::YMinus, 0, "Temperature"), nullptr);
  auto on_ym = bcs.on_face(GridFace::YMinus, 0);
  ASSERT_EQ(on_ym.size(), 1u);
  EXPECT_EQ(on_ym[0]->region.kind, FaceRegion::Circle);
  EXPECT_EQ(on_ym[0]->region.origin, Vec3(0.5, 0, 0.5));
  EXPECT_EQ(on_ym[0]->region.radius, 0.1);
  EXPECT_EQ(on_ym[0]->scalar, 600.0);
  EXPECT_EQ(face_axis(GridFace::YMinus), 1);
  EXPECT_FALSE(face_is_upper(GridFace::YMinus));
  EXPECT_TRUE(face_is_upper(GridFace::ZPlus));
}

TEST(GridBCs, LodiBlockIsKept) {
  BoundaryConditions bcs = parse(
      "<LODI><press_infinity>101325</press_infinity><sigma>0.27</sigma><material>air</material></LODI>\n"
      "<Face side=\"x+\"><BCType id=\"0\" var=\"LODI\" label=\"Pressure\"><value>101325</value></BCType></Face>\n");
  ASSERT_TRUE(bcs.lodi.has_value());
  EXPECT_EQ(bcs.lodi->press_infinity, 101325.0);
  EXPECT_EQ(bcs.lodi->sigma, 0.27);
  EXPECT_FALSE(bcs.lodi->li_scale.has_value());
  EXPECT_EQ(bcs.lodi->material, "air");
  EXPECT_EQ(bcs.find(GridFace::XPlus, 0, "Pressure")->kind, BCKind::LODI);
  EXPECT_FALSE(bcs.sine.has_value());
}

TEST(GridBCs, NoBlockMeansNoConditions) {
  auto deck = load_deck_from_string("<Uintah_specification>\n<Grid>\n</Grid>\n</Uintah_specification>\n",
                                    "inline.ups", ".");
  EXPECT_TRUE(parse_boundary_conditions(deck->root.require_child("Grid")).empty());
}

TEST(GridBCs, BadInputIsAnErrorAtTheElement) {
  // Line 4 is the first line of the body.
  expect_error_at("<Face side=\"x-\">\n<BCType id=\"all\" var=\"Dirichlet\" label=\"Velocity\"> </BCType>\n</Face>\n",
                  5, "Face/BCType");  // Dirichlet without <value>
  expect_error_at("<Face side=\"w-\">\n<BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/>\n</Face>\n", 4,
                  "BoundaryConditions/Face");
  expect_error_at("<Face side=\"x-\">\n<BCType id=\"first\" var=\"symmetry\" label=\"Symmetric\"/>\n</Face>\n", 5,
                  "Face/BCType");
  expect_error_at("<Face side=\"x-\">\n<BCType id=\"all\" var=\"Dirichlett\" label=\"Velocity\"/>\n</Face>\n", 5,
                  "Face/BCType");
  expect_error_at("<Face side=\"x-\">\n<BCType id=\"all\" var=\"Dirichlet\" label=\"Velocity\">\n"
                  "<value>1.0</value>\n</BCType>\n</Face>\n",
                  6, "BCType/value");  // a Velocity value is a vector
  expect_error_at("<Face side=\"x-\">\n<BCType id=\"0\" var=\"Neumann\" label=\"Pressure\">\n"
                  "<value>[1,2,3]</value>\n</BCType>\n</Face>\n",
                  6, "BCType/value");  // a Pressure value is a number
  expect_error_at("<Face side=\"x-\" circle=\"x-\" origin=\"[0,0,0]\" radius=\"1\">\n</Face>\n", 4, "Face");
  expect_error_at("<Face circle=\"x-\" origin=\"[0,0,0]\">\n</Face>\n", 4, "Face");  // no radius
  expect_error_at("<Face side=\"x-\">\n<BCType id=\"0\" var=\"Neumann\" label=\"Pressure\"><value>0</value></BCType>\n"
                  "<BCType id=\"0\" var=\"Dirichlet\" label=\"Pressure\"><value>1</value></BCType>\n</Face>\n",
                  6, "Face/BCType");  // a second Pressure condition for material 0
  expect_error_at("<Fase side=\"x-\">\n</Fase>\n", 4, "BoundaryConditions/Fase");

  auto deck = bc_deck("<Face side=\"x-\">\n<BCType id=\"0\" var=\"VelocityFileInput\" label=\"Velocity\">"
                      "<inputfile>v.dat</inputfile></BCType>\n</Face>\n");
  EXPECT_THROW(parse_boundary_conditions(deck->root.require_child("Grid")), MissingFeature);
}

// Two shared decks checked entry by entry against their text.
TEST(GridBCs, SharedDecksReadAsWritten) {
  {
    // disks_sulsky.ups: zero-velocity Dirichlet on x-, x+, y-, y+; symmetry on z-, z+.
    auto deck = load_deck(test::shared_dir() + "/decks/inputs/UintahRelease/MPM/disks_sulsky.ups");
    BoundaryConditions bcs = parse_boundary_conditions(deck->root.require_child("Grid"));
    ASSERT_EQ(bcs.list.size(), 6u);
    for (GridFace f : {GridFace::XMinus, GridFace::XPlus, GridFace::YMinus, GridFace::YPlus}) {
      const BoundaryCondition* v = bcs.find(f, 0, "Velocity");
      ASSERT_NE(v, nullptr);
      EXPECT_EQ(v->kind, BCKind::Dirichlet);
      EXPECT_EQ(v->vector, Vec3::Zero());
    }
    for (GridFace f : {GridFace::ZMinus, GridFace::ZPlus})
      EXPECT_EQ(bcs.find(f, 1, "Symmetric")->kind, BCKind::Symmetry);
  }
  {
    // ICE/advect.ups: on each of 6 faces, material 0 has Neumann Pressure,
    // Velocity, Temperature, Density (zero gradients) and computeFromDensity SpecificVol.
    auto deck = load_deck(test::shared_dir() + "/decks/inputs/ICE/advect.ups");
    BoundaryConditions bcs = parse_boundary_conditions(deck->root.require_child("Grid"));
    ASSERT_EQ(bcs.list.size(), 30u);
    for (int f = 0; f < 6; ++f) {
      const GridFace face = static_cast<GridFace>(f);
      for (const char* label : {"Pressure", "Velocity", "Temperature", "Density"}) {
        const BoundaryCondition* bc = bcs.find(face, 0, label);
        ASSERT_NE(bc, nullptr) << face_name(face) << " " << label;
        EXPECT_EQ(bc->kind, BCKind::Neumann);
        EXPECT_EQ(bc->material, 0);
        EXPECT_EQ(bc->is_vector, std::string(label) == "Velocity");
        EXPECT_EQ(bc->scalar, 0.0);
        EXPECT_EQ(bc->vector, Vec3::Zero());
      }
      EXPECT_EQ(bcs.find(face, 0, "SpecificVol")->kind, BCKind::ComputeFromDensity);
      EXPECT_EQ(bcs.find(face, 1, "Pressure"), nullptr);
    }
  }
}
