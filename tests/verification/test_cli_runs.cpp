// End-to-end runs of the tephra executable: exit codes, output files, and a
// restart that reproduces the uninterrupted run's .dat files byte for byte.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "tests/support/TestPaths.h"

namespace fs = std::filesystem;
using tephra::test::run_tephra;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string disks() { return tephra::test::source_dir() + "/inputs/mpm/disks.ups"; }

}  // namespace

TEST(CommandLine, BadCommandLinesExitWith2) {
  std::string out;
  EXPECT_EQ(run_tephra("", &out), 2);
  EXPECT_EQ(run_tephra("--no-such-flag", &out), 2);
  EXPECT_EQ(run_tephra(disks() + " --max-steps abc", &out), 2);
  EXPECT_EQ(run_tephra("--list no_such_family", &out), 2);
  EXPECT_NE(out.find("constitutive_model"), std::string::npos) << out;
  EXPECT_EQ(run_tephra("extract", &out), 2);
}

TEST(CommandLine, ListsRegisteredKeys) {
  std::string out;
  ASSERT_EQ(run_tephra("--list constitutive_model", &out), 0) << out;
  EXPECT_NE(out.find("comp_neo_hook\n"), std::string::npos) << out;
  ASSERT_EQ(run_tephra("--list interpolator", &out), 0) << out;
  EXPECT_NE(out.find("linear\n"), std::string::npos) << out;
}

TEST(CommandLine, EveryStockDeckValidatesOrNamesTheMissingFeature) {
  // Exit 0 (valid, runnable) or 3 (valid, needs a feature not built yet, named).
  // orderAccuracy/MPM/AA.ups is not XML: it is a symbolic link stored as a
  // text file holding the path of inputs/MPM/AA.ups, so it must be rejected (1).
  int checked = 0;
  for (const auto& e : fs::recursive_directory_iterator(tephra::test::shared_dir() + "/decks")) {
    if (e.path().extension() != ".ups") continue;
    std::string out;
    int code = run_tephra("--validate " + e.path().string(), &out);
    ++checked;
    if (e.path().string().find("orderAccuracy/MPM/AA.ups") != std::string::npos) {
      EXPECT_EQ(code, 1) << out;
      continue;
    }
    EXPECT_TRUE(code == 0 || code == 3) << e.path() << " exit " << code << "\n" << out;
    if (code == 3) EXPECT_NE(out.find("does not have this feature"), std::string::npos) << out;
  }
  EXPECT_GE(checked, 20);
}

TEST(CommandLine, MalformedDeckExitsWith1NamingFileAndLine) {
  fs::path dir = tephra::test::scratch_dir("cli_malformed");
  std::string text = slurp(disks());
  // Misspell an element: the error must name the file, a line and suggest the right name.
  std::string bad = std::regex_replace(text, std::regex("<maxTime>"), "<maxTimee>", std::regex_constants::format_first_only);
  bad = std::regex_replace(bad, std::regex("</maxTime>"), "</maxTimee>", std::regex_constants::format_first_only);
  std::ofstream(dir / "bad.ups") << bad;
  std::string out;
  EXPECT_EQ(run_tephra("--validate " + (dir / "bad.ups").string(), &out), 1) << out;
  EXPECT_NE(out.find("bad.ups:"), std::string::npos) << out;
  EXPECT_NE(out.find("maxTimee"), std::string::npos) << out;
  // Truncated file.
  std::ofstream(dir / "cut.ups") << text.substr(0, text.size() / 2);
  EXPECT_EQ(run_tephra("--validate " + (dir / "cut.ups").string(), &out), 1) << out;
  EXPECT_NE(out.find("cut.ups:"), std::string::npos) << out;
}

TEST(CommandLine, DisksRunWritesOutputs) {
  fs::path dir = fs::path(tephra::test::scratch_dir("cli_disks")) / "disks.uda";
  std::string out;
  ASSERT_EQ(run_tephra(disks() + " --quiet --max-steps 40 --output " + dir.string(), &out), 0) << out;
  for (const char* f : {"input.ups", "tephra.xdmf", "KineticEnergy.dat", "TotalMass.dat", "StrainEnergy.dat",
                        "TotalMomentum.dat", "CenterOfMassPosition.dat"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  std::string csv;
  ASSERT_EQ(run_tephra("extract " + dir.string() + " --var p.stress --step last", &csv), 0) << csv;
  EXPECT_EQ(csv.rfind("time,particle_id,x,y,z,p.stress_xx,p.stress_xy", 0), 0u) << csv.substr(0, 200);
}

TEST(CommandLine, RestartReproducesDatFilesByteForByte) {
  // disks.ups checkpoints every 0.01 s (cycle 2) and writes reductions every 0.025 s.
  fs::path full = fs::path(tephra::test::scratch_dir("cli_restart_full")) / "out";
  fs::path part = fs::path(tephra::test::scratch_dir("cli_restart_part")) / "out";
  std::string out;
  ASSERT_EQ(run_tephra(disks() + " --quiet --end-time 0.3 --output " + full.string(), &out), 0) << out;
  ASSERT_EQ(run_tephra(disks() + " --quiet --end-time 0.3 --max-steps 20 --output " + part.string(), &out), 0)
      << out;
  ASSERT_EQ(run_tephra("--restart " + part.string() + " --quiet --end-time 0.3", &out), 0) << out;
  for (const char* f : {"KineticEnergy.dat", "TotalMass.dat", "StrainEnergy.dat", "TotalMomentum.dat",
                        "CenterOfMassPosition.dat"}) {
    std::string a = slurp(full / f), b = slurp(part / f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, b) << f;
  }
}

TEST(CommandLine, TimeStepBelowDeltMinExitsWith4) {
  fs::path dir = tephra::test::scratch_dir("cli_deltmin");
  std::string text = slurp(disks());
  text = std::regex_replace(text, std::regex("<delt_min>[^<]*</delt_min>"), "<delt_min>0.009</delt_min>");
  std::ofstream(dir / "deltmin.ups") << text;
  std::string out;
  EXPECT_EQ(run_tephra((dir / "deltmin.ups").string() + " --quiet --output " + (dir / "o").string(), &out), 4)
      << out;
  EXPECT_NE(out.find("delt_min"), std::string::npos) << out;
}
