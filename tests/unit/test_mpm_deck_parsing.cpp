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
  EXPECT_EQ(parse_mpm_flags(deck("<MPM><interpolator>cpti</interpolator></MPM>")->root.child("MPM")).interpolator.kind,
            InterpolatorKind::Cpti);
  EXPECT_EQ(
      parse_mpm_flags(deck("<MPM><interpolator>4thorderBS</interpolator></MPM>")->root.child("MPM")).interpolator.kind,
      InterpolatorKind::CubicBspline);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><interpolator>fast_cpdi</interpolator></MPM>")->root.child("MPM")),
               MissingFeature);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><cpdi_lcrit>-1</cpdi_lcrit></MPM>")->root.child("MPM")), DeckError);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><interpolator>gimpy</interpolator></MPM>")->root.child("MPM")),
               DeckError);
  EXPECT_EQ(
      parse_mpm_flags(deck("<MPM><artificial_damping_coeff>0.1</artificial_damping_coeff></MPM>")->root.child("MPM"))
          .artificial_damping_coeff,
      0.1);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><erosion algorithm='BrittleDamage'/></MPM>")->root.child("MPM")),
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

TEST(MpmDeckParsing, ThermalDampingDeletionErosionAndStabilizationFlags) {
  const MpmFlags d = parse_mpm_flags(nullptr);  // Vaango's defaults
  EXPECT_TRUE(d.explicit_heat_conduction);
  EXPECT_EQ(d.artificial_damping_coeff, 0.0);
  EXPECT_EQ(d.minimum_particle_mass, 3e-15);
  EXPECT_EQ(d.maximum_particle_velocity, 3e105);
  EXPECT_FALSE(d.delete_rogue_particles);
  EXPECT_EQ(d.erosion, ErosionAlgorithm::None);
  EXPECT_FALSE(d.pressure_stabilization);
  const MpmFlags f = parse_mpm_flags(
      deck("<MPM><do_explicit_heat_conduction>false</do_explicit_heat_conduction>"
           "<minimum_particle_mass>1e-9</minimum_particle_mass><maximum_particle_velocity>1e3</maximum_particle_velocity>"
           "<delete_rogue_particles>true</delete_rogue_particles><erosion algorithm='AllowNoTension'/>"
           "<do_pressure_stabilization>true</do_pressure_stabilization></MPM>")
          ->root.child("MPM"));
  EXPECT_FALSE(f.explicit_heat_conduction);
  EXPECT_EQ(f.minimum_particle_mass, 1e-9);
  EXPECT_EQ(f.maximum_particle_velocity, 1e3);
  EXPECT_TRUE(f.delete_rogue_particles);
  EXPECT_EQ(f.erosion, ErosionAlgorithm::AllowNoTension);
  EXPECT_TRUE(f.pressure_stabilization);
  // Vaango: artificial viscosity implies its heating unless the deck says no;
  // heating without the viscosity is an error.
  EXPECT_TRUE(parse_mpm_flags(deck("<MPM><artificial_viscosity>true</artificial_viscosity></MPM>")->root.child("MPM"))
                  .artificial_viscosity_heating);
  EXPECT_FALSE(parse_mpm_flags(deck("<MPM><artificial_viscosity>true</artificial_viscosity>"
                                    "<artificial_viscosity_heating>false</artificial_viscosity_heating></MPM>")
                                   ->root.child("MPM"))
                   .artificial_viscosity_heating);
  EXPECT_THROW(
      parse_mpm_flags(
          deck("<MPM><artificial_viscosity_heating>true</artificial_viscosity_heating></MPM>")->root.child("MPM")),
      DeckError);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><artificial_damping_coeff>-1</artificial_damping_coeff></MPM>")->root.child("MPM")),
               DeckError);
  EXPECT_THROW(parse_mpm_flags(deck("<MPM><minimum_particle_mass>0</minimum_particle_mass></MPM>")->root.child("MPM")),
               DeckError);
}

