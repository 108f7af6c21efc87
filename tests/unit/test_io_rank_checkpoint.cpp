// Per-rank checkpoints (issue 7 item 4, session 27; core/io/RankCheckpoint.h),
// in one process: two "ranks'" archives written as rank files plus a manifest
// read back as the archive of the whole state (oracle: the whole arrays the
// parts were cut from, built by hand); a missing, truncated or inconsistent
// rank file is a RuntimeFailure naming it; a checkpoint without a manifest is
// not offered and its rank files go at the next checkpoint; retention and a
// fresh run remove rank files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/base/Errors.h"
#include "core/io/OutputWriter.h"
#include "core/io/RankCheckpoint.h"
#include "core/io/StateArchive.h"
#include "tests/support/TestPaths.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;
namespace fs = std::filesystem;

namespace {

using Runs = std::vector<std::pair<std::size_t, std::size_t>>;

// The whole state: a field of 10 entries (entry 9 in no rank's runs: 0, as
// the gather gave), particles with ids 1..6 and 3 doubles each, an int column,
// and scalars.
StateArchive whole_state() {
  StateArchive s;
  s.put("ice.press_CC", std::vector<double>{0.5, 1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5, 0.0});
  std::vector<double> x;
  for (int id = 1; id <= 6; ++id)
    for (int c = 0; c < 3; ++c) x.push_back(id + 0.1 * c);
  s.put("mpm.m0.x", x);
  s.put("mpm.m0.id", std::vector<long long>{1, 2, 3, 4, 5, 6});
  s.put("mpm.m0.flag", std::vector<long long>{10, 20, 30, 40, 50, 60});
  s.put_scalar("timeloop.time", 0.25);
  s.put_int("timeloop.step", 10);
  return s;
}

// Rank r's part: rank 0 holds entries [0,3) and [7,9) and particles 4, 1, 6
// (not in id order across ranks), rank 1 entries [3,7) and particles 2, 3, 5.
// Rank 1's whole arrays differ from rank 0's: only rank 0's may be read.
StateArchive rank_part(int r) {
  const StateArchive w = whole_state();
  const std::vector<double>& f = w.doubles("ice.press_CC");
  StateArchive s;
  const Runs runs = r == 0 ? Runs{{0, 3}, {7, 2}} : Runs{{3, 4}};
  std::vector<double> mine;
  for (const auto& [o, n] : runs) mine.insert(mine.end(), f.begin() + long(o), f.begin() + long(o + n));
  s.put("ice.press_CC", mine, ArchivePart::as_runs(10, runs));
  const std::vector<long long> ids = r == 0 ? std::vector<long long>{4, 1, 6} : std::vector<long long>{2, 3, 5};
  std::vector<double> x;
  std::vector<long long> flag;
  for (long long id : ids) {
    for (int c = 0; c < 3; ++c) x.push_back(double(id) + 0.1 * c);
    flag.push_back(10 * id);
  }
  s.put("mpm.m0.x", x, ArchivePart::as_rows("mpm.m0.id", 3));
  s.put("mpm.m0.id", ids, ArchivePart::as_rows("mpm.m0.id", 1));
  s.put("mpm.m0.flag", flag, ArchivePart::as_rows("mpm.m0.id", 1));
  s.put_scalar("timeloop.time", r == 0 ? 0.25 : -1.0);
  s.put_int("timeloop.step", r == 0 ? 10 : -1);
  return s;
}

void write_checkpoint(CheckpointStore& store, int step, int ranks = 2) {
  for (int r = 0; r < ranks; ++r) store.write_rank_part(step, rank_part(r), r, ranks);
  store.write_manifest(step, ranks);
}


template <class Fn>
void expect_failure_naming(Fn&& fn, const std::string& name) {
  try {
    fn();
    ADD_FAILURE() << "no error; expected one naming " << name;
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(IoRankCheckpoint, FileNamesParse) {
  EXPECT_EQ(rank_checkpoint_file_name(10, 3), "c00010.r3.h5");
  EXPECT_EQ(parse_rank_checkpoint_file_name("c00010.r3.h5"), std::make_pair(10, 3));
  EXPECT_EQ(parse_rank_checkpoint_file_name("c123456.r12.h5"), std::make_pair(123456, 12));
  for (const char* bad : {"c00010.h5", "c00010.r.h5", "c.r1.h5", "t00010.r1.h5", "c00010.r1.h5.tmp", "c0001x.r1.h5"})
    EXPECT_EQ(parse_rank_checkpoint_file_name(bad).first, -1) << bad;
}

TEST(IoRankCheckpoint, RankFilesReadAsTheWholeArchive) {
  const std::string dir = test::scratch_dir("io_rank_ckpt_merge");
  CheckpointStore store(dir, 2);
  write_checkpoint(store, 10);
  EXPECT_EQ(store.steps(), std::vector<int>{10});
  EXPECT_TRUE(fs::exists(store.rank_path(10, 0)));
  EXPECT_TRUE(fs::exists(store.rank_path(10, 1)));
  test::expect_same_archive(store.read(10), whole_state());
}

TEST(IoRankCheckpoint, MissingTruncatedOrForeignRankFileIsNamed) {
  const std::string dir = test::scratch_dir("io_rank_ckpt_damage");
  CheckpointStore store(dir, 2);
  write_checkpoint(store, 10);
  const std::string r1 = store.rank_path(10, 1);
  const std::string saved = dir + "/r1.copy";
  fs::copy_file(r1, saved);
  fs::remove(r1);
  expect_failure_naming([&] { store.read(10); }, "c00010.r1.h5");
  fs::copy_file(saved, r1);
  fs::resize_file(r1, fs::file_size(r1) / 2);
  expect_failure_naming([&] { store.read(10); }, "c00010.r1.h5");
  // A rank file of another checkpoint copied in with the right size: its
  // step attribute gives it away.
  fs::remove(r1);
  store.write_rank_part(20, rank_part(1), 1, 2);
  fs::copy_file(store.rank_path(20, 1), r1);
  expect_failure_naming([&] { store.read(10); }, "c00010.r1.h5");
  // A row array whose length does not match its key's.
  StateArchive bad = rank_part(1);
  bad.put("mpm.m0.flag", std::vector<long long>{20, 30}, ArchivePart::as_rows("mpm.m0.id", 1));
  store.write_rank_part(10, bad, 1, 2);
  store.write_manifest(10, 2);
  expect_failure_naming([&] { store.read(10); }, "c00010.r1.h5");
}

TEST(IoRankCheckpoint, ManifestLessRankFilesAreNotACheckpointAndGoLater) {
  const std::string dir = test::scratch_dir("io_rank_ckpt_orphans");
  CheckpointStore store(dir, 2);
  write_checkpoint(store, 10);
  // An interrupted write at step 20: the rank files, no manifest.
  store.write_rank_part(20, rank_part(0), 0, 2);
  store.write_rank_part(20, rank_part(1), 1, 2);
  EXPECT_EQ(store.steps(), std::vector<int>{10});
  // ... and a 4-rank write of step 30 interrupted after its rank 3 file.
  store.write_rank_part(30, rank_part(1), 3, 4);
  write_checkpoint(store, 30);
  EXPECT_EQ(store.steps(), (std::vector<int>{10, 30}));
  EXPECT_FALSE(fs::exists(store.rank_path(20, 0)));
  EXPECT_FALSE(fs::exists(store.rank_path(20, 1)));
  EXPECT_FALSE(fs::exists(store.rank_path(30, 3)));
  EXPECT_TRUE(fs::exists(store.rank_path(30, 1)));
  test::expect_same_archive(store.read(30), whole_state());
  // A one-file checkpoint of step 30 (a 1-rank restart writing it again)
  // leaves no rank files of step 30.
  store.write(30, whole_state());
  EXPECT_FALSE(fs::exists(store.rank_path(30, 0)));
  test::expect_same_archive(store.read(30), whole_state());
}

TEST(IoRankCheckpoint, RetentionDropsRankFilesWithTheirManifest) {
  const std::string dir = test::scratch_dir("io_rank_ckpt_cycle");
  CheckpointStore store(dir, 2);
  for (int step : {10, 20, 30}) write_checkpoint(store, step);
  EXPECT_EQ(store.steps(), (std::vector<int>{20, 30}));
  EXPECT_FALSE(fs::exists(store.rank_path(10, 0)));
  EXPECT_FALSE(fs::exists(store.rank_path(10, 1)));
  // A restart from 20 writing 20 again drops 30 (an abandoned continuation).
  write_checkpoint(store, 20);
  EXPECT_EQ(store.steps(), std::vector<int>{20});
  EXPECT_FALSE(fs::exists(store.rank_path(30, 1)));
  // A fresh run in the directory removes every checkpoint file.
  OutputWriter fresh(dir, false);
  EXPECT_TRUE(fs::is_empty(dir + "/checkpoints"));
}
