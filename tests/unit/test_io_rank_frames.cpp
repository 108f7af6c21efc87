// Per-rank frame files (issue 7 item 4, session 25; core/io/RankFrameFile.h).
// The closed-form sample frame (test_io_sample.h) is cut over two "ranks" the
// way the components cut it under mpirun -- grid fields into pieces (some
// owned by the later box, some by the earlier one, one whole array written by
// rank 0 alone), particles shuffled over the ranks -- and written as two rank
// files plus the index. Reading the index must give the single file's frame
// bit for bit, `tephra extract` the same CSV, tephra.xdmf only valid
// references into both rank files, and a missing rank file an error naming it.
// The box arithmetic behind the pieces (core/io/ArrayBoxes.h) is checked
// against brute-force membership.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <pugixml.hpp>
#include <random>
#include <set>
#include <sstream>

#include "core/base/Errors.h"
#include "core/io/ArrayBoxes.h"
#include "core/io/Extract.h"
#include "core/io/FrameFile.h"
#include "core/io/OutputWriter.h"
#include "core/io/RankFrameFile.h"
#include "tests/support/TestPaths.h"
#include "tests/support/XdmfCheck.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;

namespace {

namespace fs = std::filesystem;

bool in_box(const ArrayBox& b, int i, int j, int k) {
  return i >= b.lo[0] && i < b.hi[0] && j >= b.lo[1] && j < b.hi[1] && k >= b.lo[2] && k < b.hi[2];
}

// Brute force: every point of `a` lies in exactly one piece when it is in none
// of `minus`, else in no piece; no piece leaves `a`.
void expect_difference(const ArrayBox& a, const std::vector<ArrayBox>& minus, const std::vector<ArrayBox>& pieces) {
  long long covered = 0;
  for (const ArrayBox& p : pieces) {
    EXPECT_FALSE(p.empty());
    EXPECT_TRUE((p.lo.array() >= a.lo.array()).all() && (p.hi.array() <= a.hi.array()).all());
    covered += p.count();
  }
  long long expected = 0;
  for (int k = a.lo[2]; k < a.hi[2]; ++k)
    for (int j = a.lo[1]; j < a.hi[1]; ++j)
      for (int i = a.lo[0]; i < a.hi[0]; ++i) {
        bool removed = false;
        for (const ArrayBox& m : minus) removed |= in_box(m, i, j, k);
        int hits = 0;
        for (const ArrayBox& p : pieces) hits += in_box(p, i, j, k);
        EXPECT_EQ(hits, removed ? 0 : 1) << i << "," << j << "," << k;
        expected += !removed;
      }
  EXPECT_EQ(covered, expected);  // disjoint: the counts add up
}

TEST(IoRankFrames, BoxDifferenceIsExactByBruteForce) {
  // A 4^3 box minus its centre 2^3: 64 - 8 = 56 entries in 6 slabs.
  const ArrayBox a{IntVec3(0, 0, 0), IntVec3(4, 4, 4)};
  const std::vector<ArrayBox> centre = {{IntVec3(1, 1, 1), IntVec3(3, 3, 3)}};
  const std::vector<ArrayBox> p = subtract_boxes(a, centre);
  EXPECT_EQ(p.size(), 6u);
  expect_difference(a, centre, p);
  // Random boxes, several subtracted at once (overlapping each other too).
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> d(-2, 7);
  for (int trial = 0; trial < 200; ++trial) {
    auto box = [&] {
      ArrayBox b;
      for (int c = 0; c < 3; ++c) {
        int x = d(rng), y = d(rng);
        b.lo[c] = std::min(x, y);
        b.hi[c] = std::max(x, y) + 1;
      }
      return b;
    };
    const ArrayBox a2 = box();
    std::vector<ArrayBox> minus;
    for (int m = 0; m < trial % 4; ++m) minus.push_back(box());
    expect_difference(a2, minus, subtract_boxes(a2, minus));
  }
  // Owner rules: later / earlier box wins over the shared slab x = 2.
  const std::vector<ArrayBox> two = {{IntVec3(0, 0, 0), IntVec3(3, 1, 1)}, {IntVec3(2, 0, 0), IntVec3(4, 1, 1)}};
  EXPECT_EQ(kept_when_later_wins(two, 0), (std::vector<ArrayBox>{{IntVec3(0, 0, 0), IntVec3(2, 1, 1)}}));
  EXPECT_EQ(kept_when_later_wins(two, 1), (std::vector<ArrayBox>{two[1]}));
  EXPECT_EQ(kept_when_earlier_wins(two, 0), (std::vector<ArrayBox>{two[0]}));
  EXPECT_EQ(kept_when_earlier_wins(two, 1), (std::vector<ArrayBox>{{IntVec3(3, 0, 0), IntVec3(4, 1, 1)}}));
}

// Rank r's part of the sample frame at `step` (r = 0, 1). Entries another rank
// writes are poisoned with NaN here, so a merge that took them would differ.
OutputFrame rank_part(const Grid& grid, int step, int r) {
  OutputFrame f = test::sample_frame(grid, step);
  const double nan = std::nan("");
  auto poison_outside = [&](GridFieldArray& g, const IntVec3& extent) {
    const int nc = g.data.components;
    for (int k = 0; k < extent[2]; ++k)
      for (int j = 0; j < extent[1]; ++j)
        for (int i = 0; i < extent[0]; ++i) {
          bool mine = false;
          for (const ArrayBox& b : g.pieces) mine |= in_box(b, i, j, k);
          if (!mine)
            for (int c = 0; c < nc; ++c) g.data.values[std::size_t(((k * extent[1] + j) * extent[0] + i) * nc + c)] = nan;
        }
  };
  const IntVec3 cells = grid.cells, with_extra = grid.cells + 2 * grid.extra_cells, nodes = grid.cells + IntVec3::Ones();
  for (GridFieldArray& g : f.grid_fields) {
    const std::string& l = g.data.label;
    if (l == "press_CC" && g.data.material == 1) continue;  // unmarked: whole on every rank, rank 0 writes it
    g.partial = true;
    if (l == "press_CC") {  // i < 2 on rank 0, the rest on rank 1
      g.pieces = {r == 0 ? ArrayBox{IntVec3::Zero(), IntVec3(2, cells[1], cells[2])}
                         : ArrayBox{IntVec3(2, 0, 0), cells}};
      poison_outside(g, cells);
    } else if (l == "vel_CC") {  // all of it on rank 1
      if (r == 1) g.pieces = {{IntVec3::Zero(), cells}};
      poison_outside(g, cells);
    } else if (l == "temp_CC") {  // overlapping boxes along k, the later (rank 1) wins
      const std::vector<ArrayBox> boxes = {{IntVec3::Zero(), IntVec3(with_extra[0], with_extra[1], 4)},
                                           {IntVec3(0, 0, 2), with_extra}};
      g.pieces = kept_when_later_wins(boxes, std::size_t(r));
      poison_outside(g, with_extra);
    } else if (l == "g.mass") {  // overlapping node boxes along j, the earlier (rank 0) wins
      const std::vector<ArrayBox> boxes = {{IntVec3::Zero(), IntVec3(nodes[0], 2, nodes[2])},
                                           {IntVec3(0, 1, 0), nodes}};
      g.pieces = kept_when_earlier_wins(boxes, std::size_t(r));
      poison_outside(g, nodes);
    }
  }
  // Particles: material 0's odd ids on rank 0, even ids on rank 1 (each rank's
  // own in ascending id); material 1 on rank 1; material 2 empty on both.
  for (ParticleBlock& b : f.particles) {
    ParticleBlock kept{b.material, {}, {}, {}};
    for (FieldArray fa : b.fields) {
      fa.values.clear();
      kept.fields.push_back(fa);
    }
    for (std::size_t q = 0; q < b.id.size(); ++q) {
      const int owner = b.material == 0 ? int(1 - b.id[q] % 2) : 1;
      if (owner != r) continue;
      kept.position.push_back(b.position[q]);
      kept.id.push_back(b.id[q]);
      for (std::size_t n = 0; n < b.fields.size(); ++n) {
        const int nc = b.fields[n].components;
        kept.fields[n].values.insert(kept.fields[n].values.end(), b.fields[n].values.begin() + long(q * nc),
                                     b.fields[n].values.begin() + long((q + 1) * nc));
      }
    }
    b = kept;
  }
  return f;
}

void write_two_ranks(const std::string& dir, const Grid& grid, const std::vector<int>& steps) {
  OutputWriter writer(dir, false);
  for (int step : steps) {
    for (int r = 0; r < 2; ++r) write_rank_frame(dir, rank_part(grid, step, r), r, 2);
    writer.write_frame_index(step, step * 1e-3, 2);
  }
}

void expect_same_saved(const SavedFrame& a, const SavedFrame& b) {
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.grid.cells, b.grid.cells);
  EXPECT_EQ(a.grid.lower, b.grid.lower);
  ASSERT_EQ(a.grid_fields.size(), b.grid_fields.size());
  for (std::size_t n = 0; n < a.grid_fields.size(); ++n) {
    const SavedGridField &x = a.grid_fields[n], &y = b.grid_fields[n];
    EXPECT_EQ(x.field.data.label, y.field.data.label);
    EXPECT_EQ(x.field.data.material, y.field.data.material);
    EXPECT_EQ(x.field.data.components, y.field.data.components);
    EXPECT_EQ(x.field.location, y.field.location);
    EXPECT_EQ(x.first_index, y.first_index) << x.field.data.label;
    EXPECT_EQ(x.extent, y.extent) << x.field.data.label;
    EXPECT_TRUE(test::same_bits(x.field.data.values, y.field.data.values)) << x.field.data.label;
  }
  ASSERT_EQ(a.particles.size(), b.particles.size());
  for (std::size_t n = 0; n < a.particles.size(); ++n) {
    const ParticleBlock &x = a.particles[n].block, &y = b.particles[n].block;
    EXPECT_EQ(a.particles[n].count, b.particles[n].count);
    EXPECT_EQ(x.material, y.material);
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.position, y.position);
    ASSERT_EQ(x.fields.size(), y.fields.size());
    for (std::size_t f = 0; f < x.fields.size(); ++f) {
      EXPECT_EQ(x.fields[f].label, y.fields[f].label);
      EXPECT_TRUE(test::same_bits(x.fields[f].values, y.fields[f].values)) << x.fields[f].label;
    }
  }
}

