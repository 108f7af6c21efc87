// The MPM features that stopped with exit 3 under mpirun until session 18
// (docs/parallel.md "MPM on ranks"): <do_pressure_stabilization>,
// <use_prescribed_deformation>, <run_MMS_problem> and the kinetic-energy
// ledger labels. Each deck runs with the whole level in this process
// (keep_whole_level: the 1-rank run) and spread over the world's ranks,
// stepped with the same dt, under mpirun -np 1, 2 and 4.
//
// What the ranks must add over each other:
//  * pressure stabilisation: per cell {sum V0_p, sum J_p V0_p} over the
//    particles of the cell (mpm/PressureStabilization.h), summed over the
//    ranks at the cell's lower-corner node;
//  * prescribed deformation: nothing (v*_g = l x_g on every node, per particle after);
//  * MMS: MMSDisplacementErrorL2 = sqrt(sum V0 |u - u*|^2 / sum V0), both sums over the ranks;
//  * ledger: each node's terms counted by exactly one rank (the lowest whose
//    node box holds it), each particle's by its own, the step's totals added
//    over the ranks.
//
// Expected: the 1-rank answer to round-off (nodes two ranks reach add per-rank
// partial sums, tests/mpi/test_mpi_mpm.cpp): positions, velocity, F, stress and
// the .dat sums within 1e-12 of each field's max (the ledger terms and
// MMSDisplacementErrorL2 relative to the initial kinetic energy / the error's own
// size); particle counts conserved after every step; particles change rank
// under -np 2 (the decks move across the patch cuts). For the ledger the FLIP
// identity KE(t) - KE(0) = GridForceWork - ContactKineticEnergyRemoved -
// BoundaryKineticEnergyRemoved - TransferKineticEnergyLoss (mpm/EnergyLedger.h)
// is also asserted on the distributed run, to 1e-11 KE0: a node counted twice
// or not at all breaks it by the node's share of the kinetic energy.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/parallel/Ranks.h"
#include "mpm/MpmComponent.h"
#include "tests/mpi/MpmRankCompare.h"
#include "tests/mpi/RankCompare.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::own_ids;
using test::particles_here;

std::string box_object(const std::string& label, const Vec3& lo, const Vec3& hi, const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << "<geom_object><box label=\"" << label << "\"><min>[" << lo[0] << "," << lo[1] << "," << lo[2] << "]</min><max>["
    << hi[0] << "," << hi[1] << "," << hi[2] << "]</max></box><res>[2,2,2]</res><velocity>[" << v[0] << "," << v[1]
    << "," << v[2] << "]</velocity><temperature>300</temperature></geom_object>";
  return s.str();
}

std::string material(const std::string& model, const std::string& objects) {
  return "<material><density>1000</density><thermal_conductivity>1</thermal_conductivity>"
         "<specific_heat>1000</specific_heat>" +
         model + objects + "</material>";
}

const std::string kNearlyIncompressible =  // K/G = 50 (nu = 0.49): the locking regime stabilisation is for
    "<constitutive_model type=\"comp_neo_hook\"><bulk_modulus>5e6</bulk_modulus><shear_modulus>1e5</shear_modulus>"
    "</constitutive_model>";
const std::string kElastic =
    "<constitutive_model type=\"hypo_elastic\"><K>6e6</K><G>3e6</G></constitutive_model>";

std::string grid(const Vec3& upper, const std::string& patches, const std::string& bcs = "") {
  std::ostringstream s;
  s.precision(17);
  s << "<Grid>" << bcs << "<Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[" << upper[0] << "," << upper[1]
    << "," << upper[2] << "]</upper><extraCells>[1,1,1]</extraCells><patches>" << patches
    << "</patches></Box><spacing>[0.0625,0.0625,0.0625]</spacing></Level></Grid>";
  return s.str();
}

// 1. Pressure stabilisation: a nearly incompressible block (x in [0.125, 0.5])
//    at 2 m/s hits a resting one ([0.5, 0.875]) at the patch cut x = 0.5 (one
//    material, so they merge); the impact compresses the cells at the cut
//    unevenly, the stabilisation replaces each particle's J by its cell's.
std::string stabilization_deck() {
  return "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
         "<MPM><interpolator>gimp</interpolator><do_pressure_stabilization>true</do_pressure_stabilization></MPM>"
         "<MaterialProperties><MPM>" +
         material(kNearlyIncompressible,
                  box_object("left", Vec3(0.125, 0.0625, 0), Vec3(0.5, 0.25, 0.0625), Vec3(2, 0, 0)) +
                      box_object("right", Vec3(0.5, 0.0625, 0), Vec3(0.875, 0.25, 0.0625), Vec3(0, 0, 0))) +
         "</MPM></MaterialProperties>" + grid(Vec3(1, 0.3125, 0.0625), "[2,1,1]") + "</Uintah_specification>";
}

