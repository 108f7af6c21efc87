// MPMICE particle migration on MPI ranks (issue 7): MPMICE/advect.ups
// (decks README A12: 5^3 cells of 0.5 m, the steel block [1, 1.5]^3 in air)
// cut into patches [5,1,1] (one cell column each), with the block's velocity
// raised from (10,10,10) to (kVx, 0, 0) m/s so that within the run it moves
// 0.45 m: the particles (seeded at x = 1.125, 1.375) all cross the cut
// x = 1.5, where the load balancer puts the rank cut under -np 2 (the run
// prints the owners). The whole level in this
// process (keep_whole_level: the 1-rank run) against the patches spread over
// the ranks, stepped with the same dt.
//
// Asserted: every particle on exactly one rank after every step (the counts
// add up to the total) and, at the end, every id of the 1-rank run exactly
// once (the gathered blocks are in id order and equal); under -np 2 the
// particles change rank (all of them: the block crosses the cut whole);
// every particle field, cell field and the stable time step within the
// round-off rule of tests/mpi/MpmIceRoundOff.h (kMargin times the 1-rank
// answer's sensitivity to a 4 u change of every particle, from a third run)
// and TotalMass within 2 n u (the same terms summed in another order). While the block is inside one rank's patches its nodes
// are reached by that rank alone (the one-process bits); as it crosses, the
// nodes around the cut get both ranks' partial sums (round-off).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/deck/DeckLoader.h"
#include "core/io/OutputFrame.h"
#include "core/parallel/Ranks.h"
#include "tests/mpi/MpmIceRoundOff.h"
#include "tests/mpi/RankCompare.h"
#include "core/grid/Loop.h"
#include "ice/IceFields.h"
#include "mpmice/MpmIceComponent.h"
#include "mpmice/SolidBurn.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::flat;
using test::own_ids;
using test::particles_here;
using test::relative_difference;

constexpr double kVx = 40.0;  // m/s

struct CoupledRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
};

CoupledRun start(bool whole) {
  CoupledRun r;
  r.deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/advect.ups");
  test::deck_node(r.deck->root, {"Grid", "Level", "Box", "patches"}).text = "[5,1,1]";
  test::deck_node(r.deck->root, {"MaterialProperties", "MPM", "material", "geom_object", "velocity"}).text =
      "[" + std::to_string(kVx) + ",0,0]";
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  if (whole) r.c->keep_whole_level();
  r.c->initialize();
  return r;
}

TEST(MpiMpmIceMigration, BlockCrossingTheRankCutKeepsEveryParticleOnce) {
  CoupledRun whole = start(true);
  CoupledRun ranks = start(false);
  CoupledRun pert = start(true);  // the round-off sensitivity (tests/mpi/MpmIceRoundOff.h)
  test::perturb_particles(*pert.c);
  EXPECT_EQ(ranks.c->mpm().layout().distributed, world_ranks().size > 1);
  const std::size_t total = particles_here(whole.c->mpm().materials());
  const std::set<long long> start_ids = own_ids(ranks.c->mpm().materials());
  std::set<long long> ever_left;
  const DeckNode& time = whole.deck->root.require_child("Time");
  const double mult = time.get_double("timestep_multiplier"), delt_init = time.get_double("delt_init", 0.0);
  double t = 0, worst_dt = 0, pert_dt = 0;
  int step = 0;
  const double t_end = 0.45 / kVx;  // 0.45 m: every particle (x0 = 1.125, 1.375) passes x = 1.5, none x = 2
  while (t < t_end) {
    const double dt = step == 0 && delt_init > 0 ? delt_init : mult * whole.c->stable_timestep();
    worst_dt = std::max(worst_dt, std::abs(ranks.c->stable_timestep() / whole.c->stable_timestep() - 1));
    pert_dt = std::max(pert_dt, std::abs(pert.c->stable_timestep() / whole.c->stable_timestep() - 1));
    ++step;
    whole.c->advance(t, dt, step);
    ranks.c->advance(t, dt, step);
    pert.c->advance(t, dt, step);
    t += dt;
    double sum = 0;
    for (double n : all_gather(std::vector<double>{double(particles_here(ranks.c->mpm().materials()))})) sum += n;
    EXPECT_EQ(sum, double(total)) << "step " << step;
    const std::set<long long> now = own_ids(ranks.c->mpm().materials());
    for (long long id : start_ids)
      if (!now.count(id)) ever_left.insert(id);
  }
  EXPECT_LE(worst_dt, test::kMargin * pert_dt + 8 * test::kUlp) << "stable dt (sensitivity " << pert_dt << ")";
  double migrated = 0;
  for (double l : all_gather(std::vector<double>{double(ever_left.size())})) migrated += l;
  OutputFrame a, b, c;
  const std::set<std::string> labels = {"p.velocity", "p.stress", "p.mass", "p.temperature", "press_CC",
                                        "rho_CC",     "vel_CC",   "temp_CC", "sp_vol_CC"};
  whole.c->fill_output(labels, a);
  ranks.c->fill_output(labels, b);
  pert.c->fill_output(labels, c);
  for (const ParticleBlock& x : a.particles) EXPECT_EQ(x.id.size(), total);
  // Every field (and p.x) within kMargin x its 4 u sensitivity + 8 u, as
  // test_mpi_mpmice.cpp; frame_differences also checks every id once.
  const double worst = test::expect_within_round_off(test::frame_differences(a, b), test::frame_differences(a, c),
                                                     "migration");
  for (const auto& [label, v] : whole.c->reductions({"TotalMass"})) {
    // The particle masses are not changed by the split: TotalMass is a sum of
    // the same n terms in another order, within 2 (n - 1) u of each other (Higham eq. (4.4)).
    const double d = relative_difference(v, ranks.c->reductions({label})[label]);
    EXPECT_LE(d, 2 * double(total) * test::kUlp) << label;
  }
  if (world_ranks().size > 1) EXPECT_EQ(migrated, double(total)) << "the whole block crosses the rank cut";
  if (world_ranks().is_root()) {
    std::printf("[ mpi-mpmice-migration ] advect.ups v = (%g,0,0), %d steps to t = %.4g on %d rank(s): worst ratio to the round-off sensitivity %.3g, "
                "%g of %zu particles changed rank; owners:",
                kVx, step, t, world_ranks().size, worst, migrated, total);
    for (int o : ranks.c->mpm().layout().owner) std::printf(" %d", o);
    std::printf("\n");
  }
}

