// Output gathers to rank 0 only (issue 7 item 4, session 23;
// core/parallel/OutputGather.h). Under mpirun rank 0 alone writes frames and
// checkpoints; inside TimeLoop's OutputToRoot scope the components' gathers
// (ICE patch blocks, MPM particles and node arrays, MPMICE's node
// temperature) deliver to rank 0 only. Checked here:
//   * gather_output / gather_patch_blocks: the closed-form result (rank r
//     contributes r + 1 values r + 0.5 k) on rank 0, nothing elsewhere, and the
//     traffic counters: to rank 0, rank r > 0 sends r + 1 doubles and receives
//     none, rank 0 receives sum_{r>0} (r + 1); to every rank, each receives
//     the others' values and sends its own size - 1 times;
//   * per component (ICE Sod [4,1,1], MPM disks [2,1,1], MPMICE massX
//     [2,2,1], a few steps): the frame and the restart archive gathered to
//     rank 0 are bit for bit those gathered to every rank (which the other
//     tests in tests/mpi compare with the whole-level run), and empty on the
//     other ranks, which receive 0 doubles;
//   * TimeLoop: a Sod run with output and checkpoints: ranks > 0 receive no
//     output data, and the frame written (since session 25 one file per rank
//     plus an index; the checkpoint still gathered to rank 0) equals the
//     all-gathered frame of the same state bit for bit.
// ctest mpi_cli_sod / mpi_cli_mpm / mpi_cli_mpmice compare the files of a
// 2-rank `tephra` with the 1-rank files and restart 2 -> 1, 1 -> 2, 2 -> 4.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include "core/deck/DeckLoader.h"
#include "core/io/FrameFile.h"
#include "core/parallel/OutputGather.h"
#include "core/parallel/Ranks.h"
#include "core/sim/RunParameters.h"
#include "core/sim/TimeLoop.h"
#include "mpmice/ComponentFactory.h"
#include "tests/support/IceRuns.h"
#include "tests/support/PatchedRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

std::vector<double> my_values(int rank) {
  std::vector<double> v;
  for (int k = 0; k <= rank; ++k) v.push_back(rank + 0.5 * k);
  return v;
}

TEST(MpiOutputToRoot, GatherOutputDeliversToRankZeroOnlyInsideTheScope) {
  const Ranks r = world_ranks();
  std::vector<double> expected;
  for (int s = 0; s < r.size; ++s)
    for (double x : my_values(s)) expected.push_back(x);
  const long long total = static_cast<long long>(expected.size()), mine = r.rank + 1;

  reset_output_gather_traffic();
  EXPECT_EQ(gather_output(my_values(r.rank)), expected);  // outside: every rank
  OutputGatherTraffic t = output_gather_traffic();
  if (r.size > 1) {
    EXPECT_EQ(t.doubles_own, mine);
    EXPECT_EQ(t.doubles_received, total - mine);
    EXPECT_EQ(t.doubles_sent, mine * (r.size - 1));
  }

  reset_output_gather_traffic();
  {
    OutputToRoot to_root;
    EXPECT_TRUE(output_gathers_to_root());
    EXPECT_EQ(output_gather_lands_here(), r.is_root());
    const std::vector<double> got = gather_output(my_values(r.rank));
    if (r.is_root()) EXPECT_EQ(got, expected);
    else EXPECT_TRUE(got.empty());
  }
  EXPECT_FALSE(output_gathers_to_root());
  t = output_gather_traffic();
  if (r.size > 1) {
    EXPECT_EQ(t.calls, 1);
    EXPECT_EQ(t.doubles_own, mine);
    EXPECT_EQ(t.doubles_received, r.is_root() ? total - mine : 0);
    EXPECT_EQ(t.doubles_sent, r.is_root() ? 0 : mine);
  }

  // Patch blocks: 2 size patches, patch p on rank p % size, block p = {p, p+1..}.
  const int np = 2 * r.size;
  std::vector<int> owner(static_cast<std::size_t>(np)), own;
  std::vector<std::vector<double>> blocks;
  for (int p = 0; p < np; ++p) {
    owner[static_cast<std::size_t>(p)] = p % r.size;
    if (p % r.size == r.rank) {
      own.push_back(p);
      blocks.push_back(std::vector<double>(static_cast<std::size_t>(p + 1), double(p)));
    }
  }
  OutputToRoot to_root;
  const std::vector<std::vector<double>> all = gather_patch_blocks(owner, own, blocks);
  ASSERT_EQ(all.size(), std::size_t(np));
  for (int p = 0; p < np; ++p) {
    if (r.is_root() || r.size == 1)
      EXPECT_EQ(all[std::size_t(p)], std::vector<double>(static_cast<std::size_t>(p + 1), double(p))) << p;
    else
      EXPECT_TRUE(all[std::size_t(p)].empty()) << p;
  }
}

