// ICE on MPI ranks (issue 7): the same deck run with the whole level in this
// process (keep_whole_level: the 1-rank run, no messages) and with its
// patches cut over the world's ranks (the load balancer, MpiHaloExchange,
// ordered reductions, hypre on MPI_COMM_WORLD) must give the same answer.
//   explicit (Sod, riemann_sm.ups cut into 4 patches, two on each of 2
//   ranks, the diaphragm at x = 0.5 on the cut between patches 1 and 2):
//   every saved cell and face value, the .dat sums, the time and the step
//   count EXPECT_EQ -- bit for bit, because each rank does the one-process
//   arithmetic on its cells, ghosts arrive with the owner's bits and the sums
//   add per-patch partials in patch order;
//   implicit (Sod with <ImplicitSolver>, and the unmodified rayleigh.ups
//   cut into 4 patches along y): hypre's Krylov inner products are summed
//   across ranks in another order, so the pressure agrees to round-off only:
//   max |a - b| / max |a| <= 1e-12 per field, same step and outer-iteration
//   counts (observed: 0, the same bits, on riemann_sm and rayleigh.ups);
//   checkpoints: the archive of the distributed run equals the 1-rank
//   archive entry for entry (so a checkpoint from 2 ranks restarts on 1 and
//   one from 1 on 2), and a distributed component restored from the 1-rank
//   archive continues exactly as the 1-rank run.
// With one rank (ctest mpi_np1) both runs hold the whole level; the test then
// checks the layout code paths agree with the plain ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "core/parallel/Ranks.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

test::IceRun make_run(const std::string& deck, const std::string& patches, bool whole, bool implicit = false) {
  test::IceRun r;
  r.deck = load_deck(deck);
  test::deck_node(r.deck->root, {"Grid", "Level", "Box", "patches"}).text = patches;
  if (implicit) test::add_implicit_solver(r.deck->root, "1.0");
  r.deck->root.finalize_parents();
  r.ice = make_ice_component(*r.deck);
  if (whole) r.ice->keep_whole_level();
  r.ice->initialize();
  return r;
}

OutputFrame frame_of(const IceComponent& ice) {
  OutputFrame f;
  ice.fill_output(ice.known_labels(), f);
  return f;
}

// max over the frame's arrays of max|a - b| / max|a| (0 when a is all zero).
double worst_relative_difference(const OutputFrame& a, const OutputFrame& b) {
  double worst = 0;
  EXPECT_EQ(a.grid_fields.size(), b.grid_fields.size());
  for (std::size_t n = 0; n < std::min(a.grid_fields.size(), b.grid_fields.size()); ++n) {
    const std::vector<double>& x = a.grid_fields[n].data.values;
    const std::vector<double>& y = b.grid_fields[n].data.values;
    EXPECT_EQ(a.grid_fields[n].data.label, b.grid_fields[n].data.label);
    EXPECT_EQ(x.size(), y.size());
    double scale = 0, diff = 0;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
      scale = std::max(scale, std::abs(x[i]));
      diff = std::max(diff, std::abs(x[i] - y[i]));
    }
    if (scale > 0) worst = std::max(worst, diff / scale);
  }
  return worst;
}

void expect_frames_equal(const OutputFrame& a, const OutputFrame& b) {
  ASSERT_EQ(a.grid_fields.size(), b.grid_fields.size());
  for (std::size_t n = 0; n < a.grid_fields.size(); ++n) {
    const FieldArray& x = a.grid_fields[n].data;
    const FieldArray& y = b.grid_fields[n].data;
    ASSERT_EQ(x.label, y.label);
    ASSERT_EQ(x.material, y.material);
    ASSERT_EQ(x.values.size(), y.values.size()) << x.label;
    for (std::size_t i = 0; i < x.values.size(); ++i) ASSERT_EQ(x.values[i], y.values[i]) << x.label << " entry " << i;
  }
}

const std::string kSod = "/decks/inputs/ICE/riemann_sm.ups";

