// Per-rank checkpoints under mpirun (issue 7 item 4, session 27;
// core/io/RankCheckpoint.h, core/sim/TimeLoop.cpp write_checkpoint).
// Per component (ICE Sod [4,1,1], MPM disks [2,1,1] with its contact, MPMICE
// massX [2,2,1], a few steps), on every rank count the suite runs:
//   * inside OutputPerRank save_state sends and receives nothing (rank 0
//     receives 0 doubles of checkpoint data);
//   * every rank writes c<step>.r<rank>.h5, rank 0 the manifest c<step>.h5;
//     the archive read back through the manifest equals, array by array and
//     bit for bit, the archive gathered to every rank (what rank 0 wrote into
//     its single checkpoint file before session 27, and what a 1-rank run
//     writes: tests/mpi/test_mpi_ice.cpp Checkpoint*, the mpi_cli_* restarts);
//   * a fresh component restored from it on the same ranks continues as the
//     uninterrupted run, bit for bit (the frames of both after more steps).
// Restarts across rank counts (2 -> 1, 1 -> 2, 2 -> 4) of the executable
// through these files: ctest mpi_cli_sod / mpi_cli_mpm / mpi_cli_mpmice, which
// also check a missing or truncated rank file and a manifest-less checkpoint.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/io/OutputWriter.h"
#include "core/io/StateArchive.h"
#include "core/parallel/OutputGather.h"
#include "core/parallel/Ranks.h"
#include "core/sim/RunParameters.h"
#include "mpmice/ComponentFactory.h"
#include "tests/support/IceRuns.h"
#include "tests/support/PatchedRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

void expect_archives_equal(const StateArchive& merged, const StateArchive& every, const std::string& name) {
  EXPECT_EQ(merged.all_doubles().size(), every.all_doubles().size()) << name;
  EXPECT_EQ(merged.all_ints().size(), every.all_ints().size()) << name;
  for (const auto& [label, v] : every.all_doubles()) {
    ASSERT_TRUE(merged.has(label)) << name << ": " << label;
    EXPECT_TRUE(same_bits(merged.doubles(label), v)) << name << ": " << label;
  }
  for (const auto& [label, v] : every.all_ints()) {
    ASSERT_TRUE(merged.has(label)) << name << ": " << label;
    EXPECT_EQ(merged.ints(label), v) << name << ": " << label;
  }
}

void expect_frames_equal(const OutputFrame& a, const OutputFrame& b, const std::string& name) {
  ASSERT_EQ(a.grid_fields.size(), b.grid_fields.size()) << name;
  for (std::size_t n = 0; n < a.grid_fields.size(); ++n) {
    EXPECT_EQ(a.grid_fields[n].data.label, b.grid_fields[n].data.label) << name;
    EXPECT_TRUE(same_bits(a.grid_fields[n].data.values, b.grid_fields[n].data.values))
        << name << ": " << a.grid_fields[n].data.label << " of material " << a.grid_fields[n].data.material;
  }
  ASSERT_EQ(a.particles.size(), b.particles.size()) << name;
  for (std::size_t m = 0; m < a.particles.size(); ++m) {
    EXPECT_EQ(a.particles[m].id, b.particles[m].id) << name;
    EXPECT_EQ(a.particles[m].position, b.particles[m].position) << name;
    ASSERT_EQ(a.particles[m].fields.size(), b.particles[m].fields.size()) << name;
    for (std::size_t f = 0; f < a.particles[m].fields.size(); ++f)
      EXPECT_TRUE(same_bits(a.particles[m].fields[f].values, b.particles[m].fields[f].values))
          << name << ": " << a.particles[m].fields[f].label;
  }
}

// `steps` more steps of min(delt_max, multiplier x stable dt), numbered from `first`.
void advance(test::PatchedRun& run, int first, int steps) {
  const TimeParameters tp = read_time_parameters(run.deck->root.require_child("Time"));
  for (int s = first; s < first + steps; ++s) {
    const double dt = std::min(tp.delt_max, tp.timestep_multiplier * run.c->stable_timestep());
    run.c->advance(run.t, dt, s);
    run.t += dt;
  }
}

void check_component(const std::string& name, const std::string& path, const std::string& patches, int steps) {
  const Ranks r = world_ranks();
  test::PatchedRun run = test::start_patched_run(path, patches, steps);
  StateArchive every, mine;
  run.c->save_state(every);  // gathered to every rank
  reset_output_gather_traffic();
  {
    OutputPerRank per_rank;
    run.c->save_state(mine);
  }
  const OutputGatherTraffic t = output_gather_traffic();
  EXPECT_EQ(t.doubles_received, 0) << name << " rank " << r.rank;
  EXPECT_EQ(t.doubles_sent, 0) << name << " rank " << r.rank;

  const std::string dir = std::string(TEPHRA_TEST_WORK_DIR) + "/mpi_rank_checkpoints_" + name + "_np" + std::to_string(r.size);
  if (r.is_root()) std::filesystem::remove_all(dir);
  barrier();
  CheckpointStore store(dir, 2);
  if (r.size > 1) {
    store.write_rank_part(steps, mine, r.rank, r.size);
    barrier();
    if (r.is_root()) store.write_manifest(steps, r.size);
  } else if (r.is_root()) {
    store.write(steps, mine);
  }
  barrier();
  EXPECT_EQ(std::filesystem::exists(store.rank_path(steps, r.rank)), r.size > 1) << name;
  const StateArchive merged = store.read(steps);
  expect_archives_equal(merged, every, name);
  // A wrong archive would make the ranks' continued runs diverge (and wait
  // on each other): continue only when every rank read it right.
  if (any_rank(::testing::Test::HasFailure())) {
    ADD_FAILURE() << name << ": the merged archive differs on some rank; restart not tried";
    return;
  }

  // A fresh component restored from the files on these ranks continues as the run.
  test::PatchedRun restored;
  restored.deck = load_deck(path);
  test::deck_node(restored.deck->root, {"Grid", "Level", "Box", "patches"}).text = patches;
  restored.deck->root.finalize_parents();
  restored.c = make_component(*restored.deck);
  restored.c->load_state(merged);
  restored.t = run.t;
  advance(run, steps + 1, 3);
  advance(restored, steps + 1, 3);
  std::set<std::string> labels = run.c->known_labels();
  OutputFrame a, b;
  run.c->fill_output(labels, a);
  for (const GridFieldArray& g : a.grid_fields)  // node columns a component does not keep (MPMICE's g.stressFS)
    if (g.data.values.empty()) labels.erase(g.data.label);
  a = OutputFrame{};
  run.c->fill_output(labels, a);
  restored.c->fill_output(labels, b);
  expect_frames_equal(a, b, name + " restored");
  barrier();
}

TEST(MpiRankCheckpoints, IceRankFilesMergeIntoTheGatheredArchiveAndRestart) {
  check_component("ICE_Sod", test::shared_dir() + "/decks/inputs/ICE/riemann_sm.ups", "[4,1,1]", 10);
}

TEST(MpiRankCheckpoints, MpmRankFilesMergeIntoTheGatheredArchiveAndRestart) {
  check_component("MPM_disks", test::source_dir() + "/inputs/mpm/disks.ups", "[2,1,1]", 20);
}

TEST(MpiRankCheckpoints, MpmIceRankFilesMergeIntoTheGatheredArchiveAndRestart) {
  check_component("MPMICE_massX", test::shared_dir() + "/decks/inputs/MPMICE/massX.ups", "[2,2,1]", 2);
}

}  // namespace
}  // namespace tephra
