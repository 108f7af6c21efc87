// MPMICE sums do not depend on the particles' storage order when the level
// has several patches (issue 7, session 21; docs/parallel.md "Session 21").
//
// Why bits are expected: every particle scatter of the coupled step (MPM's
// P2G, internal force and MUSL velocity; MPMICE's T_g, pressure force, burn
// node and cell sums, solid mass projections: mpmice/BandScatter.h) visits
// the particles in the scatter order (colour, block, id), which depends on
// positions and ids only, and adds the patches' partials at the patch-cut
// band in patch order; MPM's .dat sums take each patch's particles in id
// order (mpm/MpmComponentOutput.cpp). This is the one-process identity that
// makes 1 and N MPI ranks agree bit for bit: on ranks a particle that
// changed rank sits at another storage position than in one process.
// With storage-order sums (before session 21) reversing the storage changes
// the last bits, and the decks amplify them (tests/mpi/test_mpi_mpmice.cpp:
// 1e-10 .. 1e-6 of a field's max within a few steps), so this fails then.
//
// Cases: MPMICE/massX.ups (A13, Simple_Burn from step 1) in patches [2,2,1]
// (the cuts through the burning cube), 5 steps; MPMICE/guni2dRT.ups in its
// own [2,2,1], 3 steps. Run A as seeded, run B with every material's
// particle columns reversed after initialize(); asserted: every saved
// particle field (matched by id), every cell field, the .dat sums EXPECT_EQ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>

#include "core/deck/DeckLoader.h"
#include "core/io/OutputFrame.h"
#include "mpm/ParticleReorder.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

struct Result {
  OutputFrame frame;
  std::map<std::string, std::vector<double>> sums;
};

Result run(const std::string& deck_name, const std::string& patches, int steps, bool reversed) {
  auto deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/" + deck_name);
  if (!patches.empty()) test::deck_node(deck->root, {"Grid", "Level", "Box", "patches"}).text = patches;
  deck->root.finalize_parents();
  auto c = make_mpmice_component(*deck);
  c->initialize();
  if (reversed)
    for (MpmMaterial& m : c->mpm().materials()) {
      std::vector<std::uint32_t> order(m.particles.size());
      std::iota(order.rbegin(), order.rend(), 0u);  // order[j] = n - 1 - j
      std::vector<Mat3> scratch;
      permute_particles(m.particles, order, scratch);
    }
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
  c->fill_output(c->known_labels(), r.frame);
  r.sums = c->reductions({"TotalMass", "KineticEnergy", "TotalMomentum", "totalMassBurned"});
  return r;
}

struct Case {
  const char* deck;
  const char* patches;
  int steps;
};

class MpmIceStorageOrder : public ::testing::TestWithParam<Case> {};

TEST_P(MpmIceStorageOrder, ReversedParticleStorageGivesTheSameBits) {
  const Case cs = GetParam();
  const Result a = run(cs.deck, cs.patches, cs.steps, false);
  const Result b = run(cs.deck, cs.patches, cs.steps, true);
  ASSERT_EQ(a.frame.particles.size(), b.frame.particles.size());
  std::size_t compared = 0;
  for (std::size_t k = 0; k < a.frame.particles.size(); ++k) {
    const ParticleBlock& x = a.frame.particles[k];
    const ParticleBlock& y = b.frame.particles[k];
    ASSERT_EQ(x.id.size(), y.id.size());
    std::map<long long, std::size_t> at;  // id -> index in y
    for (std::size_t i = 0; i < y.id.size(); ++i) at[y.id[i]] = i;
    ASSERT_EQ(at.size(), x.id.size()) << "the same ids";
    ASSERT_EQ(x.fields.size(), y.fields.size());
    for (std::size_t i = 0; i < x.id.size(); ++i) {
      ASSERT_TRUE(at.count(x.id[i]));
      const std::size_t j = at[x.id[i]];
      EXPECT_TRUE(x.position[i] == y.position[j]) << "p.x of particle " << x.id[i];
      for (std::size_t f = 0; f < x.fields.size(); ++f) {
        const std::size_t w = std::size_t(x.fields[f].components);
        for (std::size_t c = 0; c < w; ++c)
          EXPECT_EQ(x.fields[f].values[i * w + c], y.fields[f].values[j * w + c])
              << x.fields[f].label << " of particle " << x.id[i] << " material " << x.material;
      }
    }
    compared += x.fields.size();
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

INSTANTIATE_TEST_SUITE_P(Decks, MpmIceStorageOrder,
                         ::testing::Values(Case{"massX.ups", "[2,2,1]", 5}, Case{"guni2dRT.ups", "", 3}));

}  // namespace
}  // namespace tephra
