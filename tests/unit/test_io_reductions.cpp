// Reduction .dat files: %.17g rows that round-trip every double exactly
// (17 significant digits identify a binary64 uniquely, IEEE 754-2008
// 5.12.2), truncation for restarts, and the clean-up of a fresh run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/io/OutputWriter.h"
#include "core/io/Reductions.h"
#include "core/io/StateArchive.h"
#include "core/io/detail/Files.h"
#include "tests/support/TestPaths.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;
namespace fs = std::filesystem;

namespace {

std::string slurp(const std::string& path) { return files::read_all(path); }

void spit(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

TEST(IoReductions, RowsRoundTripBitExact) {
  const std::string dir = test::scratch_dir("io_red_roundtrip");
  OutputWriter w(dir, false);
  const std::vector<double> awkward = {0.1, 1.0 / 3.0, -0.0,
                                       std::numeric_limits<double>::denorm_min(),
                                       std::numeric_limits<double>::max(), -1e-300};
  for (size_t n = 0; n < awkward.size(); ++n)
    w.append_reductions(0.1 * double(n), {{"KineticEnergy", {awkward[n]}},
                                          {"TotalMomentum", {awkward[n], 1.0, -awkward[n]}}});
  // The text itself: 0.1 prints as 0.10000000000000001 at 17 digits.
  const std::string text = slurp(dir + "/KineticEnergy.dat");
  EXPECT_EQ(text.substr(0, text.find('\n', text.find('\n') + 1) + 1),
            "0 0.10000000000000001\n0.10000000000000001 0.33333333333333331\n");
  const std::vector<ReductionRow> ke = read_reduction_file(dir + "/KineticEnergy.dat");
  const std::vector<ReductionRow> mom = read_reduction_file(dir + "/TotalMomentum.dat");
  ASSERT_EQ(ke.size(), awkward.size());
  ASSERT_EQ(mom.size(), awkward.size());
  for (size_t n = 0; n < awkward.size(); ++n) {
    const double t = 0.1 * double(n);
    EXPECT_EQ(std::memcmp(&ke[n].time, &t, sizeof t), 0);
    EXPECT_TRUE(test::same_bits(ke[n].values, {awkward[n]})) << n;
    EXPECT_TRUE(test::same_bits(mom[n].values, {awkward[n], 1.0, -awkward[n]})) << n;
  }
  EXPECT_EQ(read_reduction_labels(dir), (std::vector<std::string>{"KineticEnergy", "TotalMomentum"}));
}

TEST(IoReductions, BadLabelsAndEmptyValuesAreRejected) {
  const std::string dir = test::scratch_dir("io_red_bad");
  OutputWriter w(dir, false);
  EXPECT_THROW(w.append_reductions(0.0, {{"../evil", {1.0}}}), std::invalid_argument);
  EXPECT_THROW(w.append_reductions(0.0, {{"Kinetic Energy", {1.0}}}), std::invalid_argument);
  EXPECT_THROW(w.append_reductions(0.0, {{"KineticEnergy", {}}}), std::invalid_argument);
}

TEST(IoReductions, MalformedRowNamesFileAndLine) {
  const std::string dir = test::scratch_dir("io_red_malformed");
  spit(dir + "/X.dat", "0 1\n0.5 abc\n");
  try {
    read_reduction_file(dir + "/X.dat");
    FAIL() << "expected RuntimeFailure";
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find("X.dat:2"), std::string::npos) << e.what();
  }
}

TEST(IoReductions, TruncateKeepsRowsUpToRestartTime) {
  const std::string dir = test::scratch_dir("io_red_truncate");
  {
    OutputWriter w(dir, false);
    for (int n = 1; n <= 5; ++n) w.append_reductions(0.1 * n, {{"TotalMass", {double(n)}}});
  }
  // An uninterrupted run writing rows 1..5, against a run interrupted after
  // row 5, restarted from the checkpoint at t = 0.3 and rerunning 4 and 5:
  // the files must be identical.
  const std::string uninterrupted = slurp(dir + "/TotalMass.dat");
  OutputWriter r(dir, true);
  r.truncate_after(30, 0.1 * 3);
  EXPECT_EQ(read_reduction_file(dir + "/TotalMass.dat").size(), 3u);
  for (int n = 4; n <= 5; ++n) r.append_reductions(0.1 * n, {{"TotalMass", {double(n)}}});
  EXPECT_EQ(slurp(dir + "/TotalMass.dat"), uninterrupted);
}

TEST(IoReductions, RestartDropsATornRow) {
  const std::string dir = test::scratch_dir("io_red_torn");
  {
    OutputWriter w(dir, false);
    w.append_reductions(0.5, {{"TotalMass", {2.0}}});
  }
  std::ofstream(dir + "/TotalMass.dat", std::ios::app) << "0.75 1.2";  // no newline: torn
  EXPECT_EQ(read_reduction_file(dir + "/TotalMass.dat").size(), 1u);
  OutputWriter r(dir, true);
  r.append_reductions(1.0, {{"TotalMass", {3.0}}});
  EXPECT_EQ(slurp(dir + "/TotalMass.dat"), "0.5 2\n1 3\n");
}

TEST(IoReductions, FreshRunRemovesOnlyTephraFiles) {
  const std::string dir = test::scratch_dir("io_red_fresh");
  Grid grid = test::sample_grid();
  {
    OutputWriter w(dir, false);
    w.write_deck_copy("<Uintah_specification/>\n");
    w.append_reductions(0.0, {{"KineticEnergy", {1.0}}});
    w.write_frame(test::sample_frame(grid, 5));
    CheckpointStore c(dir, 2);
    c.write(5, StateArchive());
  }
  EXPECT_EQ(slurp(dir + "/input.ups"), "<Uintah_specification/>\n");
  spit(dir + "/notes.dat", "mine\n");       // not a Tephra reduction
  spit(dir + "/frames/readme.txt", "mine\n");
  {
    OutputWriter restarted(dir, true);     // keeps everything
    EXPECT_TRUE(fs::exists(dir + "/KineticEnergy.dat"));
    EXPECT_TRUE(fs::exists(dir + "/frames/t00005.h5"));
    EXPECT_TRUE(fs::exists(dir + "/tephra.xdmf"));
  }
  OutputWriter fresh(dir, false);
  EXPECT_FALSE(fs::exists(dir + "/KineticEnergy.dat"));
  EXPECT_FALSE(fs::exists(dir + "/frames/t00005.h5"));
  EXPECT_FALSE(fs::exists(dir + "/tephra.xdmf"));
  EXPECT_FALSE(fs::exists(dir + "/input.ups"));
  EXPECT_FALSE(fs::exists(dir + "/checkpoints/c00005.h5"));
  EXPECT_TRUE(fs::exists(dir + "/notes.dat"));
  EXPECT_TRUE(fs::exists(dir + "/frames/readme.txt"));
}
