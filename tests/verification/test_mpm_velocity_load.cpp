// <PhysicalBC><MPM><velocity>: a prescribed velocity from a vector load curve
// on the particles of a surface (mpm/loads/ParticleLoads.h, VelocitySurface).
//
// The harness is the velocity-driven bar of test_mpm_bar_wave (Vaango's
// OneD_velocityBC_gimp_damped_uintah.ups on the decks README's coarser grid,
// <spacing>[0.004, 0.001, 0.001], GIMP, artificial viscosity) with its x-
// Dirichlet face removed and replaced by a velocity load v0 = 1 m/s (held
// from t = 0) on the plane x = -0.6 (a box of zero thickness in x):
//   <velocity><geom_object><box>..</box></geom_object>
//     <load_curve><time_point><time>0</time><load>[1,0,0]</load></time_point></load_curve></velocity>.
//
// Exact solution (d'Alembert, as for the Dirichlet face): a step wave with
// c = sqrt((K + 4G/3)/rho) = 325.40 m/s runs into the bar at rest; behind it
// v = v0 and sigma_xx = -rho c v0 = -0.5532 MPa. Tolerances as the Dirichlet
// and pressure bars (tests/verification/test_mpm_bar_wave.cpp,
// test_mpm_pressure_bar.cpp): sigma and v behind the front within 2 %, the
// front speed within 1 %. The driven nodes are those the flagged particles'
// GIMP stencils reach, one node layer deeper than the Dirichlet face's, so
// the front starts up to one cell ahead: its position at t2 is asserted
// within two cells (h_x = 4 mm) of -0.6 + c t2.
// The flagged particles themselves move exactly as prescribed: v_p = v0 and
// x_p = X_p + v0 t to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"
#include "tests/support/BarProfile.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::BarProfile;

// The A6 deck on the coarse grid, its x- face replaced by `physical_bc` (inserted before the end).
std::string bar_deck(const std::string& physical_bc) {
  std::ifstream in(test::shared_dir() +
                   "/decks/inputs/MPM/WavePropagationVerification/MPM1DVerificationTests/"
                   "OneD_velocityBC_gimp_damped_uintah.ups");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const auto face = s.find("<Face side = \"x-\">");
  EXPECT_NE(face, std::string::npos);
  s.erase(face, s.find("</Face>", face) + 7 - face);
  s.insert(s.rfind("</Uintah_specification>"), physical_bc);
  const std::string spacing = "<spacing> [0.001, 0.001, 0.001] </spacing>";
  EXPECT_NE(s.find(spacing), std::string::npos);
  s.replace(s.find(spacing), spacing.size(), "<spacing> [0.004, 0.001, 0.001] </spacing>");
  return s;
}

const char* kVelocityBc =
    "<PhysicalBC><MPM><velocity><geom_object><box label=\"driven_end\"><min>[-0.6,-0.0005,-0.0005]</min>"
    "<max>[-0.6,0.0005,0.0005]</max></box></geom_object><load_curve><id>1</id><time_point><time>0</time>"
    "<load>[1,0,0]</load></time_point></load_curve></velocity></MPM></PhysicalBC>\n";

TEST(MpmVelocityLoad, DrivenBarGivesMinusRhoCVBehindTheFront) {
  set_thread_count(1);
  const double rho = 1700, K = 6e7, G = 9e7, v0 = 1.0;
  const double c_exact = std::sqrt((K + 4.0 * G / 3.0) / rho);
  const double sigma_exact = -rho * c_exact * v0;
  auto deck = load_deck_from_string(bar_deck(kVelocityBc), "velocity_bar.ups", ".");
  const double multiplier = deck->root.require_child("Time").get_double("timestep_multiplier");
  auto c = make_mpm_component(*deck);
  c->initialize();
  ASSERT_EQ(c->setup().loads.velocity.size(), 1u);

  const double t1 = 0.3e-3, t2 = 0.6e-3;
  double t = 0;
  int step = 0;
  BarProfile r1, r;
  for (double t_stop : {t1, t2}) {
    while (t < t_stop) {
      const double dt = std::min(multiplier * c->stable_timestep(), t_stop - t);
      c->advance(t, dt, ++step);
      t += dt;
    }
    (t_stop == t1 ? r1 : r) = test::bar_profile(c->materials()[0].particles, v0);
  }
  const double c_observed = (r.front - r1.front) / (t2 - t1);
  // The flagged particles (reference x within dxpp = 2 mm of the plane): v0 and X + v0 t exactly.
  const Particles& p = c->materials()[0].particles;
  int flagged = 0;
  double dev_v = 0, dev_x = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double X = p.x[i][0] - p.displacement[i][0];
    if (X > -0.598) continue;
    ++flagged;
    dev_v = std::max(dev_v, (p.v[i] - Vec3(v0, 0, 0)).norm());
    dev_x = std::max(dev_x, std::abs(p.displacement[i][0] - v0 * t2));
  }
  std::printf("velocity-load bar: sigma_xx behind the front %.1f Pa (exact %.1f, error %.3f %%), v %.4f m/s, "
              "front speed %.2f m/s (exact %.2f, error %.3f %%), front at t2 %.4f m (exact %.4f); %d driven "
              "particles: |v - v0| %.1e, |u - v0 t| %.1e\n",
              r.mean_stress, sigma_exact, 100 * (r.mean_stress / sigma_exact - 1), r.mean_velocity, c_observed,
              c_exact, 100 * (c_observed / c_exact - 1), r.front, -0.6 + c_exact * t2, flagged, dev_v, dev_x);
  EXPECT_NEAR(r.mean_stress / sigma_exact, 1.0, 0.02);
  EXPECT_NEAR(r.mean_velocity / v0, 1.0, 0.02);
  EXPECT_NEAR(c_observed / c_exact, 1.0, 0.01);
  EXPECT_NEAR(r.front, -0.6 + c_exact * t2, 0.008);
  EXPECT_GT(flagged, 0);
  EXPECT_LT(dev_v, 1e-12);
  EXPECT_LT(dev_x, 1e-12);
}

