// MPMICE on MPI ranks (issue 7, docs/parallel.md "MPMICE on ranks"): the
// coupled decks cut into patches, run with the whole level in this process
// (keep_whole_level: the 1-rank run) and with the patches spread over the
// world's ranks, stepped with the same dt (the deck's rule on the whole run).
//
// Where 1 and 2 ranks first differ (session 16, per field and step): the MPM
// node sums at nodes that particles of two ranks reach (g.mass 3.6e-16 of its
// max at t = 0 in guni2dRT, on the cut j = 26): they are added per rank, then
// over the ranks (mpm/RankNodeSums.h), where one process adds all particles
// in one sequence; IEEE addition is not associative. Every other difference
// follows from those last bits; the coupled step amplifies them: the solid's
// pressure from its EOS changes by K du/u (K/p ~ 1e5 for a solid in 1 atm
// gas: press_CC 4.8e-11 at t = 0), the velocities of a deck nearly at rest
// follow pressure differences (massX vel_CC 3.5e-10), and a trace material
// (volume fraction 1e-11 .. 1e-12, guni2dRT's product gas before the burn
// fills the cell) takes its temperature and specific volume from exchange
// terms of the other materials divided by its own mass (guni2dRT sp_vol_CC
// 1.1e-6, temp_CC 2.2e-7 of the max). So a fixed bound (the 1e-12)
// cannot hold without bit-equal node sums (per-patch sums in one process as
// well, and the one-process particle order inside every patch after
// migration: not done, docs/parallel.md).
//
// Session 21: that was done for the MPMICE scatters (mpmice/BandScatter.h:
// per patch in patch order at the patch-cut band, in one process too, each
// patch's particles in the scatter order (colour, block, id)), and massX and
// guni2dRT now give the 1-rank bits in every field, the stable dt and
// totalMassBurned (EXPECT_EQ, Case::bits), and with MPM's particle sums
// per patch in id order (mpm/MpmComponentOutput.cpp) the .dat sums too. The
// round-off comparison below stays as the coarser check of every case.
// What is asserted, per field: the distributed answer lies within
// kMargin = 10 times the 1-rank answer's own round-off sensitivity, measured
// in the same test on a third, whole-level run whose particles are changed by
// 4 u (perturb_particles: the backward error of the re-associated node sums),
// and since session 18 on a fourth whose 4 u carry one sign per rank of the
// distributed run (perturb_particles_by_rank; the sensitivity is the larger of
// the two: the hashed signs cancel in sums over many particles).
// Measured (2 ranks): the ratio rank difference / sensitivity <= 1.72
// (massX), 1.06 (guni2dRT), 2.44 (restart 2 -> 1); the same ratios for the
// .dat sums <= 0.57 with the floor 2 n u of sums_floor. A missing, doubled or
// misplaced rank contribution changes a field by far more than its 1-ulp
// sensitivity and fails (mutation checks in docs/parallel.md).
// advect.ups is asserted bit for bit: its block never shares a node between
// two ranks. Also asserted: every particle id once over the ranks, the
// particle count conserved every step (the burn deletes none here).
// Cases:
//   advect.ups  (decks README A12; 5^3 cells, the block [1, 1.5]^3 moving at
//               (10,10,10) m/s) in patches [5,1,1] (one cell column each),
//               20 steps: bits;
//   massX.ups   (A13; 10^3 cells, the cube [2,3]^3 burning with Simple_Burn
//               from step 1) in patches [2,2,1]: the cuts x = y = 2.5 go
//               through the cube, so the burning cells on both sides share
//               nodes and particles (the f_c gather and the burned shares
//               sent to the owning rank, mpmice/ParticleBurn.cpp); 5 steps;
//   guni2dRT.ups (A14: 2 MPM + 2 ICE materials, gimp, approach contact,
//               visco_scram, Simple_Burn) in its own patches [2,2,1], 3 steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "core/deck/DeckLoader.h"
#include "core/io/OutputFrame.h"
#include "core/io/StateArchive.h"
#include "core/parallel/Ranks.h"
#include "tests/mpi/MpmIceRoundOff.h"
#include "tests/mpi/RankCompare.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::flat;
using test::own_ids;
using test::particles_here;
using test::relative_difference;
using test::expect_within_round_off;
using test::FieldDiffs;
using test::frame_differences;
using test::kMargin;
using test::kUlp;
using test::larger_of;
using test::perturb_particles;
using test::perturb_particles_by_rank;

struct CoupledRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
};

CoupledRun start(const std::string& deck, const std::string& patches, bool whole) {
  CoupledRun r;
  r.deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/" + deck);
  if (!patches.empty()) test::deck_node(r.deck->root, {"Grid", "Level", "Box", "patches"}).text = patches;
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  if (whole) r.c->keep_whole_level();
  r.c->initialize();
  return r;
}