std::string extract(const std::string& dir, const std::string& label) {
  ExtractRequest r;
  r.dir = dir;
  r.label = label;
  r.when = ExtractRequest::When::AllTimes;
  std::ostringstream out;
  extract_csv(r, out);
  return out.str();
}

TEST(IoRankFrames, TwoRankFilesReadAsTheSingleFileBitForBit) {
  const Grid grid = test::sample_grid();
  const std::string single = test::scratch_dir("io_rank_frames_single");
  const std::string ranks = test::scratch_dir("io_rank_frames_two");
  {
    OutputWriter w(single, false);
    w.write_frame(test::sample_frame(grid, 0));
    w.write_frame(test::sample_frame(grid, 10));
  }
  write_two_ranks(ranks, grid, {0, 10});
  for (int step : {0, 10}) {
    const std::string index = ranks + "/frames/" + frame_file_name(step);
    EXPECT_TRUE(fs::exists(ranks + "/frames/" + rank_frame_file_name(step, 0)));
    EXPECT_TRUE(fs::exists(ranks + "/frames/" + rank_frame_file_name(step, 1)));
    const SavedFrame one = read_frame_file(single + "/frames/" + frame_file_name(step));
    expect_same_saved(one, read_frame_file(index));
    expect_same_saved(read_frame_file(single + "/frames/" + frame_file_name(step), false),
                      read_frame_file(index, false));  // layout-only reads agree too
    expect_same_saved(read_frame_file(single + "/frames/" + frame_file_name(step), true, "p.mass"),
                      read_frame_file(index, true, "p.mass"));
  }
  // tephra extract: the same CSV for cell (split, whole-on-rank-0, extra
  // cells), node and particle labels of both frames.
  for (const char* label : {"press_CC", "vel_CC", "temp_CC", "g.mass", "p.x", "p.mass", "p.stress", "p.velocity"}) {
    const std::string a = extract(single, label), b = extract(ranks, label);
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b) << label;
  }
  // The rank files (not the single file's datasets) are what the index names.
  EXPECT_TRUE(is_frame_index_file(ranks + "/frames/t00010.h5"));
  EXPECT_FALSE(is_frame_index_file(single + "/frames/t00010.h5"));
}

