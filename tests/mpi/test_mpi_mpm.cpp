// MPM on MPI ranks (issue 7): the colliding-disks deck (inputs/mpm/disks.ups,
// decks README A1) cut into patches, run with the whole level in this process
// (keep_whole_level: the 1-rank run) and with its patches spread over the
// world's ranks (mpm/MpmRanks.cpp), stepped with the same dt.
//
// Expected: the same bits for the particles. Every node sum of P2G, the
// internal force and the MUSL velocity is formed per patch, in the scatter
// order (colour, block, particle id), and the patches' partials are added in
// ascending patch id, in one process and on ranks alike (mpm/PatchBand.h). So
// positions, velocities, F and stress are asserted EQUAL (difference 0) and
// the stable dt too, for the cases marked exact. Not exact (bound
// max |a - b| <= 1e-12 max |a|): friction contact, whose mass gradients
// (normals) and contact positions are still summed by rank (mpm/RankNodeSums.h).
// The .dat sums (session 21): one partial per patch, its particles in
// ascending id, added in ascending patch id (mpm/MpmComponentOutput.cpp),
// in one process and on ranks alike: EQUAL for the exact cases; 1e-12
// relative otherwise (TotalMomentum, 0 to round-off, relative to sum m |v|).
// Also asserted: particles really cross the patch cut and change rank during
// the run (under -np 2; some come back before the end), every particle id exists exactly once over the
// ranks after every step, the total count is constant.
// The deck conducts heat (k = 1) at a uniform temperature, so the conduction
// decision is taken over the ranks and the step is skipped.
// Cases: one material (null contact), linear and gimp, patches [2,1,1]
// (cut x = 0.5: disk 1 reaches it at t ~ 0.5 and crosses it) and [2,2,1]; two
// materials (one disk each) with single_velocity and friction contact
// (multi-material node fields, contact normals and positions summed over the ranks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/deck/DeckLoader.h"
#include "core/io/OutputFrame.h"
#include "core/parallel/Ranks.h"
#include "tests/mpi/RankCompare.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::flat;
using test::own_ids;
using test::particles_here;
using test::relative_difference;

DeckNode& child(DeckNode& n, const std::string& name) {
  for (DeckNode& c : n.children)
    if (c.name == name) return c;
  throw std::runtime_error("no <" + name + ">");
}

// disks.ups with the given patches and interpolator; with `contact` the second
// disk becomes material 1 (the same properties) and the contact block is replaced.
std::unique_ptr<Deck> disks_deck(const std::string& patches, const std::string& interpolator,
                                 const std::string& contact = "") {
  auto deck = load_deck(test::source_dir() + "/inputs/mpm/disks.ups");
  DeckNode& root = deck->root;
  DeckNode& box = child(child(child(root, "Grid"), "Level"), "Box");
  child(box, "patches").text = patches;
  if (interpolator != "linear") child(box, "extraCells").text = "[1,1,1]";  // gimp reaches one node layer out
  child(child(root, "MPM"), "interpolator").text = interpolator;
  if (!contact.empty()) {
    DeckNode& mpm = child(child(root, "MaterialProperties"), "MPM");
    DeckNode& m0 = child(mpm, "material");
    DeckNode m1 = m0;
    // material 0 keeps geom_object gp1, material 1 gets gp2.
    auto drop = [](DeckNode& m, int which) {
      int seen = 0;
      for (auto it = m.children.begin(); it != m.children.end();)
        if (it->name == "geom_object" && seen++ == which) it = m.children.erase(it);
        else ++it;
    };
    drop(m0, 1);
    drop(m1, 0);
    auto pos = std::find_if(mpm.children.begin(), mpm.children.end(), [](const DeckNode& c) { return c.name == "material"; });
    mpm.children.insert(pos + 1, m1);
    DeckNode& c = child(mpm, "contact");
    child(c, "type").text = contact;
    child(c, "materials").text = "[0,1]";
    if (contact == "friction") {
      DeckNode mu;
      mu.name = "mu";
      mu.text = "0.3";
      c.children.push_back(mu);
    }
  }
  root.finalize_parents();
  return deck;
}

struct Run {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmComponent> mpm;
};

Run start(const std::string& patches, const std::string& interpolator, bool whole, const std::string& contact) {
  Run r;
  r.deck = disks_deck(patches, interpolator, contact);
  r.mpm = make_mpm_component(*r.deck);
  if (whole) r.mpm->keep_whole_level();
  r.mpm->initialize();
  return r;
}

const std::set<std::string> kParticleLabels = {"p.velocity", "p.stress", "p.deformationMeasure"};
const std::set<std::string> kSums = {"KineticEnergy", "StrainEnergy", "TotalMass", "TotalMomentum",
                                     "CenterOfMassPosition"};

struct Worst {
  double particles = 0, sums = 0, dt = 0;
};