const std::set<std::string> kParticleLabels = {"p.velocity", "p.stress", "p.mass", "p.temperature"};
const std::set<std::string> kCellLabels = {"press_CC", "rho_CC", "vel_CC", "temp_CC", "sp_vol_CC",
                                           "SimpleBurn.onSurface", "SimpleBurn.BurningCell"};
const std::set<std::string> kSums = {"TotalMass", "KineticEnergy", "TotalMomentum", "totalMassBurned"};

OutputFrame frame_of(const MpmIceComponent& c) {
  OutputFrame f;
  std::set<std::string> labels = kParticleLabels;
  const std::set<std::string> known = c.known_labels();
  for (const std::string& l : kCellLabels)
    if (known.count(l)) labels.insert(l);
  c.fill_output(labels, f);  // gathered from every rank: particles in id order, cells in level order
  return f;
}

// The .dat sums, per label (material -1); TotalMomentum relative to
// sum m |v| over particles and cells (it is 0 to round-off in massX), taken
// from the first run's KE and mass: sum m |v| <= sqrt(2 KE M).
// The floor of the .dat sums: MPM adds its particles per rank, then the rank
// partials in rank order (docs/parallel.md "MPM on ranks"), another order
// than one process; two orders of a sum of n terms each lie within
// (n - 1) u sum |x| of the exact sum (Higham eq. (4.4)), so they differ by at
// most 2 (n - 1) u sum |x|, n = the particles plus the cells of every ICE
// material (sum |x| = the sum for the masses and energies; TotalMomentum is
// scaled by sum m |v| already).
double sums_floor(const OutputFrame& f) {
  double n = 0;
  for (const ParticleBlock& b : f.particles) n += double(b.id.size());
  for (const auto& g : f.grid_fields)
    if (g.data.label == "rho_CC") n += double(g.data.values.size());
  return 2 * n * kUlp;
}

FieldDiffs sum_differences(const MpmIceComponent& a, const MpmIceComponent& b) {
  auto ra = a.reductions(kSums);
  auto rb = b.reductions(kSums);
  const double momentum_scale = std::sqrt(2 * ra["KineticEnergy"][0] * ra["TotalMass"][0]);
  FieldDiffs out;
  for (const auto& [label, v] : ra) {
    double d = relative_difference(v, rb[label]);
    if (label == "TotalMomentum") {
      d = 0;
      for (std::size_t k = 0; k < v.size(); ++k) d = std::max(d, std::abs(v[k] - rb[label][k]) / momentum_scale);
    }
    out[{label, -1}] = d;
  }
  return out;
}

// The deck's time rule on the reference run `ref`: delt_init first, then
// timestep_multiplier * stable step (at most delt_max).
struct Stepper {
  double delt_init, mult, delt_max;
  double t = 0;
  int step = 0;
  explicit Stepper(const Deck& d) {
    const DeckNode& time = d.root.require_child("Time");
    delt_init = time.get_double("delt_init", 0.0);
    mult = time.get_double("timestep_multiplier", 1.0);
    delt_max = time.get_double("delt_max", 1e300);
  }
  double next(const MpmIceComponent& ref) const {
    return std::min(step == 0 && delt_init > 0 ? delt_init : mult * ref.stable_timestep(), delt_max);
  }
};

const SolidBurnModel* burn_of(const MpmIceComponent& c) {
  for (const IceModelP& m : c.ice().models())
    if (auto* b = dynamic_cast<const SolidBurnModel*>(m.get())) return b;
  return nullptr;
}

struct Case {
  const char* deck;
  const char* patches;  // "" = the deck's own
  int steps;
  bool bits;  // every field and .dat sum the 1-rank bits (session 21: mpmice/BandScatter.h, MPM's sums per patch)
};

class MpiMpmIce : public ::testing::TestWithParam<Case> {};

