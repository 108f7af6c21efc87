// A 1-D elastic bar under a step pressure at one end: <PhysicalBC><MPM>
// <pressure> with a load curve (mpm/loads/ParticleLoads.h). The harness is
// Vaango's wave-propagation deck OneD_velocityBC_gimp_damped_uintah.ups on
// the coarser grid of the decks README (<spacing>[0.004, 0.001, 0.001],
// 300 cells, GIMP, artificial viscosity), with its x- velocity condition
// replaced by a pressure p on the plane x = -0.6 (a box of zero thickness in
// x; positive load = force along +x, i.e. compression at the x- end), held
// from t = 0:
//   <load_curve><time_point><time>0</time><load>p</load></time_point></load_curve>.
//
// Exact solution (d'Alembert, linear elastodynamics in uniaxial strain): a
// step wave with c = sqrt((K + 4G/3)/rho) = 325.40 m/s runs into the bar at
// rest; behind it sigma_xx = -p and v = p / (rho c) (momentum balance
// across the front, [sigma] = -rho c [v]). With p = rho c v0, v0 = 1 m/s,
// the state behind the front equals that of the velocity-driven deck
// (tests/verification/test_mpm_bar_wave.cpp). Tolerances (the issue's):
// sigma behind the front within 2 % of -p, particle velocity within 2 % of
// v0, front speed within 1 % of c, front within one cell of -0.6 + c t. The finite-strain hypoelastic
// answers differ from the linear ones by O(v0/c) = 0.3 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"
#include "tests/support/BarProfile.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::BarProfile;

TEST(MpmPressureBar, StepPressureGivesStressMinusPBehindTheFront) {
  set_thread_count(1);
  const double rho = 1700, K = 6e7, G = 9e7, v0 = 1.0;
  const double c_exact = std::sqrt((K + 4.0 * G / 3.0) / rho);
  const double p = rho * c_exact * v0;  // 0.5532 MPa

  std::ifstream in(test::shared_dir() +
                   "/decks/inputs/MPM/WavePropagationVerification/MPM1DVerificationTests/"
                   "OneD_velocityBC_gimp_damped_uintah.ups");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  // Drop the x- velocity face: the loaded end is free but for the pressure.
  const auto face = s.find("<Face side = \"x-\">");
  ASSERT_NE(face, std::string::npos);
  s.erase(face, s.find("</Face>", face) + 7 - face);
  std::ostringstream bc;
  bc.precision(17);
  bc << "<PhysicalBC><MPM><pressure><geom_object><box label=\"loaded_end\"><min>[-0.6,-0.0005,-0.0005]</min>"
        "<max>[-0.6,0.0005,0.0005]</max></box></geom_object><load_curve><id>1</id><time_point><time>0</time>"
        "<load>"
     << p << "</load></time_point></load_curve></pressure></MPM></PhysicalBC>\n";
  s.insert(s.rfind("</Uintah_specification>"), bc.str());
  const std::string spacing = "<spacing> [0.001, 0.001, 0.001] </spacing>";
  ASSERT_NE(s.find(spacing), std::string::npos);
  s.replace(s.find(spacing), spacing.size(), "<spacing> [0.004, 0.001, 0.001] </spacing>");
  auto deck = load_deck_from_string(s, "pressure_bar.ups", ".");
  const double multiplier = deck->root.require_child("Time").get_double("timestep_multiplier");
  auto c = make_mpm_component(*deck);
  c->initialize();

  // Profiles at t1 and t2: the front speed from their difference (free of
  // the start-up offset), the state behind the front at t2.
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
  std::printf("pressure bar: sigma_xx behind the front %.1f Pa (exact %.1f, error %.3f %%), v %.4f m/s "
              "(exact %.4f), front speed %.2f m/s (exact %.2f), front at t2 %.4f m (exact %.4f)\n",
              r.mean_stress, -p, 100 * (r.mean_stress / -p - 1), r.mean_velocity, v0, c_observed, c_exact, r.front,
              -0.6 + c_exact * t2);
  EXPECT_NEAR(r.mean_stress / -p, 1.0, 0.02);
  EXPECT_NEAR(r.mean_velocity / v0, 1.0, 0.02);
  EXPECT_NEAR(c_observed / c_exact, 1.0, 0.01);
  EXPECT_NEAR(r.front, -0.6 + c_exact * t2, 0.004);  // within one cell (h_x = 4 mm)
}

// The deck inputs/mpm/pressure_bar.ups (the same set-up) runs from the command
// line: 30 steps, exit 0, the AccStrainEnergy reduction written.
TEST(MpmPressureBar, InputDeckRunsFromTheCommandLine) {
  const std::string out = test::scratch_dir("pressure_bar_cli");
  std::string log;
  const int rc = test::run_tephra(test::source_dir() + "/inputs/mpm/pressure_bar.ups --max-steps 30 --quiet --output " +
                                      out + "/uda",
                                  &log);
  EXPECT_EQ(rc, 0) << log;
  EXPECT_TRUE(std::ifstream(out + "/uda/AccStrainEnergy.dat").good()) << log;
}

}  // namespace
}  // namespace tephra