TEST(MpmDeckParsing, TemperatureBoundaryConditions) {
  auto d = deck(
      "<Grid><BoundaryConditions>"
      "<Face side='x-'><BCType id='all' var='Dirichlet' label='Temperature'><value>400</value></BCType></Face>"
      "<Face side='x+'><BCType id='all' var='Neumann' label='Temperature'><value>0</value></BCType></Face>"
      "</BoundaryConditions></Grid>");
  GridBoundaryConditions b = parse_grid_boundary_conditions(d->root.require_child("Grid").child("BoundaryConditions"), 0);
  ASSERT_TRUE(b.temperature[0].has_value());
  EXPECT_EQ(*b.temperature[0], 400.0);
  EXPECT_FALSE(b.temperature[1].has_value());  // zero flux: the natural condition
  auto flux = deck(
      "<Grid><BoundaryConditions>"
      "<Face side='x+'><BCType id='all' var='Neumann' label='Temperature'><value>5</value></BCType></Face>"
      "</BoundaryConditions></Grid>");
  EXPECT_THROW(parse_grid_boundary_conditions(flux->root.require_child("Grid").child("BoundaryConditions"), 0),
               MissingFeature);
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

  // Zero-gradient velocity (the MPMICE decks' open faces) is a free face for
  // the MPM grid; a non-zero gradient is not supported.
  auto neumann0 = deck(
      "<Grid><BoundaryConditions><Face side='x-'><BCType id='all' var='Neumann' label='Velocity'>"
      "<value>[0,0,0]</value></BCType></Face></BoundaryConditions></Grid>");
  EXPECT_EQ(parse_grid_boundary_conditions(neumann0->root.require_child("Grid").child("BoundaryConditions"), 0)
                .face[0].kind,
            FaceVelocityBC::Kind::None);
  auto neumann = deck(
      "<Grid><BoundaryConditions><Face side='x-'><BCType id='all' var='Neumann' label='Velocity'>"
      "<value>[1,0,0]</value></BCType></Face></BoundaryConditions></Grid>");
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

namespace tephra {
namespace {

// <artificial_viscosity> and its coefficients (Vaango defaults 0.2, 2.0),
// <deformation_gradient algorithm> with <num_terms> (Vaango default 1).
TEST(MpmDeckParsing, ArtificialViscosityAndDeformationGradientFlags) {
  auto flags = [](const std::string& body) {
    auto d = load_deck_from_string("<Uintah_specification><MPM>" + body + "</MPM></Uintah_specification>", "t.ups", ".");
    return parse_mpm_flags(d->root.child("MPM"));
  };
  const MpmFlags none = flags("");
  EXPECT_FALSE(none.artificial_viscosity);
  EXPECT_EQ(none.artificial_viscosity_coeff1, 0.2);
  EXPECT_EQ(none.artificial_viscosity_coeff2, 2.0);
  EXPECT_EQ(none.deformation_gradient, "first_order");
  EXPECT_EQ(none.deformation_gradient_terms, 1);
  const MpmFlags av = flags("<artificial_viscosity>true</artificial_viscosity><artificial_viscosity_heating>true"
                            "</artificial_viscosity_heating><artificial_viscosity_coeff1>0.3</artificial_viscosity_coeff1>"
                            "<artificial_viscosity_coeff2>1.5</artificial_viscosity_coeff2>");
  EXPECT_TRUE(av.artificial_viscosity);
  EXPECT_TRUE(av.artificial_viscosity_heating);
  EXPECT_EQ(av.artificial_viscosity_coeff1, 0.3);
  EXPECT_EQ(av.artificial_viscosity_coeff2, 1.5);
  EXPECT_THROW(flags("<artificial_viscosity_coeff1>-1</artificial_viscosity_coeff1>"), DeckError);
  const MpmFlags ts = flags("<deformation_gradient algorithm=\"taylor_series\"><num_terms>5</num_terms></deformation_gradient>");
  EXPECT_EQ(ts.deformation_gradient, "taylor_series");
  EXPECT_EQ(ts.deformation_gradient_terms, 5);
  EXPECT_EQ(flags("<deformation_gradient algorithm=\"subcycling\"/>").deformation_gradient, "subcycling");
  EXPECT_THROW(flags("<deformation_gradient algorithm=\"exact\"/>"), DeckError);
  EXPECT_THROW(flags("<deformation_gradient algorithm=\"taylor_series\"><num_terms>0</num_terms></deformation_gradient>"),
               DeckError);
  EXPECT_THROW(flags("<deformation_gradient algorithm=\"taylor_series\"><terms>3</terms></deformation_gradient>"),
               DeckError);
  EXPECT_TRUE(flags("<use_load_curves>true</use_load_curves>").use_load_curves);
}

}  // namespace
}  // namespace tephra
