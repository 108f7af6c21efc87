// BndyForce_<face> / BndyContactArea_<face> (Vaango's computeInternalForce
// reductions). Oracle: a block of uniform Cauchy stress sigma filling whole
// cells from the z- face. For a particle of the first cell layer the shape
// function gradients of the four z = 0 nodes sum to (0, 0, -1/h) (sum_x S'_x =
// 0, sum_xy S_x S_y = 1), so sum_{z=0 nodes} f_int = sum_p V_p sigma e_z / h =
// sigma e_z A, A = Lx Ly, and BndyForce_zminus = -sigma e_z A. The "area" is
// Vaango's sum V_g / h over the same nodes: the first layer's particles sit at
// z = h/4 and 3h/4 with bottom weights 3/4 and 1/4, so the nodes collect half
// the layer's volume, A h / 2, and BndyContactArea_zminus = A/2 (Vaango's
// definition, not the geometric area). The z+ face, not reached, gives 0.
#include <gtest/gtest.h>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

TEST(MpmBoundaryForce, UniformStressBlockOnTheZMinusFace) {
  auto deck = load_deck_from_string(
      "<Uintah_specification><MPM><boundary_traction_faces>[zminus,zplus]</boundary_traction_faces></MPM>"
      "<MaterialProperties><MPM><material><density>1000</density>"
      "<constitutive_model type='comp_neo_hook'><bulk_modulus>1e6</bulk_modulus><shear_modulus>1e6</shear_modulus>"
      "</constitutive_model><thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
      "<geom_object><box><min>[0.1,0.1,0]</min><max>[0.3,0.4,0.2]</max></box><res>[2,2,2]</res>"
      "<velocity>[0,0,0]</velocity><temperature>300</temperature></geom_object></material></MPM>"
      "</MaterialProperties><Grid><Level><Box><lower>[0,0,0]</lower><upper>[0.5,0.5,0.5]</upper>"
      "<resolution>[5,5,5]</resolution><extraCells>[0,0,0]</extraCells><patches>[1,1,1]</patches></Box></Level>"
      "</Grid></Uintah_specification>",
      "b.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  Mat3 sigma;
  sigma << -3, 1, 2, 1, -5, 0.5, 2, 0.5, -7;
  for (Mat3& s : c->materials()[0].particles.stress) s = sigma;
  c->advance(0.0, 1e-9, 1);
  EXPECT_TRUE(c->known_labels().count("BndyForce_zminus"));
  EXPECT_FALSE(c->known_labels().count("BndyForce_xminus"));  // not requested
  auto r = c->reductions({"BndyForce_zminus", "BndyForce_zplus", "BndyContactArea_zminus", "BndyContactArea_zplus"});
  const double A = 0.2 * 0.3;
  const Vec3 expected = -sigma.col(2) * A;
  const Vec3 got(r["BndyForce_zminus"][0], r["BndyForce_zminus"][1], r["BndyForce_zminus"][2]);
  EXPECT_LE((got - expected).norm(), 1e-12 * expected.norm()) << got.transpose();
  EXPECT_NEAR(r["BndyContactArea_zminus"][0], A / 2, 1e-12 * A);
  EXPECT_EQ(r["BndyForce_zplus"], (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(r["BndyContactArea_zplus"][0], 0.0);
}

// With extra cells the domain's faces are the node planes `extra` and
// n - 1 - extra (Vaango's Patch::FaceNodes), not the outermost node layer:
// the same block and oracle with <extraCells>[1,1,1].
TEST(MpmBoundaryForce, FaceNodesAreTheDomainFaceWithExtraCells) {
  auto deck = load_deck_from_string(
      "<Uintah_specification><MPM><boundary_traction_faces>[zminus]</boundary_traction_faces></MPM>"
      "<MaterialProperties><MPM><material><density>1000</density>"
      "<constitutive_model type='comp_neo_hook'><bulk_modulus>1e6</bulk_modulus><shear_modulus>1e6</shear_modulus>"
      "</constitutive_model><thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
      "<geom_object><box><min>[0.1,0.1,0]</min><max>[0.3,0.4,0.2]</max></box><res>[2,2,2]</res>"
      "<velocity>[0,0,0]</velocity><temperature>300</temperature></geom_object></material></MPM>"
      "</MaterialProperties><Grid><Level><Box><lower>[0,0,0]</lower><upper>[0.5,0.5,0.5]</upper>"
      "<resolution>[5,5,5]</resolution><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box></Level>"
      "</Grid></Uintah_specification>",
      "b.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  Mat3 sigma;
  sigma << -3, 1, 2, 1, -5, 0.5, 2, 0.5, -7;
  for (Mat3& s : c->materials()[0].particles.stress) s = sigma;
  c->advance(0.0, 1e-9, 1);
  auto r = c->reductions({"BndyForce_zminus", "BndyContactArea_zminus"});
  const double A = 0.2 * 0.3;
  const Vec3 expected = -sigma.col(2) * A;
  const Vec3 got(r["BndyForce_zminus"][0], r["BndyForce_zminus"][1], r["BndyForce_zminus"][2]);
  EXPECT_LE((got - expected).norm(), 1e-12 * expected.norm()) << got.transpose();
  EXPECT_NEAR(r["BndyContactArea_zminus"][0], A / 2, 1e-12 * A);
}

}  // namespace
}  // namespace tephra