// 2. Prescribed deformation F*(t) (mpm/PrescribedDeformation.h): from I at t = 0
//    to [[1.3, 0.1, 0], [0, 0.9, 0], [0, 0, 1]] at t = 1e-3 (x = F* X about the
//    origin: the block [0.25, 0.75] x [0.0625, 0.25] stretches to x <= 1.0,
//    its particles right of X = 0.48 cross the cut x = 0.625).
std::string prescribed_deck(const std::string& file) {
  return "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
         "<MPM><interpolator>linear</interpolator><use_prescribed_deformation>true</use_prescribed_deformation>"
         "<prescribed_deformation_file>" +
         file +
         "</prescribed_deformation_file></MPM><PhysicalConstants><gravity>[0,0,0]</gravity></PhysicalConstants>"
         "<MaterialProperties><MPM>" +
         material(kElastic, box_object("block", Vec3(0.25, 0.0625, 0), Vec3(0.75, 0.25, 0.0625), Vec3(0, 0, 0))) +
         "</MPM></MaterialProperties>" + grid(Vec3(1.25, 0.3125, 0.0625), "[2,1,1]") + "</Uintah_specification>";
}

// The table of F*(t): "t F11 F12 F13 F21 ... F33 angle axis_x axis_y axis_z" per row;
// one file per rank (every rank reads its own, no shared write).
std::string write_prescribed_table() {
  const std::string dir = test::scratch_dir("mpi_prescribed_rank" + std::to_string(world_ranks().rank));
  const std::string file = dir + "/prescribed.txt";
  std::ofstream out(file);
  out << "0 1 0 0 0 1 0 0 0 1 0 0 0 1\n"
      << "1e-3 1.3 0.1 0 0 0.9 0 0 0 1 0 0 0 1\n";
  return file;
}

// 3. MMS: the expanding ring (inputs/mpm/expanding_ring_mms.ups, cpdi, 32 x 32
//    cells) cut into [2,2,1] patches; the ring's particles move radially across
//    both cuts x = y = 0.4.
std::string mms_deck() {
  std::string text = test::slurp(test::source_dir() + "/inputs/mpm/expanding_ring_mms.ups");
  const std::string a = "<patches>[1,1,1]</patches>", b = "<patches>[2,2,1]</patches>";
  const std::size_t at = text.find(a);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.replace(at, a.size(), b);
  return text;
}

// 4. Ledger: a block ([0.0625, 0.9375] x [0.0625, 0.25], across the cut
//    x = 0.5) moving at (-3, -1) m/s towards the walls x- and y- (velocity 0:
//    BoundaryKineticEnergyRemoved; z faces symmetry planes), and a second material at rest beside it
//    ([0.0625, 0.9375] x [0.25, 0.375]) with single_velocity contact
//    (ContactKineticEnergyRemoved); all four labels saved.
std::string ledger_deck() {
  std::string bcs = "<BoundaryConditions>";
  for (const char* f : {"x-", "y-"})  // walls at rest: v_g = 0 at their nodes
    bcs += std::string("<Face side=\"") + f +
           "\"><BCType id=\"all\" var=\"Dirichlet\" label=\"Velocity\"><value>[0,0,0]</value></BCType></Face>";
  for (const char* f : {"z-", "z+"})
    bcs += std::string("<Face side=\"") + f + "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"></BCType></Face>";
  bcs += "</BoundaryConditions>";
  std::string saves = "<DataArchiver><filebase>ledger.uda</filebase><outputInterval>1</outputInterval>";
  for (const char* l : {"ContactKineticEnergyRemoved", "BoundaryKineticEnergyRemoved", "GridForceWork",
                        "TransferKineticEnergyLoss", "KineticEnergy"})
    saves += std::string("<save label=\"") + l + "\"/>";
  saves += "</DataArchiver>";
  return "<Uintah_specification><SimulationComponent type=\"mpm\"/>" + saves +
         "<MPM><interpolator>gimp</interpolator></MPM><MaterialProperties><MPM>" +
         material(kElastic, box_object("block", Vec3(0.0625, 0.0625, 0), Vec3(0.9375, 0.25, 0.0625), Vec3(-3, -1, 0))) +
         material(kElastic, box_object("beside", Vec3(0.0625, 0.25, 0), Vec3(0.9375, 0.375, 0.0625), Vec3(0, 0, 0))) +
         "<contact><type>single_velocity</type><materials>[0,1]</materials></contact>"
         "</MPM></MaterialProperties>" +
         grid(Vec3(1, 0.5, 0.0625), "[2,1,1]", bcs) + "</Uintah_specification>";
}