TEST(MpiIce, SodShockTubeOnRanksIsBitForBitTheOneRankRun) {
  const Ranks ranks = world_ranks();
  test::IceRun one = make_run(test::shared_dir() + kSod, "[4,1,1]", true);
  test::IceRun many = make_run(test::shared_dir() + kSod, "[4,1,1]", false);
  EXPECT_EQ(many.ice->layout().distributed, ranks.size > 1);
  EXPECT_EQ(many.ice->grid().patches.size(), ranks.size == 2 ? 2u : (ranks.size == 1 ? 4u : many.ice->grid().patches.size()));
  test::run_to(one);
  test::run_to(many);
  EXPECT_EQ(one.steps, many.steps);
  EXPECT_EQ(one.time, many.time);
  EXPECT_GT(one.steps, 50);
  expect_frames_equal(frame_of(*one.ice), frame_of(*many.ice));
  const std::set<std::string> sums = {"TotalMass", "KineticEnergy", "TotalIntEng", "TotalMomentum"};
  auto r1 = one.ice->reductions(sums), r2 = many.ice->reductions(sums);
  for (const auto& [label, v] : r1) {
    ASSERT_EQ(v.size(), r2[label].size());
    for (std::size_t c = 0; c < v.size(); ++c) EXPECT_EQ(v[c], r2[label][c]) << label;
  }
  // The shock moved: kinetic energy from zero (both states at rest).
  EXPECT_GT(r1["KineticEnergy"][0], 0.0);
  if (ranks.is_root())
    std::printf("Sod on %d rank(s): %d steps, t = %.6g, KE = %.17g (1-rank run %.17g)\n", ranks.size, many.steps,
                many.time, r2["KineticEnergy"][0], r1["KineticEnergy"][0]);
}

TEST(MpiIce, CheckpointIsTheSameOnAnyRankCountAndRestartsAcrossThem) {
  test::IceRun one = make_run(test::shared_dir() + kSod, "[4,1,1]", true);
  test::IceRun many = make_run(test::shared_dir() + kSod, "[4,1,1]", false);
  test::run_to(one, -1, 20);
  test::run_to(many, -1, 20);
  StateArchive a1, a2;
  one.ice->save_state(a1);
  many.ice->save_state(a2);
  ASSERT_EQ(a1.all_doubles().size(), a2.all_doubles().size());
  for (const auto& [name, v] : a1.all_doubles()) {
    ASSERT_TRUE(a2.has(name)) << name;
    ASSERT_EQ(v, a2.doubles(name)) << name;
  }
  // The 1-rank archive restored into a distributed component (1 -> N ranks)
  // and the N-rank archive into a whole-level one (N -> 1) continue as the
  // uninterrupted 1-rank run.
  test::IceRun restored_many = make_run(test::shared_dir() + kSod, "[4,1,1]", false);
  test::IceRun restored_one = make_run(test::shared_dir() + kSod, "[4,1,1]", true);
  restored_many.ice->load_state(a1);
  restored_one.ice->load_state(a2);
  for (test::IceRun* r : {&restored_many, &restored_one}) {
    r->time = one.time;
    r->steps = one.steps;
  }
  test::run_to(one, -1, 40);
  test::run_to(restored_many, -1, 40);
  test::run_to(restored_one, -1, 40);
  const OutputFrame f = frame_of(*one.ice);
  expect_frames_equal(f, frame_of(*restored_many.ice));
  expect_frames_equal(f, frame_of(*restored_one.ice));
}

TEST(MpiIce, ImplicitSodOnRanksMatchesTheOneRankRunToRoundOff) {
  const Ranks ranks = world_ranks();
  test::IceRun one = make_run(test::shared_dir() + kSod, "[4,1,1]", true, true);
  test::IceRun many = make_run(test::shared_dir() + kSod, "[4,1,1]", false, true);
  test::run_to(one, 1e-4);
  test::run_to(many, 1e-4);
  EXPECT_EQ(one.steps, many.steps);
  EXPECT_EQ(one.ice->last_outer_iterations(), many.ice->last_outer_iterations());
  EXPECT_GE(many.ice->last_outer_iterations(), 1);
  EXPECT_NEAR(one.time, many.time, 1e-12 * one.time);
  const double worst = worst_relative_difference(frame_of(*one.ice), frame_of(*many.ice));
  if (ranks.is_root())
    std::printf("implicit Sod on %d rank(s): %d steps, worst field difference %.3e relative\n", ranks.size,
                many.steps, worst);
  EXPECT_LE(worst, 1e-12);
}

TEST(MpiIce, RayleighDeckOnRanksMatchesTheOneRankRunToRoundOff) {
  const Ranks ranks = world_ranks();
  const std::string deck = test::shared_dir() + "/decks/orderAccuracy/ICE/rayleigh.ups";
  test::IceRun one = make_run(deck, "[1,4,1]", true);
  test::IceRun many = make_run(deck, "[1,4,1]", false);
  test::run_to(one);
  test::run_to(many);
  EXPECT_EQ(one.steps, many.steps);
  EXPECT_NEAR(one.time, many.time, 1e-12 * one.time);
  const double worst = worst_relative_difference(frame_of(*one.ice), frame_of(*many.ice));
  if (ranks.is_root())
    std::printf("rayleigh.ups on %d rank(s): %d steps, worst field difference %.3e relative\n", ranks.size,
                many.steps, worst);
  EXPECT_LE(worst, 1e-12);
}

}  // namespace
}  // namespace tephra