using Run = test::PatchedRun;

void expect_same_frames(const OutputFrame& a, const OutputFrame& b) {
  ASSERT_EQ(a.particles.size(), b.particles.size());
  for (std::size_t k = 0; k < a.particles.size(); ++k) {
    const ParticleBlock& x = a.particles[k];
    const ParticleBlock& y = b.particles[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.position, y.position);
    ASSERT_EQ(x.fields.size(), y.fields.size());
    for (std::size_t f = 0; f < x.fields.size(); ++f) EXPECT_EQ(x.fields[f].values, y.fields[f].values) << x.fields[f].label;
  }
  ASSERT_EQ(a.grid_fields.size(), b.grid_fields.size());
  for (std::size_t f = 0; f < a.grid_fields.size(); ++f) {
    EXPECT_EQ(a.grid_fields[f].data.label, b.grid_fields[f].data.label);
    EXPECT_EQ(a.grid_fields[f].data.values, b.grid_fields[f].data.values) << a.grid_fields[f].data.label;
  }
}

// Field data of a frame (particle positions, ids as doubles, values).
long long frame_doubles(const OutputFrame& f) {
  long long n = 0;
  for (const ParticleBlock& b : f.particles) {
    n += 4 * static_cast<long long>(b.id.size());
    for (const FieldArray& a : b.fields) n += static_cast<long long>(a.values.size());
  }
  for (const GridFieldArray& g : f.grid_fields) n += static_cast<long long>(g.data.values.size());
  return n;
}

void check_component(const std::string& name, const std::string& path, const std::string& patches, int steps) {
  const Ranks r = world_ranks();
  Run run = test::start_patched_run(path, patches, steps);
  const std::set<std::string> labels = run.c->known_labels();
  OutputFrame every, root;
  StateArchive a_every, a_root;
  reset_output_gather_traffic();
  run.c->fill_output(labels, every);
  run.c->save_state(a_every);
  const OutputGatherTraffic before = output_gather_traffic();
  reset_output_gather_traffic();
  {
    OutputToRoot to_root;
    run.c->fill_output(labels, root);
    run.c->save_state(a_root);
  }
  const OutputGatherTraffic after = output_gather_traffic();
  EXPECT_GT(frame_doubles(every), 0);
  if (r.is_root()) {
    expect_same_frames(every, root);
    EXPECT_EQ(a_every.all_doubles(), a_root.all_doubles());
    EXPECT_EQ(a_every.all_ints(), a_root.all_ints());
  } else {
    for (const ParticleBlock& b : root.particles) EXPECT_TRUE(b.id.empty() && b.position.empty()) << name;
    for (const GridFieldArray& g : root.grid_fields) EXPECT_TRUE(g.data.values.empty()) << name << " " << g.data.label;
    EXPECT_EQ(after.doubles_received, 0) << name;
  }
  if (r.size > 1) {
    EXPECT_EQ(before.calls, after.calls) << name << ": the same collectives in both modes";
    std::printf("[ output-to-root ] %s rank %d: frame + checkpoint, doubles sent / received: to every rank %lld / %lld,"
                " to rank 0 %lld / %lld\n",
                name.c_str(), r.rank, before.doubles_sent, before.doubles_received, after.doubles_sent,
                after.doubles_received);
  }
}

