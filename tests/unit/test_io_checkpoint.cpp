// Checkpoints: a StateArchive written and read back is identical bit for bit
// (identity oracle); only the newest `cycle` files are kept; a missing,
// truncated or corrupted file is a RuntimeFailure naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/base/Errors.h"
#include "core/io/OutputWriter.h"
#include "core/io/StateArchive.h"
#include "core/io/detail/Files.h"
#include "tests/support/TestPaths.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;
namespace fs = std::filesystem;

namespace {

StateArchive sample_state(double salt) {
  StateArchive s;
  std::vector<double> x;
  for (int n = 0; n < 100000; ++n) x.push_back(salt + n / 7.0);  // spans two chunks
  s.put("mpm/mat0/p.x", x);
  s.put("%odd name", std::vector<double>{-0.0, std::numeric_limits<double>::denorm_min(),
                                         std::nan("0x123"), std::numeric_limits<double>::infinity(),
                                         std::numeric_limits<double>::max()});
  s.put(".hidden", std::vector<double>{});
  s.put("ice/press_CC", std::vector<double>{salt});
  s.put("ids", std::vector<long long>{std::numeric_limits<long long>::min(), -1, 0,
                                      std::numeric_limits<long long>::max()});
  s.put_int("step", 42);
  s.put_scalar("time", 0.1 + 0.2);
  return s;
}


// Where `value`'s 8 bytes first occur in the file.
size_t find_bytes(const std::string& data, double value) {
  return data.find(std::string(reinterpret_cast<const char*>(&value), sizeof value));
}

}  // namespace

TEST(IoCheckpoint, RoundTripIsBitExact) {
  const std::string dir = test::scratch_dir("io_ckpt_roundtrip");
  CheckpointStore store(dir, 3);
  const StateArchive in = sample_state(0.5);
  store.write(7, in);
  EXPECT_TRUE(fs::exists(dir + "/checkpoints/c00007.h5"));
  EXPECT_FALSE(fs::exists(dir + "/checkpoints/c00007.h5.tmp"));
  test::expect_same_archive(in, store.read(7));
  test::expect_same_archive(store.read(7), in);
  EXPECT_EQ(store.read(7).integer("step"), 42);
}

TEST(IoCheckpoint, KeepsTheNewestCycle) {
  const std::string dir = test::scratch_dir("io_ckpt_cycle");
  CheckpointStore store(dir, 2);
  for (int s : {10, 20, 30}) store.write(s, sample_state(s));
  EXPECT_EQ(store.steps(), (std::vector<int>{20, 30}));
  test::expect_same_archive(sample_state(20), store.read(20));
  // A restart from 20 writes 25: 30 belongs to the abandoned continuation.
  store.write(25, sample_state(25));
  EXPECT_EQ(store.steps(), (std::vector<int>{20, 25}));
  // A leftover tmp from a crash is not a checkpoint.
  std::ofstream(dir + "/checkpoints/c00040.h5.tmp") << "partial";
  EXPECT_EQ(store.steps(), (std::vector<int>{20, 25}));
  EXPECT_THROW(CheckpointStore(dir, 0), std::invalid_argument);
}

TEST(IoCheckpoint, MissingTruncatedOrCorruptFilesFail) {
  const std::string dir = test::scratch_dir("io_ckpt_corrupt");
  CheckpointStore store(dir, 5);
  auto expect_failure_naming = [&](int step) {
    try {
      store.read(step);
      FAIL() << "expected RuntimeFailure for step " << step;
    } catch (const RuntimeFailure& e) {
      EXPECT_NE(std::string(e.what()).find(store.path(step)), std::string::npos) << e.what();
    }
  };
  expect_failure_naming(3);  // absent

  store.write(1, sample_state(1.0));
  std::string bytes = files::read_all(store.path(1));
  std::ofstream(store.path(1), std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  expect_failure_naming(1);  // truncated

  store.write(2, sample_state(2.0));
  bytes = files::read_all(store.path(2));
  // Flip one bit of a stored double of mpm/mat0/p.x (value 2 + 500/7): the
  // Fletcher-32 checksum of its chunk no longer matches.
  const size_t at = find_bytes(bytes, 2.0 + 500 / 7.0);
  ASSERT_NE(at, std::string::npos);
  bytes[at] ^= 0x01;
  std::ofstream(store.path(2), std::ios::binary | std::ios::trunc) << bytes;
  expect_failure_naming(2);  // corrupt
}
