// Stability of the explicit step against <timestep_multiplier> (the CFL
// number of Vaango's rule dt = multiplier * min_d h_d / max_p (c_p + |v_p,d|)),
// swept 0.1, 0.2, ..., 1.2 through the executable for
//   * disks.ups (inputs/mpm; linear hats, comp_neo_hook, to t = 3), and
//   * the struck bar (decks A6, GIMP + artificial viscosity, hypo_elastic,
//     on the coarse grid <spacing>[0.004, 0.001, 0.001], to t = 0.1 ms).
// Oracle: every run ends with exit 0 (completed) or 4 (NumericalFailure: a
// clean stop naming the particle), never a crash, and no written reduction
// (.dat) or last particle frame holds a NaN or Inf. The deck's own multiplier
// must complete. The observed limits are printed and recorded in
// docs/mpm-stability.md (largest multiplier of the sweep that completes).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

namespace fs = std::filesystem;

using test::has_non_finite;
using test::slurp;

// Runs `deck_text` at each multiplier; returns the largest multiplier that
// completed with exit 0 below the first failure (0 if 0.1 fails).
double sweep(const std::string& name, const std::string& deck_text, const std::string& extra_args,
             double deck_multiplier) {
  double limit = 0.0;
  bool failed = false;
  std::string table;
  for (int k = 1; k <= 12; ++k) {
    const double m = 0.1 * k;
    const fs::path dir = test::scratch_dir("stability_" + name + "_" + std::to_string(k));
    char value[32];
    std::snprintf(value, sizeof value, "%.1f", m);
    const std::string text = std::regex_replace(
        deck_text, std::regex("<timestep_multiplier>[^<]*</timestep_multiplier>"),
        std::string("<timestep_multiplier>") + value + "</timestep_multiplier>");
    std::ofstream(dir / "deck.ups") << text;
    std::string out;
    const int code = test::run_tephra((dir / "deck.ups").string() + " --quiet --threads 1 --output " +
                                          (dir / "out").string() + " " + extra_args,
                                      &out);
    EXPECT_TRUE(code == 0 || code == 4) << name << " multiplier " << value << ": exit " << code << "\n" << out;
    if (code == 4) EXPECT_NE(out.find("MPM step"), std::string::npos) << out;  // names step and particle
    for (const auto& e : fs::directory_iterator(dir / "out"))
      if (e.path().extension() == ".dat")
        EXPECT_FALSE(has_non_finite(slurp(e.path().string()))) << name << " multiplier " << value << ": " << e.path();
    std::string csv;
    EXPECT_EQ(test::run_tephra("extract " + (dir / "out").string() + " --var p.stress --step last", &csv), 0) << csv;
    EXPECT_FALSE(has_non_finite(csv)) << name << " multiplier " << value << ": last frame";
    if (std::abs(m - deck_multiplier) < 1e-9) EXPECT_EQ(code, 0) << name << ": the deck's own multiplier";
    if (code == 0 && !failed) limit = m;
    failed = failed || code != 0;
    table += std::string(" ") + value + ":" + std::to_string(code);
  }
  std::printf("stability %s: exit codes%s; completes up to %.1f\n", name.c_str(), table.c_str(), limit);
  return limit;
}

std::string without_checkpoints(std::string text, const char* interval) {
  text = std::regex_replace(text, std::regex("<checkpoint[^>]*/>"), "");
  return std::regex_replace(text, std::regex("<outputInterval>[^<]*</outputInterval>"),
                            std::string("<outputInterval>") + interval + "</outputInterval>");
}

TEST(MpmStability, DisksSweepStopsCleanly) {
  const std::string text = without_checkpoints(slurp(test::source_dir() + "/inputs/mpm/disks.ups"), "0.5");
  const double limit = sweep("disks", text, "", 0.2);
  EXPECT_GE(limit, 0.2);
}

TEST(MpmStability, BarSweepStopsCleanly) {
  std::string text = slurp(test::shared_dir() +
                           "/decks/inputs/MPM/WavePropagationVerification/MPM1DVerificationTests/"
                           "OneD_velocityBC_gimp_damped_uintah.ups");
  text = std::regex_replace(text, std::regex("<spacing>[^<]*</spacing>"), "<spacing> [0.004, 0.001, 0.001] </spacing>");
  text = without_checkpoints(text, "5e-5");
  // To 0.1 ms (the front crosses 8 cells; 330 steps at 0.1, 28 at 1.2): an
  // unstable mode grows by a factor per step, so 28 steps show it.
  const double limit = sweep("bar", text, "--end-time 1e-4", 0.1);
  EXPECT_GE(limit, 0.1);
}

}  // namespace
}  // namespace tephra