struct MpmRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmComponent> mpm;
};

MpmRun start(const std::string& text, bool whole) {
  MpmRun r;
  r.deck = load_deck_from_string(text, "mpi_mpm_rank_features.ups", test::source_dir() + "/inputs/mpm");
  r.mpm = make_mpm_component(*r.deck);
  if (whole) r.mpm->keep_whole_level();
  r.mpm->initialize();
  return r;
}

const std::set<std::string> kParticleLabels = {"p.velocity", "p.stress", "p.deformationMeasure"};
const std::vector<std::string> kLedger = {"ContactKineticEnergyRemoved", "BoundaryKineticEnergyRemoved",
                                          "GridForceWork", "TransferKineticEnergyLoss"};

double kinetic_energy(const MpmComponent& c) { return c.reductions({"KineticEnergy"}).at("KineticEnergy").at(0); }

// Steps both runs with the whole run's dt (multiplier x stable dt), asserts
// conserved counts after every step; returns how many particles left their
// starting rank at some step, over all ranks.
double step_both(MpmRun& whole, MpmRun& ranks, int steps, double multiplier, double dt_fixed = 0,
                 const std::function<void(double)>& after_step = {}) {
  const std::size_t total = particles_here(whole.mpm->materials());
  const std::set<long long> start_ids = own_ids(ranks.mpm->materials());
  std::set<long long> ever_left;
  double t = 0;
  for (int step = 1; step <= steps; ++step) {
    const double dt = dt_fixed > 0 ? dt_fixed : multiplier * whole.mpm->stable_timestep();
    whole.mpm->advance(t, dt, step);
    ranks.mpm->advance(t, dt, step);
    t += dt;
    double sum = 0;
    for (double n : all_gather(std::vector<double>{double(particles_here(ranks.mpm->materials()))})) sum += n;
    EXPECT_EQ(sum, double(total)) << "step " << step;
    const std::set<long long> now = own_ids(ranks.mpm->materials());
    for (long long id : start_ids)
      if (!now.count(id)) ever_left.insert(id);
    if (after_step) after_step(t);
  }
  double migrated = 0;
  for (double l : all_gather(std::vector<double>{double(ever_left.size())})) migrated += l;
  if (world_ranks().size > 1) EXPECT_GT(migrated, 0) << "no particle crossed to another rank";
  return migrated;
}

void report(const char* name, int steps, double worst, double migrated) {
  if (world_ranks().is_root())
    std::printf("[ mpi-mpm-rank-features ] %s on %d ranks, %d steps: worst relative difference %.3g, %g particles "
                "changed rank\n",
                name, world_ranks().size, steps, worst, migrated);
}

TEST(MpiMpmRankFeatures, PressureStabilizationGivesTheOneRankAnswer) {
  const std::string text = stabilization_deck();
  MpmRun whole = start(text, true);
  MpmRun ranks = start(text, false);
  EXPECT_EQ(ranks.mpm->layout().distributed, world_ranks().size > 1);
  const int steps = 120;
  const double migrated = step_both(whole, ranks, steps, 0.4);
  const double worst = test::compare_mpm_runs(*whole.mpm, *ranks.mpm, kParticleLabels,
                                              {"KineticEnergy", "StrainEnergy", "TotalMass"}, 1e-12);
  report("pressure stabilisation", steps, worst, migrated);
}