// Steps both runs to the deck's end with the whole run's dt; returns the worst
// relative differences of the particle fields, the .dat sums (at the end) and the stable dt (every step).
Worst run_and_compare(const std::string& patches, const std::string& interpolator, const std::string& contact,
                       int* migrated_out) {
  Run whole = start(patches, interpolator, true, contact);
  Run ranks = start(patches, interpolator, false, contact);
  EXPECT_EQ(ranks.mpm->layout().distributed, world_ranks().size > 1);
  const DeckNode& time = whole.deck->root.require_child("Time");
  const double multiplier = time.get_double("timestep_multiplier"), delt_max = time.get_double("delt_max");
  // To t = 2 of the deck's 3 s: the disks cross the cuts (t ~ 0.5), collide (t ~ 1.1) and rebound.
  const double max_time = std::min(2.0, time.get_double("maxTime"));
  std::size_t total = 0;
  for (const MpmMaterial& m : whole.mpm->materials()) total += m.particles.size();
  const std::set<long long> start_ids = own_ids(ranks.mpm->materials());
  std::set<long long> ever_left;  // ids that were on this rank at the start and left it at some step
  // TotalMomentum is 0 to round-off (point-symmetric disks): its scale is sum m |v| = m0 |v0|.
  const double momentum_scale = whole.mpm->reductions({"TotalMass"})["TotalMass"][0] * std::sqrt(0.02);
  double t = 0;
  int step = 0;
  double worst_dt = 0;
  while (t < max_time) {
    const double dt = std::min(multiplier * whole.mpm->stable_timestep(), delt_max);
    worst_dt = std::max(worst_dt, std::abs(ranks.mpm->stable_timestep() - whole.mpm->stable_timestep()) /
                                      whole.mpm->stable_timestep());
    whole.mpm->advance(t, dt, ++step);
    ranks.mpm->advance(t, dt, step);
    t += dt;
    // Every particle on exactly one rank: the counts add up to the total.
    std::size_t here = 0;
    for (const MpmMaterial& m : ranks.mpm->materials()) here += m.particles.size();
    const std::vector<double> counts = all_gather({double(here)});
    double sum = 0;
    for (double c : counts) sum += c;
    EXPECT_EQ(sum, double(total)) << "step " << step;
    const std::set<long long> now = own_ids(ranks.mpm->materials());
    for (long long id : start_ids)
      if (!now.count(id)) ever_left.insert(id);
  }
  EXPECT_GT(step, 100);
  EXPECT_LE(worst_dt, 1e-12) << "stable dt of the distributed run";
  Worst w;
  w.dt = worst_dt;
  // Particles that left this rank's patches during the run, over all ranks.
  const std::vector<double> lefts = all_gather({double(ever_left.size())});
  int migrated = 0;
  for (double l : lefts) migrated += int(l);
  *migrated_out = migrated;

  OutputFrame a, b;
  std::set<std::string> labels = kParticleLabels;
  whole.mpm->fill_output(labels, a);
  ranks.mpm->fill_output(labels, b);  // gathered from every rank, ascending id
  double& worst = w.particles;
  EXPECT_EQ(a.particles.size(), b.particles.size());
  for (std::size_t k = 0; k < std::min(a.particles.size(), b.particles.size()); ++k) {
    const ParticleBlock& x = a.particles[k];
    const ParticleBlock& y = b.particles[k];
    EXPECT_EQ(x.id, y.id) << "every id exactly once, material " << x.material;
    worst = std::max(worst, relative_difference(flat(x.position), flat(y.position)));
    EXPECT_EQ(x.fields.size(), y.fields.size());
    for (std::size_t f = 0; f < std::min(x.fields.size(), y.fields.size()); ++f) {
      const double d = relative_difference(x.fields[f].values, y.fields[f].values);
      EXPECT_LE(d, 1e-12) << x.fields[f].label;
      worst = std::max(worst, d);
    }
  }
  auto ra = whole.mpm->reductions(kSums);
  auto rb = ranks.mpm->reductions(kSums);
  for (const auto& [label, values] : ra) {
    double d = relative_difference(values, rb[label]);
    if (label == "TotalMomentum") {
      d = 0;
      for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(values[k] - rb[label][k]) / momentum_scale);
    }
    EXPECT_LE(d, 1e-12) << label;
    w.sums = std::max(w.sums, d);
  }
  return w;
}

struct Case {
  const char* patches;
  const char* interpolator;
  const char* contact;
  bool exact;  // the particles' bits equal (every scatter the case uses is band-summed)
};

class MpiMpm : public ::testing::TestWithParam<Case> {};

TEST_P(MpiMpm, RanksGiveTheOneRankAnswer) {
  const Case c = GetParam();
  int migrated = 0;
  const Worst w = run_and_compare(c.patches, c.interpolator, c.contact, &migrated);
  const double worst = std::max(w.particles, w.sums);
  EXPECT_LE(worst, 1e-12);
  if (c.exact) {
    EXPECT_EQ(w.particles, 0.0) << "positions, velocity, F, stress: the one-rank bits";
    EXPECT_EQ(w.dt, 0.0) << "stable dt: the one-rank bits";
    EXPECT_EQ(w.sums, 0.0) << ".dat sums: the one-rank bits";
  }
  if (world_ranks().size > 1) EXPECT_GT(migrated, 0) << "no particle crossed to another rank";
  else EXPECT_EQ(migrated, 0);
  if (world_ranks().is_root())
    std::printf("[ mpi-mpm ] %s %s %s: worst relative difference particles %.3g, .dat sums %.3g, dt %.3g; "
                "%d particles changed rank\n",
                c.patches, c.interpolator, c.contact, w.particles, w.sums, w.dt, migrated);
}

INSTANTIATE_TEST_SUITE_P(Disks, MpiMpm,
                         ::testing::Values(Case{"[2,1,1]", "linear", "", true}, Case{"[2,1,1]", "gimp", "", true},
                                           Case{"[2,2,1]", "gimp", "", true},
                                           Case{"[2,2,1]", "linear", "single_velocity", true},
                                           Case{"[2,1,1]", "gimp", "friction", false}));

}  // namespace
}  // namespace tephra
