// HDF5 frame files: what write_frame writes, read_frame_file returns bit for
// bit (identity oracle), with the grid geometry and the stored extents.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "core/base/Errors.h"
#include "core/io/FrameFile.h"
#include "core/io/OutputWriter.h"
#include "tests/support/TestPaths.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;
using tephra::test::same_bits;

namespace {

const SavedGridField* find_grid(const SavedFrame& f, const std::string& label, int mat) {
  for (const SavedGridField& g : f.grid_fields)
    if (g.field.data.label == label && g.field.data.material == mat) return &g;
  return nullptr;
}

}  // namespace

TEST(IoFrame, FileNameIsZeroPaddedStep) {
  EXPECT_EQ(frame_file_name(10), "t00010.h5");
  EXPECT_EQ(frame_file_name(1234567), "t1234567.h5");
  EXPECT_EQ(parse_frame_file_name("t00010.h5"), 10);
  EXPECT_EQ(parse_frame_file_name("t00010.h5.tmp"), -1);
  EXPECT_EQ(parse_frame_file_name("t10.h5"), -1);
  EXPECT_EQ(parse_frame_file_name("x00010.h5"), -1);
}

TEST(IoFrame, RoundTripIsBitExact) {
  const std::string dir = test::scratch_dir("io_frame_roundtrip");
  Grid grid = test::sample_grid();
  OutputFrame frame = test::sample_frame(grid, 10);
  // Values whose bits a lossy path would change: -0, a subnormal, a NaN
  // with payload, the largest double.
  frame.grid_fields[0].data.values[0] = -0.0;
  frame.grid_fields[0].data.values[1] = std::numeric_limits<double>::denorm_min();
  frame.grid_fields[0].data.values[2] = std::nan("0x5a5");
  frame.grid_fields[0].data.values[3] = std::numeric_limits<double>::max();
  frame.time = 0.1 + 0.2;  // 0.30000000000000004
  OutputWriter writer(dir, false);
  writer.write_frame(frame);

  const std::string path = dir + "/frames/t00010.h5";
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  SavedFrame back = read_frame_file(path);
  EXPECT_EQ(back.step, 10);
  EXPECT_EQ(std::memcmp(&back.time, &frame.time, sizeof(double)), 0);
  ASSERT_TRUE(back.has_grid);
  EXPECT_EQ(back.grid.lower, grid.lower);
  EXPECT_EQ(back.grid.dx, grid.dx);
  EXPECT_EQ(back.grid.cells, grid.cells);
  EXPECT_EQ(back.grid.extra_cells, grid.extra_cells);

  ASSERT_EQ(back.grid_fields.size(), frame.grid_fields.size());
  for (const GridFieldArray& in : frame.grid_fields) {
    const SavedGridField* out = find_grid(back, in.data.label, in.data.material);
    ASSERT_NE(out, nullptr) << in.data.label;
    EXPECT_EQ(out->field.location, in.location);
    EXPECT_EQ(out->field.data.components, in.data.components);
    EXPECT_TRUE(same_bits(out->field.data.values, in.data.values)) << in.data.label;
  }
  // Extents: cells (3,2,4) for interior cell fields, +2*extra for temp_CC
  // starting at -extra, cells+1 nodes for g.mass.
  EXPECT_EQ(find_grid(back, "press_CC", 0)->extent, IntVec3(3, 2, 4));
  EXPECT_EQ(find_grid(back, "press_CC", 0)->first_index, IntVec3(0, 0, 0));
  EXPECT_EQ(find_grid(back, "temp_CC", 0)->extent, IntVec3(5, 4, 6));
  EXPECT_EQ(find_grid(back, "temp_CC", 0)->first_index, IntVec3(-1, -1, -1));
  EXPECT_EQ(find_grid(back, "g.mass", 0)->extent, IntVec3(4, 3, 5));

  ASSERT_EQ(back.particles.size(), 3u);
  for (size_t b = 0; b < 3; ++b) {
    const ParticleBlock& in = frame.particles[b];
    const ParticleBlock& out = back.particles[b].block;
    EXPECT_EQ(out.material, in.material);
    EXPECT_EQ(back.particles[b].count, static_cast<long long>(in.position.size()));
    ASSERT_EQ(out.position.size(), in.position.size());
    for (size_t p = 0; p < in.position.size(); ++p) EXPECT_EQ(out.position[p], in.position[p]);
    EXPECT_EQ(out.id, in.id);
    ASSERT_EQ(out.fields.size(), in.fields.size());
    for (const FieldArray& f : in.fields) {
      bool found = false;
      for (const FieldArray& g : out.fields)
        if (g.label == f.label) {
          found = true;
          EXPECT_EQ(g.components, f.components);
          EXPECT_TRUE(same_bits(g.values, f.values)) << f.label;
        }
      EXPECT_TRUE(found) << f.label;
    }
  }
}

TEST(IoFrame, LayoutReadSkipsValues) {
  const std::string dir = test::scratch_dir("io_frame_layout");
  Grid grid = test::sample_grid();
  OutputWriter writer(dir, false);
  writer.write_frame(test::sample_frame(grid, 3));
  SavedFrame layout = read_frame_file(dir + "/frames/t00003.h5", false);
  ASSERT_EQ(layout.grid_fields.size(), 5u);
  for (const SavedGridField& g : layout.grid_fields) EXPECT_TRUE(g.field.data.values.empty());
  EXPECT_EQ(layout.particles[0].count, 5);
  EXPECT_TRUE(layout.particles[0].block.position.empty());
}

TEST(IoFrame, InconsistentFramesAreRejected) {
  const std::string dir = test::scratch_dir("io_frame_bad");
  Grid grid = test::sample_grid();
  OutputWriter writer(dir, false);
  {
    OutputFrame f = test::sample_frame(grid, 1);
    f.grid_fields[0].data.values.pop_back();  // fits neither 24 nor 120 cells
    EXPECT_THROW(writer.write_frame(f), std::invalid_argument);
  }
  {
    OutputFrame f = test::sample_frame(grid, 1);
    f.particles[0].fields[0].values.pop_back();
    EXPECT_THROW(writer.write_frame(f), std::invalid_argument);
  }
  {
    OutputFrame f = test::sample_frame(grid, 1);
    f.particles[0].fields[1].components = 2;
    EXPECT_THROW(writer.write_frame(f), std::invalid_argument);
  }
  {
    OutputFrame f = test::sample_frame(grid, 1);
    f.grid_fields[0].data.label = "a/b";
    EXPECT_THROW(writer.write_frame(f), std::invalid_argument);
  }
  // Nothing half-written is left behind, and no index lists a bad frame.
  EXPECT_FALSE(std::filesystem::exists(dir + "/frames/t00001.h5"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/frames/t00001.h5.tmp"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/tephra.xdmf"));
}

TEST(IoFrame, UnreadableFileNamesTheFile) {
  const std::string dir = test::scratch_dir("io_frame_unreadable");
  const std::string path = dir + "/t00001.h5";
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("not hdf5", f);
  std::fclose(f);
  try {
    read_frame_file(path);
    FAIL() << "expected RuntimeFailure";
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_frame_file(dir + "/missing.h5"), RuntimeFailure);
}
