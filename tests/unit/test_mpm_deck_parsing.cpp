// Reading the <MPM> flags and grid boundary conditions: accepted values,
// MissingFeature (exit 3) for valid-but-unimplemented input, DeckError (exit 1)
// for invalid input, both located at the element.
#include <gtest/gtest.h>

#include "core/deck/DeckLoader.h"
#include "mpm/GridBoundaryConditions.h"
#include "mpm/MpmFlags.h"

namespace tephra {
namespace {

std::unique_ptr<Deck> deck(const std::string& body) {
  return load_deck_from_string("<Uintah_specification>" + body + "</Uintah_specification>", "t.ups", ".");
}

TEST(MpmDeckParsing, FlagsAcceptDefaultsAndRejectTheRest) {
  auto ok = deck("<MPM><time_integrator>explicit</time_integrator><interpolator>linear</interpolator>"
                 "<withColor>true</withColor><do_grid_reset>true</do_grid_reset>"
                 "<artificial_damping_coeff>0.0</artificial_damping_coeff></MPM>");
  EXPECT_NO_THROW(parse_mpm_flags(ok->root.child("MPM")));
  EXPECT_NO_THROW(parse_mpm_flags(nullptr));
  EXPECT_EQ(parse_mpm_flags(deck("<MPM><interpolator>gimp</interpolator></MPM>")->root.child("MPM")).interpolator.kind,
            InterpolatorKind::Gimp);
  EXPECT_EQ(parse_mpm_flags(deck("<MPM><interpolator>3rdorderBS</interpolator><cpdi_lcrit>0.9</cpdi_lcrit></MPM>")
                                ->root.child("MPM"))
                .interpolator.cpdi_lcrit,
            0.9);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><interpolator>cpti</interpolator></MPM>")->root.child("MPM")),
               MissingFeature);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><cpdi_lcrit>-1</cpdi_lcrit></MPM>")->root.child("MPM")), DeckError);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><interpolator>gimpy</interpolator></MPM>")->root.child("MPM")),
               DeckError);
  EXPECT_THROW(
      parse_mpm_flags(deck("<MPM><artificial_damping_coeff>0.1</artificial_damping_coeff></MPM>")->root.child("MPM")),
      MissingFeature);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><no_such_flag>1</no_such_flag></MPM>")->root.child("MPM")),
               MissingFeature);
  try {
    parse_mpm_flags(deck("<MPM>\n<time_integrator>implicit</time_integrator></MPM>")->root.child("MPM"));
    FAIL();
  } catch (const MissingFeature& e) {
    EXPECT_NE(std::string(e.what()).find("t.ups:2"), std::string::npos) << e.what();
  }
}

TEST(MpmDeckParsing, BoundaryConditions) {
  auto d = deck(
      "<Grid><BoundaryConditions>"
      "<Face side='x-'><BCType id='all' var='Dirichlet' label='Velocity'><value>[1,2,3]</value></BCType></Face>"
      "<Face side='z+'><BCType id='all' var='symmetry' label='Symmetric'></BCType>"
      "<BCType id='0' var='Dirichlet' label='Pressure'><value>1</value></BCType></Face>"
      "<Face side='y+'><BCType id='1' var='Dirichlet' label='Velocity'><value>[9,9,9]</value></BCType></Face>"
      "</BoundaryConditions></Grid>");
  const DeckNode* bcs = d->root.require_child("Grid").child("BoundaryConditions");
  GridBoundaryConditions b = parse_grid_boundary_conditions(bcs, 0);
  EXPECT_EQ(b.face[0].kind, FaceVelocityBC::Kind::Velocity);
  EXPECT_EQ(b.face[0].value, Vec3(1, 2, 3));
  EXPECT_EQ(b.face[5].kind, FaceVelocityBC::Kind::Symmetry);
  EXPECT_EQ(b.face[3].kind, FaceVelocityBC::Kind::None);  // id='1': another material
  EXPECT_EQ(parse_grid_boundary_conditions(bcs, 1).face[3].kind, FaceVelocityBC::Kind::Velocity);

  auto neumann = deck(
      "<Grid><BoundaryConditions><Face side='x-'><BCType id='all' var='Neumann' label='Velocity'>"
      "<value>[0,0,0]</value></BCType></Face></BoundaryConditions></Grid>");
  EXPECT_THROW(parse_grid_boundary_conditions(neumann->root.require_child("Grid").child("BoundaryConditions"), 0),
               MissingFeature);
  auto bad_side = deck(
      "<Grid><BoundaryConditions><Face side='w-'><BCType id='all' var='symmetry' label='Symmetric'>"
      "</BCType></Face></BoundaryConditions></Grid>");
  EXPECT_THROW(parse_grid_boundary_conditions(bad_side->root.require_child("Grid").child("BoundaryConditions"), 0),
               DeckError);
}

}  // namespace
}  // namespace tephra