TEST_P(MpiMpmIce, RanksGiveTheOneRankAnswerToRoundOff) {
  const Case cs = GetParam();
  CoupledRun whole = start(cs.deck, cs.patches, true);
  CoupledRun ranks = start(cs.deck, cs.patches, false);
  CoupledRun pert = start(cs.deck, cs.patches, true);
  perturb_particles(*pert.c);
  CoupledRun pert2 = start(cs.deck, cs.patches, true);  // the rank-coherent sample
  perturb_particles_by_rank(*pert2.c, ranks.c->mpm().layout().owner);
  EXPECT_EQ(ranks.c->mpm().layout().distributed, world_ranks().size > 1);
  EXPECT_EQ(ranks.c->ice().layout().owner, ranks.c->mpm().layout().owner) << "ICE takes MPM's patch owners";
  const std::size_t total = particles_here(whole.c->mpm().materials());
  const std::set<long long> start_ids = own_ids(ranks.c->mpm().materials());
  std::set<long long> ever_left;
  Stepper st(*whole.deck);
  double worst_dt = 0, pert_dt = 0, worst_burned = 0, pert_burned = 0, burned = 0;
  int first_diff_step = -1;  // the diagnostic below
  double first_diff = 0;
  std::string first_diff_field;
  for (int n = 0; n < cs.steps; ++n) {
    const double dt = st.next(*whole.c);
    worst_dt = std::max(worst_dt, std::abs(ranks.c->stable_timestep() / whole.c->stable_timestep() - 1));
    pert_dt = std::max({pert_dt, std::abs(pert.c->stable_timestep() / whole.c->stable_timestep() - 1),
                        std::abs(pert2.c->stable_timestep() / whole.c->stable_timestep() - 1)});
    ++st.step;
    whole.c->advance(st.t, dt, st.step);
    ranks.c->advance(st.t, dt, st.step);
    pert.c->advance(st.t, dt, st.step);
    pert2.c->advance(st.t, dt, st.step);
    st.t += dt;
    const std::vector<double> counts = all_gather({double(particles_here(ranks.c->mpm().materials()))});
    double sum = 0;
    for (double x : counts) sum += x;
    EXPECT_EQ(sum, double(total)) << "step " << st.step;
    const std::set<long long> now = own_ids(ranks.c->mpm().materials());
    for (long long id : start_ids)
      if (!now.count(id)) ever_left.insert(id);
    // Diagnostic (issue 7): the first step and field where 1 and N ranks
    // differ (every saved particle and cell field and the .dat sums).
    if (first_diff_step < 0) {
      FieldDiffs d = frame_differences(frame_of(*whole.c), frame_of(*ranks.c));
      for (const auto& kv : sum_differences(*whole.c, *ranks.c)) d.insert(kv);
      for (const auto& [key, v] : d)
        if (v > first_diff) first_diff = v, first_diff_field = key.first + " material " + std::to_string(key.second);
      if (first_diff > 0) first_diff_step = st.step;
    }
    if (const SolidBurnModel* b = burn_of(*whole.c)) {
      const double w = whole.c->reductions({"totalMassBurned"})["totalMassBurned"][0];
      const double r = ranks.c->reductions({"totalMassBurned"})["totalMassBurned"][0];
      const double q = pert.c->reductions({"totalMassBurned"})["totalMassBurned"][0];
      const double q2 = pert2.c->reductions({"totalMassBurned"})["totalMassBurned"][0];
      worst_burned = std::max(worst_burned, std::abs(r - w) / std::max(std::abs(w), 1e-300));
      pert_burned = std::max({pert_burned, std::abs(q - w) / std::max(std::abs(w), 1e-300),
                              std::abs(q2 - w) / std::max(std::abs(w), 1e-300)});
      burned += b->mass_burned_last_step();
    }
  }
  EXPECT_LE(worst_dt, kMargin * pert_dt + 8 * kUlp) << "stable dt (round-off sensitivity " << pert_dt << ")";
  EXPECT_LE(worst_burned, kMargin * pert_burned + 8 * kUlp)
      << "totalMassBurned after a step (round-off sensitivity " << pert_burned << ")";
  double migrated = 0;
  for (double l : all_gather({double(ever_left.size())})) migrated += l;
  const OutputFrame ref = frame_of(*whole.c);
  const double fields =
      expect_within_round_off(frame_differences(ref, frame_of(*ranks.c)),
                              larger_of(frame_differences(ref, frame_of(*pert.c)), frame_differences(ref, frame_of(*pert2.c))),
                              cs.deck);
  const double sums = expect_within_round_off(sum_differences(*whole.c, *ranks.c),
                                              larger_of(sum_differences(*whole.c, *pert.c), sum_differences(*whole.c, *pert2.c)),
                                              cs.deck, sums_floor(ref));
  if (cs.bits) {  // every saved field, the stable dt and totalMassBurned after every step: the 1-rank bits
    for (const auto& [key, d] : frame_differences(ref, frame_of(*ranks.c)))
      EXPECT_EQ(d, 0.0) << key.first << " material " << key.second << ": the 1-rank bits";
    EXPECT_EQ(worst_dt, 0.0) << "stable dt";
    EXPECT_EQ(worst_burned, 0.0) << "totalMassBurned";
  }
  // The .dat sums (session 21: MPM's particle sums per patch in id order,
  // then in patch order, mpm/MpmComponentOutput.cpp; ICE's per patch): the 1-rank bits.
  if (cs.bits)
    for (const auto& [key, d] : sum_differences(*whole.c, *ranks.c)) EXPECT_EQ(d, 0.0) << key.first;
  if (world_ranks().is_root())
    std::printf("[ mpi-mpmice ] %s %s %d steps on %d rank(s): fields %.3g, sums %.3g (worst difference / round-off sensitivity), totalMassBurned %.3g "
                "(1-ulp-perturbed %.3g; burned %.6g kg), %g particles changed rank\n",
                cs.deck, cs.patches, cs.steps, world_ranks().size, fields, sums, worst_burned, pert_burned, burned, migrated);
  if (world_ranks().is_root()) {
    if (first_diff_step < 0) std::printf("[ mpi-mpmice ] %s: 1 and %d rank(s) the same bits after every step\n", cs.deck, world_ranks().size);
    else
      std::printf("[ mpi-mpmice ] %s: 1 and %d rank(s) first differ after step %d, largest in %s (%.3g of its max)\n", cs.deck,
                  world_ranks().size, first_diff_step, first_diff_field.c_str(), first_diff);
  }
  if (world_ranks().is_root() && ranks.c->mpm().layout().distributed) {
    std::printf("[ mpi-mpmice ] patch owners:");
    for (int o : ranks.c->mpm().layout().owner) std::printf(" %d", o);
    std::printf("\n");
  }
  if (burn_of(*whole.c)) EXPECT_GT(burned, 0.0) << "the deck burns";
}

