// <PhysicalBC><MPM> loads (mpm/loads/): the load curve, the loaded surfaces
// (flags, area, normal), the force per particle p A / N with Nanson's
// relation, force regions, and the deck errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "mpm/loads/ParticleLoads.h"

namespace tephra {
namespace {

std::unique_ptr<Deck> deck(const std::string& body) {
  return load_deck_from_string("<Uintah_specification>" + body + "</Uintah_specification>", "t.ups", ".");
}

ParticleLoads loads_of(const std::string& mpm_bc, bool use_load_curves = true) {
  auto d = deck("<PhysicalBC><MPM>" + mpm_bc + "</MPM></PhysicalBC>");
  return parse_particle_loads(d->root.child("PhysicalBC"), use_load_curves);
}

const char* kCurve =
    "<load_curve><id>1</id>"
    "<time_point><time>0</time><load>0</load></time_point>"
    "<time_point><time>1</time><load>10</load></time_point>"
    "<time_point><time>3</time><load>-10</load></time_point></load_curve>";

TEST(MpmLoads, LoadCurveIsPiecewiseLinearAndHeldOutside) {
  const ParticleLoads l = loads_of(std::string("<pressure><geom_object><box><min>[0,0,0]</min><max>[0,1,2]</max></box>"
                                               "</geom_object>") + kCurve + "</pressure>");
  ASSERT_EQ(l.pressure.size(), 1u);
  const LoadCurve<double>& c = l.pressure[0].curve;
  EXPECT_EQ(c.id, 1);
  EXPECT_DOUBLE_EQ(c.at(0.25), 2.5);   // 10 t on [0, 1]
  EXPECT_DOUBLE_EQ(c.at(2.0), 0.0);    // 10 - 10 (t - 1) on [1, 3]
  EXPECT_DOUBLE_EQ(c.at(1.0), 10.0);
  EXPECT_DOUBLE_EQ(c.at(5.0), -10.0);  // held after the last point
  EXPECT_DOUBLE_EQ(c.at(-1.0), 0.0);   // and before the first
  // The box: thin in x, so the loaded plane is x = 0, A = 1 * 2, normal +x.
  EXPECT_EQ(l.pressure[0].thickness_dir, 0);
  EXPECT_DOUBLE_EQ(l.pressure[0].area, 2.0);
  EXPECT_EQ(l.pressure[0].normal(Vec3(5, 5, 5)), Vec3(1, 0, 0));
}

TEST(MpmLoads, SurfaceAreasAndNormals) {
  const ParticleLoads l = loads_of(
      std::string("<pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0,0,2]</top><radius>0.5</radius>"
                  "</cylinder></geom_object><volume_fraction_inside_domain>0.25</volume_fraction_inside_domain>") +
      kCurve + "</pressure>" +
      "<pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0,0,0.001]</top><radius>0.5</radius>"
      "<cylinder_end>true</cylinder_end></cylinder></geom_object>" + kCurve + "</pressure>" +
      "<pressure><geom_object><sphere><origin>[1,1,1]</origin><radius>2</radius></sphere></geom_object>" + kCurve +
      "</pressure>");
  ASSERT_EQ(l.pressure.size(), 3u);
  const double pi = std::numbers::pi;
  EXPECT_DOUBLE_EQ(l.pressure[0].area, 0.25 * 2 * pi * 0.5 * 2);  // quarter of the lateral surface 2 pi r L
  EXPECT_DOUBLE_EQ(l.pressure[1].area, pi * 0.25);                 // one end cap pi r^2
  EXPECT_DOUBLE_EQ(l.pressure[2].area, 4 * pi * 4);                // 4 pi r^2
  // Radial normal of the cylinder at (0.3, 0.4, 1): (0.6, 0.8, 0); the disc's is the axis.
  EXPECT_NEAR((l.pressure[0].normal(Vec3(0.3, 0.4, 1)) - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(l.pressure[1].normal(Vec3(0.1, 0, 0)), Vec3(0, 0, 1));
  EXPECT_NEAR((l.pressure[2].normal(Vec3(1, 4, 5)) - Vec3(0, 0.6, 0.8)).norm(), 0.0, 1e-15);
  // Flags: within dxpp = 0.1 (0.9 min dxpp = 0.09 for cylinders) of the surface.
  const Vec3 dxpp(0.1, 0.1, 0.1);
  EXPECT_TRUE(l.pressure[0].on_surface(Vec3(0.45, 0, 1), dxpp));
  EXPECT_FALSE(l.pressure[0].on_surface(Vec3(0.40, 0, 1), dxpp));
  EXPECT_FALSE(l.pressure[0].on_surface(Vec3(0.5, 0, 2.05), dxpp));  // beyond the ends
  EXPECT_TRUE(l.pressure[1].on_surface(Vec3(0.2, 0, 0.05), dxpp));
  EXPECT_FALSE(l.pressure[1].on_surface(Vec3(0.2, 0, 0.2), dxpp));
  EXPECT_TRUE(l.pressure[2].on_surface(Vec3(1, 1, 3.1), dxpp));     // |dxpp| = 0.173
  EXPECT_FALSE(l.pressure[2].on_surface(Vec3(1, 1, 2.8), dxpp));
}

// Two particles on the plane x = 1 of a unit square (A = 1), pressure
// p(t) = 10 t: each carries p A / 2 along +x. With F = diag(2, 1, 1) (a
// stretch along the normal) J F^{-T} e_x = 2 (1/2) e_x: the force is
// unchanged; with F = diag(1, 3, 1) (a stretch of the loaded plane) the
// area triples: J F^{-T} e_x = 3 e_x. The particle inside gets nothing;
// force regions add m * force_density.
TEST(MpmLoads, ForcePerParticleAndNanson) {
  const ParticleLoads l = loads_of(
      std::string("<pressure><geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>") + kCurve +
      "</pressure><force><lower>[0,0,0]</lower><upper>[0.6,1,1]</upper><force_density>[0,0,-9.81]</force_density>"
      "</force>");
  Particles p;
  const Mat3 size = Mat3::Identity() * 0.5;  // res 2: dxpp = h/2
  p.add(Vec3(0.75, 0.25, 0.5), Vec3::Zero(), 2.0, 1.0, 300, 0, 0, size);
  p.add(Vec3(0.75, 0.75, 0.5), Vec3::Zero(), 2.0, 1.0, 300, 0, 1, size);
  p.add(Vec3(0.25, 0.75, 0.5), Vec3::Zero(), 2.0, 1.0, 300, 0, 2, size);
  p.F[0] = Vec3(2, 1, 1).asDiagonal();
  p.F[1] = Vec3(1, 3, 1).asDiagonal();
  // The particles moved: flags and counts use X = x - u.
  p.x[0] += Vec3(0.75, 0, 0);
  p.displacement[0] = Vec3(0.75, 0, 0);
  const Vec3 h(0.5, 0.5, 0.5);
  EXPECT_EQ(particles_per_pressure_surface(l, h, {&p}), std::vector<long>{2});
  apply_particle_loads(l, 0.5, h, {&p});  // p = 5 Pa, A = 1, N = 2
  EXPECT_NEAR((p.external_force[0] - Vec3(2.5, 0, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((p.external_force[1] - Vec3(7.5, 0, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((p.external_force[2] - Vec3(0, 0, -2 * 9.81)).norm(), 0.0, 1e-14);
}

TEST(MpmLoads, PressureNeedsLoadCurves) {
  const std::string bc =
      std::string("<pressure><geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>") + kCurve +
      "</pressure>";
  EXPECT_EQ(loads_of(bc, false).pressure.size(), 0u);
  EXPECT_EQ(loads_of(bc, true).pressure.size(), 1u);
}

TEST(MpmLoads, DeckErrorsAndMissingFeatures) {
  const std::string box = "<geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>";
  EXPECT_THROW(loads_of("<moment>" + box + kCurve + "</moment>"), DeckError);  // no <normal_plane> (test_mpm_moment_load)
  EXPECT_THROW(loads_of("<pressure>" + box + kCurve +
                        "<load_curve_scaling_function>t*2</load_curve_scaling_function></pressure>"),
               MissingFeature);
  // Axisymmetric surfaces (session 15): the side's per-radian area R L; an
  // end needs the <pressure>'s <res> (Vaango requires it); the axis is x = 0
  // along y. (Whether the run is axisymmetric is checked by the deck reader:
  // test_mpm_axisymmetric_loads.)
  const ParticleLoads side = loads_of(
      "<pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0,2,0]</top><radius>0.5</radius>"
      "<axisymmetric_side>true</axisymmetric_side></cylinder></geom_object>" + std::string(kCurve) + "</pressure>");
  ASSERT_EQ(side.pressure.size(), 1u);
  EXPECT_EQ(side.pressure[0].kind, PressureSurface::Kind::AxiSide);
  EXPECT_DOUBLE_EQ(side.pressure[0].area, 0.5 * 2.0);  // 2 pi R L / (2 pi)
  EXPECT_THROW(loads_of("<pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0,1,0]</top><radius>1</radius>"
                        "<axisymmetric_end>true</axisymmetric_end></cylinder></geom_object>" +
                        std::string(kCurve) + "</pressure>"),
               DeckError);  // no <res>
  EXPECT_THROW(loads_of("<pressure><geom_object><cylinder><bottom>[1,0,0]</bottom><top>[1,1,0]</top><radius>1</radius>"
                        "<axisymmetric_side>true</axisymmetric_side></cylinder></geom_object>" +
                        std::string(kCurve) + "</pressure>"),
               DeckError);  // not on the axis x = 0
  EXPECT_NO_THROW(loads_of("<pressure>" + box + kCurve +
                           "<load_curve_scaling_function>1.0</load_curve_scaling_function></pressure>"));
  // Times must increase.
  EXPECT_THROW(loads_of("<pressure>" + box +
                        "<load_curve><id>1</id><time_point><time>1</time><load>0</load></time_point>"
                        "<time_point><time>1</time><load>1</load></time_point></load_curve></pressure>"),
               DeckError);
  EXPECT_THROW(loads_of("<pressure>" + box + "</pressure>"), DeckError);  // no load curve
  EXPECT_THROW(loads_of("<pressure><geom_object><cone/></geom_object>" + std::string(kCurve) + "</pressure>"),
               DeckError);
  // A box thin in two directions spans no plane.
  EXPECT_THROW(loads_of("<pressure><geom_object><box><min>[0,0,0]</min><max>[1,0,0]</max></box></geom_object>" +
                        std::string(kCurve) + "</pressure>"),
               DeckError);
}

}  // namespace
}  // namespace tephra