// A ramp v(t) = (a t, 0, 0), a = 1000 m/s^2, on a block's x- face: the driven
// particles move by sum_k dt v(t_{k+1}) (the scheme's exact displacement; with
// equal steps a dt^2 n (n + 1) / 2) to round-off. The load curve evaluates
// L_0 s + L_1 (1 - s) with s = (1 - t)/1, which rounds 1 - s at 1e-16, i.e.
// 1e-13 m/s of the 1000 m/s load: the tolerance is 1e-12 on v (and on u).
TEST(MpmVelocityLoad, RampLoadCurveMovesTheDrivenParticlesExactly) {
  const char* ramp =
      "<PhysicalBC><MPM><velocity><geom_object><box label=\"driven_end\"><min>[-0.6,-0.0005,-0.0005]</min>"
      "<max>[-0.6,0.0005,0.0005]</max></box></geom_object><load_curve><id>1</id>"
      "<time_point><time>0</time><load>[0,0,0]</load></time_point>"
      "<time_point><time>1</time><load>[1000,0,0]</load></time_point></load_curve></velocity></MPM></PhysicalBC>\n";
  set_thread_count(1);
  auto deck = load_deck_from_string(bar_deck(ramp), "ramp_bar.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  const int n = 40;
  const double dt = 2e-6, a = 1000.0;
  for (int k = 0; k < n; ++k) c->advance(k * dt, dt, k + 1);
  const Particles& p = c->materials()[0].particles;
  double dev_u = 0, dev_v = 0;
  int flagged = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[i][0] - p.displacement[i][0] < -0.598) {
      ++flagged;
      dev_u = std::max(dev_u, std::abs(p.displacement[i][0] - a * dt * dt * n * (n + 1) / 2));
      dev_v = std::max(dev_v, std::abs(p.v[i][0] - a * n * dt));
    }
  std::printf("ramp velocity load: %d driven particles, |u - a dt^2 n(n+1)/2| %.1e m, |v - a t| %.1e m/s\n", flagged,
              dev_u, dev_v);
  EXPECT_GT(flagged, 0);
  EXPECT_LT(dev_u, 1e-12);
  EXPECT_LT(dev_v, 1e-12);
}

// Parsing: vector loads, the load curve checks, and the <use_load_curves> gate.
TEST(MpmVelocityLoad, Parsing) {
  auto loads = [](const std::string& bc, bool use) {
    auto d = load_deck_from_string("<Uintah_specification><PhysicalBC><MPM>" + bc + "</MPM></PhysicalBC></Uintah_specification>",
                                   "t.ups", ".");
    return parse_particle_loads(d->root.child("PhysicalBC"), use);
  };
  const std::string box = "<geom_object><box><min>[1,0,0]</min><max>[1,1,1]</max></box></geom_object>";
  const std::string curve =
      "<load_curve><id>1</id><time_point><time>0</time><load>[0,0,0]</load></time_point>"
      "<time_point><time>2</time><load>[2,-4,6]</load></time_point></load_curve>";
  const ParticleLoads l = loads("<velocity>" + box + curve + "</velocity>", true);
  ASSERT_EQ(l.velocity.size(), 1u);
  EXPECT_EQ(l.velocity[0].curve.at(0.5), Vec3(0.5, -1, 1.5));
  EXPECT_EQ(l.velocity[0].curve.at(3.0), Vec3(2, -4, 6));
  EXPECT_FALSE(l.empty());
  EXPECT_TRUE(loads("<velocity>" + box + curve + "</velocity>", false).velocity.empty());
  EXPECT_THROW(loads("<velocity>" + box + "<load_curve><id>1</id><time_point><time>0</time><load>1</load>"
                     "</time_point></load_curve></velocity>", true),
               DeckError);  // a scalar where a vector is needed
  EXPECT_THROW(loads("<velocity>" + box + curve + "<load_curve_scaling_function>2*t</load_curve_scaling_function>"
                     "</velocity>", true),
               MissingFeature);
  EXPECT_THROW(loads("<velocity>" + box + curve + "<bogus/></velocity>", true), DeckError);
}

}  // namespace
}  // namespace tephra