INSTANTIATE_TEST_SUITE_P(Decks, MpiMpmIce,
                         ::testing::Values(Case{"advect.ups", "[5,1,1]", 20, true}, Case{"massX.ups", "[2,2,1]", 5, true},
                                           Case{"guni2dRT.ups", "", 3, true}));

// Checkpoints across rank counts: the archive of the N-rank run restored into
// a whole-level component (N -> 1) and the 1-rank archive into a distributed
// one (1 -> N) continue as the uninterrupted 1-rank run, to round-off.
TEST(MpiMpmIce, CheckpointsRestartAcrossRankCounts) {
  const char* deck = "massX.ups";
  const char* patches = "[2,2,1]";
  CoupledRun one = start(deck, patches, true);
  CoupledRun many = start(deck, patches, false);
  CoupledRun pert = start(deck, patches, true);  // the round-off sensitivity of `one`
  perturb_particles(*pert.c);
  Stepper st(*one.deck);
  auto step = [&](std::initializer_list<CoupledRun*> runs) {
    const double dt = st.next(*one.c);
    ++st.step;
    for (CoupledRun* r : runs) r->c->advance(st.t, dt, st.step);
    st.t += dt;
  };
  for (int n = 0; n < 3; ++n) step({&one, &many, &pert});
  StateArchive a1, an;
  one.c->save_state(a1);
  many.c->save_state(an);
  CoupledRun to_many = start(deck, patches, false);
  CoupledRun to_one = start(deck, patches, true);
  to_many.c->load_state(a1);
  to_one.c->load_state(an);
  for (int n = 0; n < 3; ++n) step({&one, &to_many, &to_one, &pert});
  const OutputFrame f = frame_of(*one.c);
  const FieldDiffs sens = frame_differences(f, frame_of(*pert.c));
  const FieldDiffs sums_sens = sum_differences(*one.c, *pert.c);
  const double d_many = expect_within_round_off(frame_differences(f, frame_of(*to_many.c)), sens, "restart 1 -> N");
  const double d_one = expect_within_round_off(frame_differences(f, frame_of(*to_one.c)), sens, "restart N -> 1");
  expect_within_round_off(sum_differences(*one.c, *to_many.c), sums_sens, "restart 1 -> N sums", sums_floor(f));
  expect_within_round_off(sum_differences(*one.c, *to_one.c), sums_sens, "restart N -> 1 sums", sums_floor(f));
  // Session 21: the restored runs continue with the 1-rank bits (measured 0 on 2 and 4 ranks).
  for (const auto& [key, d] : frame_differences(f, frame_of(*to_many.c))) EXPECT_EQ(d, 0.0) << "restart 1 -> N " << key.first;
  for (const auto& [key, d] : frame_differences(f, frame_of(*to_one.c))) EXPECT_EQ(d, 0.0) << "restart N -> 1 " << key.first;
  double sums_many = 0, sums_one = 0;
  for (const auto& [key, d] : sum_differences(*one.c, *to_many.c)) sums_many = std::max(sums_many, d);
  for (const auto& [key, d] : sum_differences(*one.c, *to_one.c)) sums_one = std::max(sums_one, d);
  EXPECT_EQ(sums_many, 0.0);
  EXPECT_EQ(sums_one, 0.0);
  if (world_ranks().is_root())
    std::printf("[ mpi-mpmice ] restart 1 -> %d ranks: %.3g, %d -> 1: %.3g (sums %.3g, %.3g)\n", world_ranks().size, d_many,
                world_ranks().size, d_one, sums_many, sums_one);
}

}  // namespace
}  // namespace tephra