// DDT1's crack-history lookup on ranks (<useCrackModel>: the largest crackRad
// of the reactant's particles in each cell, SolidBurnSupport::
// particle_history_max, read by DDT1 at the cell itself only). On ranks each
// rank looks at its own particles and fills its own cells; that is complete
// because a particle lives on the rank owning the patch of its cell
// (mpm/MpmRanks.cpp, migrate_particles after every step). Checked on the
// block above at t = 0.2 m / kVx, when it straddles the cut x = 1.5 (the
// particles seeded at x = 1.375 have crossed it, those at 1.125 have not):
// advect's comp_neo_hook_plastic history column plasticStrain is set to
// 1 + 1e-3 id on every particle of both runs, and every own cell of every rank
// must hold exactly the whole run's maximum of that cell (a max is exact: no
// round-off), and the cells holding particles must be on both ranks under -np 2.
TEST(MpiMpmIceMigration, CrackHistoryLookupGivesTheOneRankCellMaxima) {
  CoupledRun whole = start(true);
  CoupledRun ranks = start(false);
  const DeckNode& time = whole.deck->root.require_child("Time");
  const double mult = time.get_double("timestep_multiplier"), delt_init = time.get_double("delt_init", 0.0);
  double t = 0;
  int step = 0;
  while (t < 0.2 / kVx) {
    const double dt = step == 0 && delt_init > 0 ? delt_init : mult * whole.c->stable_timestep();
    ++step;
    whole.c->advance(t, dt, step);
    ranks.c->advance(t, dt, step);
    t += dt;
  }
  auto lookup = [](CoupledRun& r) {
    MpmMaterial& m = r.c->mpm().materials()[0];
    const std::vector<HistoryVariable> h = m.model->history();
    std::size_t k = h.size();
    for (std::size_t i = 0; i < h.size(); ++i)
      if (h[i].name == "plasticStrain") k = i;
    EXPECT_LT(k, h.size()) << "advect's solid model has no plasticStrain";
    for (std::size_t p = 0; p < m.particles.size(); ++p) m.particles.history[k][p] = 1.0 + 1e-3 * double(m.particles.id[p]);
    CellScalars out(r.c->ice().grid(), 0);
    EXPECT_TRUE(r.c->burn_support().particle_history_max(0, "plasticStrain", out));
    return out;
  };
  const CellScalars a = lookup(whole), b = lookup(ranks);
  const Grid& gw = whole.c->ice().grid();
  const Grid& gr = ranks.c->ice().grid();
  int mismatched = 0, cells_with_particles = 0;
  for (std::size_t pi = 0; pi < gr.patches.size(); ++pi) {
    std::size_t wi = gw.patches.size();
    for (std::size_t q = 0; q < gw.patches.size(); ++q)
      if (gw.patches[q].id == gr.patches[pi].id) wi = q;
    ASSERT_LT(wi, gw.patches.size());
    for_each_cell_serial(gr.patches[pi].cells(), [&](int i, int j, int k) {
      if (b[pi](i, j, k) != a[wi](i, j, k)) ++mismatched;
      if (b[pi](i, j, k) > 0) ++cells_with_particles;
    });
  }
  EXPECT_EQ(mismatched, 0) << "own cells whose maximum differs from the 1-rank one";
  const std::vector<double> per_rank = all_gather(std::vector<double>{double(cells_with_particles)});
  int whole_cells = 0;
  for (std::size_t q = 0; q < gw.patches.size(); ++q)
    for_each_cell_serial(gw.patches[q].cells(), [&](int i, int j, int k) { whole_cells += a[q](i, j, k) > 0; });
  double sum = 0;
  for (double n : per_rank) sum += n;
  EXPECT_EQ(sum, double(whole_cells)) << "every cell with particles on exactly one rank";
  // The block straddles a rank cut: at least two ranks hold cells with
  // particles (on 2 ranks both; on 4 ranks the block need not reach every rank).
  if (world_ranks().size > 1) {
    int ranks_with_cells = 0;
    for (double n : per_rank) ranks_with_cells += n > 0;
    EXPECT_GE(ranks_with_cells, 2) << "the block straddles the rank cut";
  }
  if (world_ranks().is_root()) {
    std::printf("[ mpi-mpmice-migration ] crack-history lookup at t = %.4g: %d cells with particles, per rank:",
                t, whole_cells);
    for (double n : per_rank) std::printf(" %g", n);
    std::printf("\n");
  }
}

}  // namespace
}  // namespace tephra
