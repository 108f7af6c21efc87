// MPM features on MPI ranks (issue 7, docs/parallel.md "MPM on ranks"):
// periodic grids, axisymmetric runs and <PhysicalBC><MPM> loads. Each deck
// runs with the whole level in this process (keep_whole_level: the 1-rank
// run) and with its patches spread over the world's ranks, stepped with the
// same dt (the whole run's).
//
// What the ranks must add over each other (mpm/MpmRanks.cpp):
//  * periodic: a node's periodic aliases lie a period apart, possibly in the
//    other rank's half; a rank's node box spans every periodic direction, so
//    the folds (mpm/PeriodicGrid.h) add the sums of all ranks;
//  * axisymmetric: per particle and per node (hoop terms), only the node
//    sums of the usual scatters;
//  * loads: a pressure or heat-flux surface shares p A (q A) among its N
//    particles, a moment normalises by sum d^2 over its particles; N and
//    sum d^2 run over the particles of every rank (mpm/loads/RankSum.h); a
//    velocity surface's nodes are those any rank's flagged particles reach.
//
// Expected: the 1-rank answer to round-off, as tests/mpi/test_mpi_mpm.cpp
// explains: nodes reached by two ranks' particles get per-rank partial sums
// added, where one process adds the particles in one sequence (IEEE addition
// is not associative). Asserted per field max |a - b| <= 1e-12 max |a|
// (positions, velocity, F, stress, temperature, external force) and the .dat
// sums 1e-12 relative (TotalMomentum relative to sum m |v|); every particle id
// exactly once over the ranks at the end, the particle count conserved after
// every step; under -np 2 particles change rank during the run.
// If the ranks did not add these (e.g. each rank's own N), the differences
// are of the size of the loads themselves (checked: see the report of the
// mutation runs in docs/parallel.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/io/OutputFrame.h"
#include "core/io/StateArchive.h"
#include "core/parallel/Ranks.h"
#include "tests/mpi/MpmRankCompare.h"
#include "tests/mpi/RankCompare.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

using test::flat;
using test::own_ids;
using test::particles_here;
using test::relative_difference;

std::string material(double K, double G, const std::string& geom_objects) {
  std::ostringstream s;
  s << "<material><density>1000</density><thermal_conductivity>1</thermal_conductivity>"
    << "<specific_heat>1000</specific_heat><constitutive_model type=\"hypo_elastic\"><K>" << K << "</K><G>" << G
    << "</G></constitutive_model>" << geom_objects << "</material>";
  return s.str();
}

std::string geom(const std::string& label, const Vec3& lo, const Vec3& hi, const std::string& res, const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << "<geom_object><box label=\"" << label << "\"><min>[" << lo[0] << "," << lo[1] << "," << lo[2] << "]</min><max>[" << hi[0]
    << "," << hi[1] << "," << hi[2] << "]</max></box><res>" << res << "</res><velocity>[" << v[0] << "," << v[1]
    << "," << v[2] << "]</velocity><temperature>300</temperature></geom_object>";
  return s.str();
}

// 1. Periodic in x (and y, z): two blocks in a [0,1] x [0,0.25] x [0,0.125]
//    box; the left one (on rank 0's half) moves at -1 m/s through the
//    periodic face x = 0 = 1 into the right one (at rest, on rank 1's half),
//    they collide there and move on together at about -0.5 m/s: the collision
//    is in the periodic aliases of the two ranks' halves, and the particles
//    cross the periodic face into the other rank's patches.
std::string periodic_deck(const std::string& interp, const std::string& patches) {
  std::ostringstream s;
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator></MPM>"
    << "<MaterialProperties><MPM>"
    << material(6e3, 3e3,
                geom("left", Vec3(0.0625, 0, 0), Vec3(0.3125, 0.25, 0.125), "[2,2,2]", Vec3(-1, 0, 0)) +
                    geom("right", Vec3(0.6875, 0, 0), Vec3(0.9375, 0.25, 0.125), "[2,2,2]", Vec3(0, 0, 0)))
    << "</MPM></MaterialProperties>"
    << "<Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1,0.25,0.125]</upper>"
    << "<extraCells>[0,0,0]</extraCells><patches>" << patches << "</patches></Box>"
    << "<spacing>[0.0625,0.0625,0.0625]</spacing><periodic>[1,1,1]</periodic></Level></Grid></Uintah_specification>";
  return s.str();
}

