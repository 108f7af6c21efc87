// MPMICE with 1 and 2 OpenMP threads gives the same bits (issue 7,
// "Deterministic answers ... with 1 or 2 threads"; docs/parallel.md).
//
// Why bits are expected: the MPM scatters are coloured block scatters whose
// per-node order does not depend on the thread count (docs/performance.md,
// tests/unit/test_mpm_threads.cpp), the ICE cell loops write each cell from
// one thread, and the MPMICE transfers (node <-> cell averages, burn shares,
// solid mass fluxes) loop serially or per cell. Any reduction that let the
// thread count decide an association order would show here as a last-bit
// difference (the decks amplify a 1-ulp change to 1e-10 .. 1e-6 of a
// field's max within a few steps, tests/mpi/test_mpi_mpmice.cpp).
// Cases: MPMICE/massX.ups (A13, Simple_Burn from step 1) 5 steps;
// MPMICE/guni2dRT.ups (2 MPM + 2 ICE materials, approach contact,
// visco_scram, Simple_Burn) 3 steps. Asserted: every saved particle field,
// every cell field of every material, the .dat sums EXPECT_EQ.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "core/io/OutputFrame.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/TestPaths.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

struct Result {
  OutputFrame frame;
  std::map<std::string, std::vector<double>> sums;
};

// `steps` steps of the deck with `threads` threads, dt from the deck's rule
// (delt_init, then timestep_multiplier x the stable step, at most delt_max).
Result run(const std::string& deck_name, int steps, int threads) {
  ThreadCountScope t(threads);
  auto deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/" + deck_name);
  auto c = make_mpmice_component(*deck);
  c->initialize();
  const DeckNode& time = deck->root.require_child("Time");
  const double delt_init = time.get_double("delt_init", 0.0);
  const double mult = time.get_double("timestep_multiplier", 1.0);
  const double delt_max = time.get_double("delt_max", 1e300);
  double tm = 0;
  for (int n = 1; n <= steps; ++n) {
    const double dt = std::min(n == 1 && delt_init > 0 ? delt_init : mult * c->stable_timestep(), delt_max);
    c->advance(tm, dt, n);
    tm += dt;
  }
  Result r;
  const std::set<std::string> labels = c->known_labels();
  c->fill_output(labels, r.frame);
  r.sums = c->reductions({"TotalMass", "KineticEnergy", "TotalMomentum", "totalMassBurned"});
  return r;
}

class MpmIceThreads : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(MpmIceThreads, TwoThreadsGiveTheOneThreadBits) {
  const auto [deck, steps] = GetParam();
  const Result a = run(deck, steps, 1);
  const Result b = run(deck, steps, 2);
  ASSERT_EQ(a.frame.particles.size(), b.frame.particles.size());
  std::size_t compared = 0;
  for (std::size_t k = 0; k < a.frame.particles.size(); ++k) {
    const ParticleBlock& x = a.frame.particles[k];
    const ParticleBlock& y = b.frame.particles[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_TRUE(x.position == y.position) << "p.x material " << x.material;
    ASSERT_EQ(x.fields.size(), y.fields.size());
    for (std::size_t f = 0; f < x.fields.size(); ++f, ++compared)
      EXPECT_TRUE(x.fields[f].values == y.fields[f].values) << x.fields[f].label << " material " << x.material;
  }
  ASSERT_EQ(a.frame.grid_fields.size(), b.frame.grid_fields.size());
  for (std::size_t k = 0; k < a.frame.grid_fields.size(); ++k, ++compared) {
    const FieldArray& x = a.frame.grid_fields[k].data;
    const FieldArray& y = b.frame.grid_fields[k].data;
    EXPECT_EQ(x.label, y.label);
    EXPECT_TRUE(x.values == y.values) << x.label << " material " << x.material;
  }
  EXPECT_GT(compared, 20u) << "the frame holds the deck's fields";
  for (const auto& [label, v] : a.sums) EXPECT_TRUE(v == b.sums.at(label)) << label;
}

INSTANTIATE_TEST_SUITE_P(Decks, MpmIceThreads,
                         ::testing::Values(std::make_pair("massX.ups", 5), std::make_pair("guni2dRT.ups", 3)));

}  // namespace
}  // namespace tephra