TEST(MpiMpmRankFeatures, PrescribedDeformationGivesTheOneRankAnswer) {
  const std::string text = prescribed_deck(write_prescribed_table());
  MpmRun whole = start(text, true);
  MpmRun ranks = start(text, false);
  const int steps = 100;
  const double migrated = step_both(whole, ranks, steps, 0, 1e-5);  // t = 1e-3: the table's end
  const double worst = test::compare_mpm_runs(*whole.mpm, *ranks.mpm, kParticleLabels,
                                              {"StrainEnergy", "TotalMass"}, 1e-12);
  // Oracle independent of the ranks: F_p = F*(1e-3) on every particle (the driver's
  // F_{n+1} = F*(t_{n+1}) F*(t_n)^-1 F_n telescopes), to round-off.
  Mat3 Fstar;
  Fstar << 1.3, 0.1, 0, 0, 0.9, 0, 0, 0, 1;
  double worst_F = 0;
  for (const MpmMaterial& m : ranks.mpm->materials())
    for (const Mat3& F : m.particles.F) worst_F = std::max(worst_F, (F - Fstar).cwiseAbs().maxCoeff());
  EXPECT_LE(worst_F, 1e-12);
  report("prescribed deformation", steps, worst, migrated);
}

TEST(MpiMpmRankFeatures, MmsErrorNormGivesTheOneRankAnswer) {
  const std::string text = mms_deck();
  MpmRun whole = start(text, true);
  MpmRun ranks = start(text, false);
  const int steps = 60;
  const double migrated = step_both(whole, ranks, steps, 0.2);
  const double e1 = whole.mpm->mms_displacement_error();
  const double worst = test::compare_mpm_runs(*whole.mpm, *ranks.mpm, {"p.velocity", "p.deformationMeasure"},
                                              {"MMSDisplacementErrorL2", "TotalMass"}, 1e-12);
  // A per-rank norm (no sums over the ranks) differs by O(1) of itself: the
  // error is not uniform over the ring's quarters.
  EXPECT_GT(e1, 0.0);
  report("MMS expanding ring", steps, worst, migrated);
}

TEST(MpiMpmRankFeatures, EnergyLedgerGivesTheOneRankAnswerAndItsIdentity) {
  const std::string text = ledger_deck();
  MpmRun whole = start(text, true);
  MpmRun ranks = start(text, false);
  const double ke0 = kinetic_energy(*whole.mpm);
  EXPECT_EQ(kinetic_energy(*ranks.mpm), ke0);
  double worst_identity = 0;
  auto identity = [&](double) {
    const auto r = ranks.mpm->reductions({kLedger.begin(), kLedger.end()});
    const double rhs = r.at("GridForceWork")[0] - r.at("ContactKineticEnergyRemoved")[0] -
                       r.at("BoundaryKineticEnergyRemoved")[0] - r.at("TransferKineticEnergyLoss")[0];
    worst_identity = std::max(worst_identity, std::abs(kinetic_energy(*ranks.mpm) - ke0 - rhs) / ke0);
  };
  const int steps = 150;
  const double migrated = step_both(whole, ranks, steps, 0.4, 0, identity);
  EXPECT_LE(worst_identity, 1e-11) << "KE(t) - KE(0) = GFW - CKR - BKR - TKL on the distributed run";
  std::map<std::string, double> scales;
  for (const std::string& l : kLedger) scales[l] = ke0;
  std::set<std::string> sums(kLedger.begin(), kLedger.end());
  sums.insert("KineticEnergy");
  const double worst = test::compare_mpm_runs(*whole.mpm, *ranks.mpm, kParticleLabels, sums, 1e-12, scales);
  const auto r = whole.mpm->reductions(sums);
  // The walls set v_g = 0 already after P2G, so BoundaryKineticEnergyRemoved
  // stays 0 here (EnergyLedger.h: those corrections are not counted); the
  // contact and the FLIP transfer must act.
  EXPECT_GT(r.at("ContactKineticEnergyRemoved")[0], 1e-2 * ke0) << "the contact must act";
  EXPECT_GT(r.at("TransferKineticEnergyLoss")[0], 1e-2 * ke0) << "the transfer loss must be seen";
  if (world_ranks().is_root())
    std::printf("[ mpi-mpm-rank-features ] ledger: KE0 %.6g, contact %.4g, boundary %.4g, work %.4g, transfer %.4g; "
                "identity on the ranks %.3g KE0\n",
                ke0, r.at("ContactKineticEnergyRemoved")[0], r.at("BoundaryKineticEnergyRemoved")[0],
                r.at("GridForceWork")[0], r.at("TransferKineticEnergyLoss")[0], worst_identity);
  report("energy ledger", steps, worst, migrated);
}

}  // namespace
}  // namespace tephra