TEST(IoRankFrames, XdmfNamesEveryRankFileWithValidReferences) {
  const Grid grid = test::sample_grid();
  const std::string dir = test::scratch_dir("io_rank_frames_xdmf");
  write_two_ranks(dir, grid, {0, 10});
  for (bool reopened : {false, true}) {
    if (reopened) OutputWriter(dir, true);  // a restart indexes the frames on disk again
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file((dir + "/tephra.xdmf").c_str()));
    std::set<std::string> files;
    EXPECT_GT(test::check_xdmf_references(doc, dir, &files), 0);
    EXPECT_EQ(files, (std::set<std::string>{"frames/t00000.r0.h5", "frames/t00000.r1.h5", "frames/t00010.r0.h5",
                                            "frames/t00010.r1.h5"}));
    // Both ranks' particle sets are listed (material 0 on both, 1 on rank 1 only;
    // the empty material 2 nowhere).
    pugi::xml_node series = doc.child("Xdmf").child("Domain").child("Grid");
    int frames = 0;
    for (pugi::xml_node f : series.children("Grid")) {
      ++frames;
      EXPECT_TRUE(f.find_child_by_attribute("Grid", "Name", "r0_particles_mat0"));
      EXPECT_TRUE(f.find_child_by_attribute("Grid", "Name", "r1_particles_mat0"));
      EXPECT_TRUE(f.find_child_by_attribute("Grid", "Name", "r1_particles_mat1"));
      EXPECT_FALSE(f.find_child_by_attribute("Grid", "Name", "r0_particles_mat1"));
      EXPECT_FALSE(f.find_child_by_attribute("Grid", "Name", "r0_particles_mat2"));
    }
    EXPECT_EQ(frames, 2);
  }
}

