// <PhysicalBC><MPM><moment> (mpm/loads/MomentLoad.h): the particle forces
// f_p = M(t) d_p / sum_q d_q^2 e (eq. 1 of MomentLoad.h) give the couple
// sum_p (X_p - P) x f_p = M(t) (n x e) exactly and no net force when the
// neutral plane passes through the flagged particles' centroid; deck errors.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "mpm/loads/ParticleLoads.h"

namespace tephra {
namespace {

ParticleLoads loads_of(const std::string& mpm_bc, bool use_load_curves = true) {
  auto d = load_deck_from_string(
      "<Uintah_specification><PhysicalBC><MPM>" + mpm_bc + "</MPM></PhysicalBC></Uintah_specification>", "t.ups", ".");
  return parse_particle_loads(d->root.child("PhysicalBC"), use_load_curves);
}

// M(t) = 4 t on [0, 1], then held at 4 N m.
const char* kCurve =
    "<load_curve><id>1</id><time_point><time>0</time><load>0</load></time_point>"
    "<time_point><time>1</time><load>4</load></time_point></load_curve>";

// The x+ face x = 1 of a unit cube, neutral plane y = 0.5 (normal +y): the
// force is along e = +x, the couple M (e_y x e_x) = -M e_z.
const std::string kFace =
    "<geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>"
    "<normal_plane><normal>[0,2,0]</normal><point>[0,0.5,0]</point></normal_plane>";

TEST(MpmMomentLoad, CoupleIsMExactlyWithNoNetForce) {
  const ParticleLoads l = loads_of("<moment>" + kFace + kCurve + "</moment>");
  ASSERT_EQ(l.moment.size(), 1u);
  EXPECT_EQ(l.moment[0].thickness_dir, 0);
  // A 4x4x4 cube of particles (h = 0.5, res 2: dxpp = 0.25) in [0,1]^3; the
  // last layer (x = 0.875) is within dxpp of the face x = 1, 16 particles.
  Particles p;
  const Mat3 size = Mat3::Identity() * 0.5;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        p.add(Vec3(0.125 + 0.25 * i, 0.125 + 0.25 * j, 0.125 + 0.25 * k), Vec3::Zero(), 1.0, 1.0, 300, 0, 0, size);
  const Vec3 h(0.5, 0.5, 0.5);
  const double t = 0.3, M = 4 * 0.3;  // the load curve at t
  apply_particle_loads(l, t, h, {&p});
  Vec3 force = Vec3::Zero(), couple = Vec3::Zero();
  int flagged = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    force += p.external_force[i];
    couple += (p.x[i] - Vec3(1, 0.5, 0.5)).cross(p.external_force[i]);
    if (p.external_force[i].norm() > 0) ++flagged;
    // Only the x = 0.875 layer is loaded, along x, linear in y - 0.5.
    if (p.x[i][0] < 0.8) EXPECT_EQ(p.external_force[i], Vec3::Zero());
    EXPECT_EQ(p.external_force[i][1], 0.0);
    EXPECT_EQ(p.external_force[i][2], 0.0);
  }
  EXPECT_EQ(flagged, 16);  // d = +-0.125, +-0.375: none on the plane
  // sum d^2 = 4 (z columns) x 4 (x 1 layer) ... = 16 particles: 8 x 0.125^2 + 8 x 0.375^2 = 1.25;
  // the particle at y = 0.875 (d = 0.375) takes M 0.375 / 1.25.
  EXPECT_NEAR(p.external_force[3 * 16 + 3 * 4 + 0][0], M * 0.375 / 1.25, 1e-15);
  EXPECT_NEAR(force.norm(), 0.0, 1e-15);
  EXPECT_NEAR((couple - Vec3(0, 0, -M)).norm(), 0.0, 1e-15);
  // Any reference point gives the same couple (zero net force).
  Vec3 couple_origin = Vec3::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) couple_origin += p.x[i].cross(p.external_force[i]);
  EXPECT_NEAR((couple_origin - Vec3(0, 0, -M)).norm(), 0.0, 1e-15);
}

TEST(MpmMomentLoad, OffCentrePlaneStillGivesMAboutItsPlane) {
  // Neutral plane y = 0: all d > 0, so a net force M sum d / sum d^2 along e
  // and the couple about the plane sum d_p f_p = M.
  const ParticleLoads l = loads_of(
      "<moment><geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>"
      "<normal_plane><normal>[0,1,0]</normal><point>[0,0,0]</point></normal_plane>" +
      std::string(kCurve) + "</moment>");
  Particles p;
  const Mat3 size = Mat3::Identity() * 0.5;
  for (int j = 0; j < 4; ++j) p.add(Vec3(0.875, 0.125 + 0.25 * j, 0.5), Vec3::Zero(), 1.0, 1.0, 300, 0, 0, size);
  apply_particle_loads(l, 2.0, Vec3(0.5, 0.5, 0.5), {&p});  // M = 4 (held)
  double sum_df = 0, sum_f = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    sum_df += p.x[i][1] * p.external_force[i][0];
    sum_f += p.external_force[i][0];
  }
  EXPECT_NEAR(sum_df, 4.0, 1e-14);
  // sum d = 0.125 + 0.375 + 0.625 + 0.875 = 2, sum d^2 = 1.3125
  EXPECT_NEAR(sum_f, 4.0 * 2.0 / 1.3125, 1e-14);
}

TEST(MpmMomentLoad, NeedsLoadCurvesAndGoodInput) {
  EXPECT_EQ(loads_of("<moment>" + kFace + kCurve + "</moment>", false).moment.size(), 0u);
  // Not a box (Vaango's MomentBC takes boxes only).
  EXPECT_THROW(loads_of("<moment><geom_object><sphere><origin>[0,0,0]</origin><radius>1</radius></sphere></geom_object>"
                        "<normal_plane><normal>[0,1,0]</normal><point>[0,0,0]</point></normal_plane>" +
                        std::string(kCurve) + "</moment>"),
               DeckError);
  // The plane normal along the force direction gives no lever arm in the face.
  EXPECT_THROW(loads_of("<moment><geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>"
                        "<normal_plane><normal>[1,0,0]</normal><point>[0,0,0]</point></normal_plane>" +
                        std::string(kCurve) + "</moment>"),
               DeckError);
  EXPECT_THROW(loads_of("<moment><geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>"
                        "<normal_plane><normal>[0,0,0]</normal><point>[0,0,0]</point></normal_plane>" +
                        std::string(kCurve) + "</moment>"),
               DeckError);
  EXPECT_THROW(loads_of("<moment>" + kFace + "</moment>"), DeckError);  // no load curve
  EXPECT_THROW(loads_of("<moment>" + kFace + kCurve + "<bogus/></moment>"), DeckError);
  try {
    loads_of("<moment><geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>\n"
             "<normal_plane><normal>[1,0,0]</normal><point>[0,0,0]</point></normal_plane>" +
             std::string(kCurve) + "</moment>");
    FAIL();
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("t.ups:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("normal"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tephra
