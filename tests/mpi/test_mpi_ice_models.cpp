// ICE source models (<Models>) on MPI ranks (issue 7): the per-cell sources
// are computed on each rank's own patches, and the models' sums
// (totalMassBurned, totalHeatReleased, ...) are kept per patch
// (ice/models/PatchSums.h) and added in ascending patch id over the ranks.
// Expected: the distributed run is the 1-rank run (keep_whole_level, same
// process) bit for bit -- every saved cell value (F and delF included), the
// model sums, the step count and the time EXPECT_EQ -- because every rank
// does the one-process arithmetic on its cells and the sums add the same
// per-patch partials in the same order. The checkpoint of the distributed run
// equals the 1-rank checkpoint entry for entry and restarts on either.
//
// Deck: ICE/LightTime.ups (programmed burn of a 1-D Comp-B stick, decks
// README A15) with 80 cells of 2 mm (as tests/verification/test_ice_reactions)
// cut into 4 patches [4,1,1] (2 on each of 2 ranks), the burn started at the
// cut between the ranks (starting_location x = 0.08 m instead of 0: the front
// runs from the rank boundary into both ranks' patches), run 150 steps (front
// 19 mm, ~10 cells, on each side of the cut).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/io/StateArchive.h"
#include "core/parallel/Ranks.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

test::IceRun light_time_run(bool whole) {
  test::IceRun r;
  r.deck = load_deck(test::shared_dir() + "/decks/inputs/ICE/LightTime.ups");
  const int cells = 80;
  const double dx = 0.16 / cells;
  test::deck_node(r.deck->root, {"Grid", "Level", "Box", "resolution"}).text = "[80, 1, 1]";
  std::ostringstream up;
  up << "[0.16, " << dx << ", " << dx << "]";
  test::deck_node(r.deck->root, {"Grid", "Level", "Box", "upper"}).text = up.str();
  test::deck_node(r.deck->root, {"Grid", "Level", "Box", "patches"}).text = "[4,1,1]";
  test::deck_node(r.deck->root, {"Models", "Model", "LightTime", "starting_location"}).text = "[0.08, 0, 0]";
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

void expect_frames_equal(const OutputFrame& a, const OutputFrame& b) {
  ASSERT_EQ(a.grid_fields.size(), b.grid_fields.size());
  for (std::size_t n = 0; n < a.grid_fields.size(); ++n) {
    const FieldArray& x = a.grid_fields[n].data;
    const FieldArray& y = b.grid_fields[n].data;
    ASSERT_EQ(x.label, y.label);
    ASSERT_EQ(x.values.size(), y.values.size()) << x.label;
    for (std::size_t i = 0; i < x.values.size(); ++i) ASSERT_EQ(x.values[i], y.values[i]) << x.label << " entry " << i;
  }
}

const std::set<std::string> kSums = {"TotalMass", "KineticEnergy", "TotalIntEng", "totalMassBurned",
                                     "totalHeatReleased"};

void expect_sums_equal(const IceComponent& a, const IceComponent& b) {
  auto ra = a.reductions(kSums), rb = b.reductions(kSums);
  ASSERT_EQ(ra.size(), kSums.size());
  for (const auto& [label, v] : ra) {
    ASSERT_EQ(v.size(), rb[label].size()) << label;
    for (std::size_t c = 0; c < v.size(); ++c) EXPECT_EQ(v[c], rb[label][c]) << label;
  }
}

// Steps with the deck's rule (delt_init first, then the stable step).
void step_to(test::IceRun& r, int n) {
  const double delt_init = r.deck->root.require_child("Time").get_double("delt_init");
  while (r.steps < n) {
    const double dt = r.steps == 0 ? delt_init : r.ice->stable_timestep();
    r.ice->advance(r.time, dt, ++r.steps);
    r.time += dt;
  }
}

TEST(MpiIceModels, LightTimeOnRanksIsBitForBitTheOneRankRun) {
  const Ranks ranks = world_ranks();
  test::IceRun one = light_time_run(true), many = light_time_run(false);
  EXPECT_EQ(many.ice->layout().distributed, ranks.size > 1);
  double burned_one = 0, burned_many = 0;
  while (one.steps < 150) {
    step_to(one, one.steps + 1);
    step_to(many, many.steps + 1);
    ASSERT_EQ(one.time, many.time) << "step " << one.steps;
    const double b1 = one.ice->reductions({"totalMassBurned"})["totalMassBurned"][0];
    const double b2 = many.ice->reductions({"totalMassBurned"})["totalMassBurned"][0];
    ASSERT_EQ(b1, b2) << "totalMassBurned at step " << one.steps;
    burned_one += b1;
    burned_many += b2;
  }
  expect_frames_equal(frame_of(*one.ice), frame_of(*many.ice));
  expect_sums_equal(*one.ice, *many.ice);
  // The front has left the rank cut by more than 5 cells (2 mm each) on each side.
  EXPECT_GT(8.1e3 * one.time, 0.01);
  // The burned mass adds up: the products' mass is what the reactant lost
  // (TotalMass constant to round-off is checked in test_ice_reactions).
  EXPECT_GT(burned_one, 0.0);
  if (ranks.is_root())
    std::printf("LightTime on %d rank(s): %d steps, t = %.6g s, front at %.4f m, burned %.17g kg (1-rank run %.17g)\n",
                ranks.size, many.steps, many.time, 8.1e3 * many.time, burned_many, burned_one);
}

TEST(MpiIceModels, LightTimeCheckpointRestartsAcrossRankCounts) {
  test::IceRun one = light_time_run(true), many = light_time_run(false);
  step_to(one, 80);
  step_to(many, 80);
  StateArchive a1, a2;
  one.ice->save_state(a1);
  many.ice->save_state(a2);
  ASSERT_EQ(a1.all_doubles().size(), a2.all_doubles().size());
  for (const auto& [name, v] : a1.all_doubles()) {
    ASSERT_TRUE(a2.has(name)) << name;
    ASSERT_EQ(v, a2.doubles(name)) << name;
  }
  ASSERT_TRUE(a1.has("ice.model0.sums.burned_heat"));
  // 1 -> N and N -> 1: the restored sums are the saved ones at once (the
  // first output after a restart), and the runs continue as the 1-rank run.
  test::IceRun restored_many = light_time_run(false), restored_one = light_time_run(true);
  restored_many.ice->load_state(a1);
  restored_one.ice->load_state(a2);
  expect_sums_equal(*one.ice, *restored_many.ice);
  expect_sums_equal(*one.ice, *restored_one.ice);
  for (test::IceRun* r : {&restored_many, &restored_one}) {
    r->time = one.time;
    r->steps = one.steps;
  }
  step_to(one, 120);
  step_to(restored_many, 120);
  step_to(restored_one, 120);
  EXPECT_GT(one.ice->reductions({"totalMassBurned"})["totalMassBurned"][0], 0.0);
  expect_frames_equal(frame_of(*one.ice), frame_of(*restored_many.ice));
  expect_frames_equal(frame_of(*one.ice), frame_of(*restored_one.ice));
  expect_sums_equal(*one.ice, *restored_many.ice);
  expect_sums_equal(*one.ice, *restored_one.ice);
}

}  // namespace
}  // namespace tephra