TEST(MpiOutputToRoot, IceFrameAndArchiveOnRankZeroEqualTheAllGatheredOnes) {
  check_component("ICE Sod", test::shared_dir() + "/decks/inputs/ICE/riemann_sm.ups", "[4,1,1]", 10);
}

TEST(MpiOutputToRoot, MpmFrameAndArchiveOnRankZeroEqualTheAllGatheredOnes) {
  check_component("MPM disks", test::source_dir() + "/inputs/mpm/disks.ups", "[2,1,1]", 20);
}

TEST(MpiOutputToRoot, MpmIceFrameAndArchiveOnRankZeroEqualTheAllGatheredOnes) {
  check_component("MPMICE massX", test::shared_dir() + "/decks/inputs/MPMICE/massX.ups", "[2,2,1]", 2);
}

TEST(MpiOutputToRoot, TimeLoopWritesOnRankZeroWithoutSendingOutputToOtherRanks) {
  const Ranks r = world_ranks();
  const std::string name = "mpi_output_to_root_np" + std::to_string(r.size);
  // Since session 25 every rank writes its own frame file (test_mpi_rank_files.cpp),
  // since session 27 its own checkpoint file (test_mpi_rank_checkpoints.cpp):
  // one directory for all, and no output data moves between the ranks.
  const std::string dir = std::string(TEPHRA_TEST_WORK_DIR) + "/" + name;
  if (r.is_root()) std::filesystem::remove_all(dir);
  barrier();
  auto deck = load_deck(test::shared_dir() + "/decks/inputs/ICE/riemann_sm.ups");
  test::deck_node(deck->root, {"Grid", "Level", "Box", "patches"}).text = "[4,1,1]";
  deck->root.finalize_parents();
  std::unique_ptr<Component> c = make_component(*deck);
  ArchiverParameters archiver = read_archiver_parameters(deck->root.require_child("DataArchiver"));
  archiver.output_interval.reset();
  archiver.output_timestep_interval = 5;
  archiver.checkpoint = true;
  archiver.checkpoint_interval.reset();
  archiver.checkpoint_timestep_interval = 10;
  RunOptions options;
  options.output_dir = dir;
  options.max_steps = 20;
  options.show_progress = false;
  TimeLoop loop(*c, read_time_parameters(deck->root.require_child("Time")), archiver, options);
  reset_output_gather_traffic();
  loop.run("<Uintah_specification/>");
  const OutputGatherTraffic t = output_gather_traffic();
  EXPECT_EQ(t.doubles_received, 0) << "rank " << r.rank << " received output data";
  EXPECT_EQ(t.doubles_sent, 0) << "rank " << r.rank << " sent output data";
  if (r.size > 1)
    EXPECT_TRUE(std::filesystem::exists(dir + "/checkpoints/c00020.r" + std::to_string(r.rank) + ".h5")) << r.rank;
  OutputFrame now;
  c->fill_output(archiver.labels(), now);  // gathered to every rank
  if (r.is_root()) {
    const SavedFrame saved = read_frame_file(dir + "/frames/" + frame_file_name(20));
    EXPECT_EQ(saved.step, 20);
    ASSERT_EQ(saved.grid_fields.size(), now.grid_fields.size());
    for (const SavedGridField& s : saved.grid_fields) {
      bool found = false;
      for (const GridFieldArray& g : now.grid_fields)
        if (g.data.label == s.field.data.label && g.data.material == s.field.data.material) {
          found = true;
          EXPECT_EQ(g.data.values, s.field.data.values) << g.data.label;
        }
      EXPECT_TRUE(found) << s.field.data.label;
    }
    EXPECT_TRUE(std::filesystem::exists(dir + "/checkpoints/c00020.h5"));
  }
  barrier();
}

}  // namespace
}  // namespace tephra