TEST(IoRankFrames, MissingRankFileIsAnErrorNamingIt) {
  const Grid grid = test::sample_grid();
  const std::string dir = test::scratch_dir("io_rank_frames_missing");
  write_two_ranks(dir, grid, {10});
  const std::string gone = dir + "/frames/" + rank_frame_file_name(10, 1);
  fs::remove(gone);
  try {
    extract(dir, "press_CC");
    ADD_FAILURE() << "no error for a missing rank file";
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find(gone), std::string::npos) << e.what();
  }
  // A restart indexes the frames on disk again: the same error.
  try {
    OutputWriter again(dir, true);
    ADD_FAILURE() << "a restart accepted a frame with a missing rank file";
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find(gone), std::string::npos) << e.what();
  }
  // The index is only written once every rank file is there.
  const std::string fresh = test::scratch_dir("io_rank_frames_missing_index");
  OutputWriter w(fresh, false);
  write_rank_frame(fresh, rank_part(grid, 20, 0), 0, 2);
  EXPECT_THROW(w.write_frame_index(20, 0.02, 2), RuntimeFailure);
  EXPECT_FALSE(fs::exists(fresh + "/frames/" + frame_file_name(20)));
}

TEST(IoRankFrames, FreshRunAndRestartRemoveStaleRankFiles) {
  const Grid grid = test::sample_grid();
  const std::string dir = test::scratch_dir("io_rank_frames_stale");
  write_two_ranks(dir, grid, {0, 10, 20});
  // A rank file of step 30 whose index was never written, and a torn tmp file.
  write_rank_frame(dir, rank_part(grid, 30, 0), 0, 2);
  { std::ofstream(dir + "/frames/t00030.r1.h5.tmp") << "torn"; }
  {
    OutputWriter w(dir, true);
    EXPECT_FALSE(fs::exists(dir + "/frames/t00030.r1.h5.tmp"));
    w.truncate_after(10, 0.01);  // a restart from step 10
  }
  EXPECT_TRUE(fs::exists(dir + "/frames/t00010.r1.h5"));
  for (const char* name : {"t00020.h5", "t00020.r0.h5", "t00020.r1.h5", "t00030.r0.h5"})
    EXPECT_FALSE(fs::exists(dir + "/frames/" + name)) << name;
  OutputWriter fresh(dir, false);  // a new run removes every frame file
  for (const auto& e : fs::directory_iterator(dir + "/frames")) ADD_FAILURE() << e.path();
}

TEST(IoRankFrames, RankFileNamesParse) {
  EXPECT_EQ(rank_frame_file_name(10, 3), "t00010.r3.h5");
  EXPECT_EQ(parse_rank_frame_file_name("t00010.r3.h5"), std::make_pair(10, 3));
  EXPECT_EQ(parse_rank_frame_file_name("t123456.r12.h5"), std::make_pair(123456, 12));
  for (const char* bad : {"t00010.h5", "t00010.r.h5", "t00010.rx.h5", "t0001.r1.h5", "t00010.r1.h5.tmp", "c00010.r1.h5"})
    EXPECT_EQ(parse_rank_frame_file_name(bad).first, -1) << bad;
  EXPECT_EQ(parse_frame_file_name("t00010.r3.h5"), -1);  // never taken for a single frame file
}

}  // namespace