// 2. Axisymmetric (x = r, y = z): a thick cylinder wall a = 0.5 <= r <= 1
//    contracting at 2 m/s against an internal pressure ramp (<axisymmetric_side>
//    load: p R L / N per particle, N over the ranks) and a second
//    <axisymmetric_side> surface at r = 9/16, on the patch cut (its particles,
//    within 0.9 dr_p of it, are on both ranks: N is a sum over the ranks);
//    symmetry faces r = 0 and in the axial direction; the particles seeded
//    just outside the cut cross it.
std::string axisymmetric_deck(const std::string& interp) {
  const double h = 1.0 / 16;
  std::ostringstream s;
  s.precision(17);
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator><axisymmetric>true</axisymmetric>"
    << "<use_load_curves>true</use_load_curves></MPM>"
    << "<MaterialProperties><MPM>"
    << material(6e6, 3e6, geom("wall", Vec3(0.5, 0, 0), Vec3(1.0, 2 * h, h), "[2,2,1]", Vec3(-2, 0, 0)))
    << "</MPM></MaterialProperties>"
    << "<PhysicalBC><MPM><pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0," << 2 * h
    << ",0]</top><radius>0.5</radius><axisymmetric_side>true</axisymmetric_side></cylinder></geom_object>"
    << "<load_curve><id>1</id><time_point><time>0</time><load>0</load></time_point><time_point><time>0.02</time>"
    << "<load>1e5</load></time_point></load_curve></pressure>"
    << "<pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0," << 2 * h
    << ",0]</top><radius>0.5625</radius><axisymmetric_side>true</axisymmetric_side></cylinder></geom_object>"
    << "<load_curve><id>2</id><time_point><time>0</time><load>5e4</load></time_point></load_curve></pressure>"
    << "</MPM></PhysicalBC><Grid><BoundaryConditions>";
  for (const char* f : {"x-", "y-", "y+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"></BCType></Face>";
  s << "</BoundaryConditions><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1.125," << 2 * h << "," << h
    << "]</upper><extraCells>[1,1,1]</extraCells><patches>[2,1,1]</patches></Box><spacing>[" << h << "," << h << ","
    << h << "]</spacing></Level></Grid></Uintah_specification>";
  return s.str();
}

// 3. Cartesian loads on a free plate [0.125, 0.875] x [0.125, 0.375] (one
//    cell thick) cut at x = 0.5, every loaded surface spanning the cut:
//    moving at 2 m/s along x (so particles cross the cut), with
//    pressure (ramp to 1e4 Pa) on the top face y = 0.375, heat flux (1e5
//    W/m^2) and a moment (ramp to 10 N m about the plane x = 0.5) on the
//    bottom face y = 0.125, a body force density on x < 0.3, and a velocity
//    surface (v = (2, 0.2, 0)) on the plane x = 0.375 (its flagged particles
//    on rank 0 reach the nodes around x = 0.4375 that rank 1's particles read).
std::string loads_deck(const std::string& interp) {
  auto box = [](const std::string& lo, const std::string& hi) {
    return "<geom_object><box label=\"s\"><min>" + lo + "</min><max>" + hi + "</max></box></geom_object>";
  };
  auto curve = [](const std::string& rows) { return "<load_curve><id>1</id>" + rows + "</load_curve>"; };
  auto point = [](const std::string& t, const std::string& load) {
    return "<time_point><time>" + t + "</time><load>" + load + "</load></time_point>";
  };
  std::ostringstream s;
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator><use_load_curves>true</use_load_curves></MPM>"
    << "<MaterialProperties><MPM>"
    << material(6e6, 3e6, geom("plate", Vec3(0.125, 0.125, 0), Vec3(0.875, 0.375, 0.0625), "[2,2,1]", Vec3(2, 0, 0)))
    << "</MPM></MaterialProperties><PhysicalBC><MPM>"
    << "<pressure>" << box("[0.125,0.375,0]", "[0.875,0.375,0.0625]") << curve(point("0", "0") + point("0.01", "1e4"))
    << "</pressure>"
    << "<heat_flux>" << box("[0.125,0.125,0]", "[0.875,0.125,0.0625]") << curve(point("0", "1e5")) << "</heat_flux>"
    << "<moment>" << box("[0.125,0.125,0]", "[0.875,0.125,0.0625]")
    << "<normal_plane><normal>[1,0,0]</normal><point>[0.5,0,0]</point></normal_plane>"
    << curve(point("0", "0") + point("0.01", "10")) << "</moment>"
    << "<force><lower>[0,0,0]</lower><upper>[0.3,1,1]</upper><force_density>[0,-20,0]</force_density></force>"
    << "<velocity>" << box("[0.375,0.125,0]", "[0.375,0.375,0.0625]") << curve(point("0", "[2,0.2,0]")) << "</velocity>"
    << "</MPM></PhysicalBC>"
    << "<Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1,0.5,0.0625]</upper>"
    << "<extraCells>[1,1,1]</extraCells><patches>[2,1,1]</patches></Box>"
    << "<spacing>[0.0625,0.0625,0.0625]</spacing></Level></Grid></Uintah_specification>";
  return s.str();
}

struct MpmRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmComponent> mpm;
};

MpmRun start(const std::string& text, bool whole) {
  MpmRun r;
  r.deck = load_deck_from_string(text, "mpi_mpm_features.ups", ".");
  r.mpm = make_mpm_component(*r.deck);
  if (whole) r.mpm->keep_whole_level();
  r.mpm->initialize();
  return r;
}

const std::set<std::string> kParticleLabels = {"p.velocity", "p.stress", "p.deformationMeasure", "p.temperature",
                                               "p.externalforce"};
const std::set<std::string> kSums = {"KineticEnergy", "StrainEnergy", "TotalMass", "TotalMomentum",
                                     "ThermalEnergy"};

double compare(const MpmComponent& a, const MpmComponent& b) {
  return test::compare_mpm_runs(a, b, kParticleLabels, kSums, 1e-12);
}

struct Case {
  const char* name;
  std::string (*deck)(const std::string&);
  const char* interpolator;
  int steps;
  double multiplier;
};

std::string periodic_gimp(const std::string& i) { return periodic_deck(i, "[2,1,1]"); }
std::string periodic_four(const std::string& i) { return periodic_deck(i, "[4,1,1]"); }

class MpiMpmFeatures : public ::testing::TestWithParam<Case> {};

TEST_P(MpiMpmFeatures, RanksGiveTheOneRankAnswerToRoundOff) {
  const Case c = GetParam();
  const std::string text = c.deck(c.interpolator);
  MpmRun whole = start(text, true);
  MpmRun ranks = start(text, false);
  EXPECT_EQ(ranks.mpm->layout().distributed, world_ranks().size > 1);
  const std::size_t total = particles_here(whole.mpm->materials());
  const std::set<long long> start_ids = own_ids(ranks.mpm->materials());
  std::set<long long> ever_left;
  double t = 0, worst_dt = 0;
  for (int step = 1; step <= c.steps; ++step) {
    const double dt = c.multiplier * whole.mpm->stable_timestep();
    worst_dt = std::max(worst_dt, std::abs(ranks.mpm->stable_timestep() / whole.mpm->stable_timestep() - 1));
    whole.mpm->advance(t, dt, step);
    ranks.mpm->advance(t, dt, step);
    t += dt;
    double sum = 0;
    for (double n : all_gather(std::vector<double>{double(particles_here(ranks.mpm->materials()))})) sum += n;
    EXPECT_EQ(sum, double(total)) << "step " << step;
    const std::set<long long> now = own_ids(ranks.mpm->materials());
    for (long long id : start_ids)
      if (!now.count(id)) ever_left.insert(id);
  }
  EXPECT_LE(worst_dt, 1e-12) << "stable dt of the distributed run";
  double migrated = 0;
  for (double l : all_gather(std::vector<double>{double(ever_left.size())})) migrated += l;
  const double worst = compare(*whole.mpm, *ranks.mpm);
  if (world_ranks().size > 1) EXPECT_GT(migrated, 0) << "no particle crossed to another rank";
  if (world_ranks().is_root())
    std::printf("[ mpi-mpm-features ] %s %s, %d steps to t = %.4g: worst relative difference %.3g, %g particles "
                "changed rank\n",
                c.name, c.interpolator, c.steps, t, worst, migrated);
}

INSTANTIATE_TEST_SUITE_P(
    Features, MpiMpmFeatures,
    ::testing::Values(Case{"periodic [2,1,1]", &periodic_gimp, "gimp", 120, 0.5},
                      Case{"periodic [4,1,1]", &periodic_four, "linear", 120, 0.5},
                      Case{"axisymmetric", &axisymmetric_deck, "gimp", 300, 0.3},
                      Case{"loads", &loads_deck, "gimp", 150, 0.3}),
    [](const ::testing::TestParamInfo<Case>& i) {
      std::string n = std::string(i.param.name) + "_" + i.param.interpolator;
      for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return n;
    });

// Checkpoints across rank counts (the periodic deck): the archive written by
// the N-rank run restored into a whole-level component (N -> 1) and the
// 1-rank archive into a distributed one (1 -> N) continue as the
// uninterrupted 1-rank run, to round-off.
TEST(MpiMpmFeatures, PeriodicCheckpointsRestartAcrossRankCounts) {
  const std::string text = periodic_deck("gimp", "[2,1,1]");
  MpmRun one = start(text, true);
  MpmRun many = start(text, false);
  double t = 0;
  int step = 0;
  auto advance = [&](std::initializer_list<MpmRun*> runs) {
    const double dt = 0.5 * one.mpm->stable_timestep();
    ++step;
    for (MpmRun* r : runs) r->mpm->advance(t, dt, step);
    t += dt;
  };
  for (int n = 0; n < 60; ++n) advance({&one, &many});  // the blocks have met through the periodic face
  StateArchive a1, an;
  one.mpm->save_state(a1);
  many.mpm->save_state(an);
  MpmRun to_many = start(text, false);
  MpmRun to_one = start(text, true);
  to_many.mpm->load_state(a1);
  to_one.mpm->load_state(an);
  for (int n = 0; n < 60; ++n) advance({&one, &to_many, &to_one});
  const double d_many = compare(*one.mpm, *to_many.mpm);
  const double d_one = compare(*one.mpm, *to_one.mpm);
  if (world_ranks().is_root())
    std::printf("[ mpi-mpm-features ] periodic restart 1 -> %d ranks: %.3g, %d -> 1: %.3g\n", world_ranks().size,
                d_many, world_ranks().size, d_one);
}

}  // namespace
}  // namespace tephra
