// The kinetic-energy ledger of the explicit step (mpm/EnergyLedger.h) on the
// Taylor impact deck (decks README A5, MPM/Impact/cylinderImpact_A_JC.ups),
// coarsened to the study's h = 1 mm grid (docs/models/taylor-impact.md), for the
// first 3 us (the impact: the wall captures the node layer y = 0).
//
// Oracle: the identity of the FLIP step (EnergyLedger.h), exact in exact arithmetic,
//   KE_p(t) - KE_p(0) = GridForceWork - ContactKineticEnergyRemoved
//                       - BoundaryKineticEnergyRemoved - TransferKineticEnergyLoss,
// checked at every step to round-off (1e-11 KE0). Signs: the rigid wall stands still
// (v = 0), so each contact correction sets a node velocity component to 0 and removes
// 1/2 m v_y^2 >= 0: the running sum never decreases; the transfer loss is >= 0 at every
// step (Jensen's inequality, S_gp >= 0 and sum_g S_gp = 1). The symmetry planes x = 0,
// z = 0 see mirror-symmetric sums: their correction removes (almost) nothing.
// And the first step's capture: at impact the wall node layer y = 0 carries the rod's
// bottom particle rows (linear weights S = 5/6, 1/2, 1/6 at y = h/6, h/2, 5h/6) at
// -227 m/s; setting its v_y to 0 removes 1/2 m_g v^2 with m_g = sum_rows m_row S,
// i.e. (5/6 + 1/2 + 1/6) = 1.5 rows of thickness h/3, a fraction 1.5 (h/3)/L_seed of
// KE0 exactly (sigma = 0 at t = 0: no node force in step 1, so the integrated stage
// removes nothing more; the staircase seeding is the same in every row).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

// wall = "symmetry": the study's --wall symmetry variant (tests/bench/taylor_impact_study.py): the
// wall material (the first <material>) and its rigid contact removed, the grid starting at
// y = 0 so that the deck's y- symmetry face is the wall (the rod is then material 0).
std::string a5_coarse_text(const std::string& wall = "rigid") {
  const std::string dir = test::shared_dir() + "/decks/inputs/MPM/Impact/";
  std::ifstream in(dir + "cylinderImpact_A_JC.ups");
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto set = [&](const std::string& open, const std::string& close, const std::string& text) {
    const std::size_t a = xml.find(open);
    const std::size_t b = xml.find(close, a);
    if (a == std::string::npos || b == std::string::npos) return false;
    xml.replace(a + open.size(), b - a - open.size(), text);
    return true;
  };
  if (wall == "symmetry") {
    for (const std::string tag : {"material", "contact"}) {
      const std::size_t a = xml.find("<" + tag + ">");
      const std::size_t b = xml.find("</" + tag + ">", a);
      if (a == std::string::npos || b == std::string::npos) return "";
      xml.erase(a, b + tag.size() + 3 - a);
    }
  }
  // The study's h = 1 mm grid: the wall face y = 0 a grid line.
  const bool rigid = wall == "rigid";
  if (!set("<lower>", "</lower>", rigid ? "[0.0,-3.0e-3,0.0]" : "[0.0,0.0,0.0]") ||
      !set("<upper>", "</upper>", "[9.0e-3,36.0e-3,9.0e-3]") ||
      !set("<resolution>", "</resolution>", rigid ? "[9,39,9]" : "[9,36,9]"))
    return "";
  const std::string save = "<save label = \"KineticEnergy\"/>";
  const std::size_t s = xml.find(save);
  if (s == std::string::npos) return "";
  xml.insert(s, "<save label = \"ContactKineticEnergyRemoved\"/> <save label = \"BoundaryKineticEnergyRemoved\"/>"
                " <save label = \"GridForceWork\"/> <save label = \"TransferKineticEnergyLoss\"/>\n");
  return xml;
}

TEST(MpmEnergyLedger, TaylorImpactStepIdentityHoldsToRoundOff) {
  const std::string xml = a5_coarse_text();
  ASSERT_FALSE(xml.empty());
  auto deck = load_deck_from_string(xml, "cylinderImpact_A_JC_h1.ups",
                                    test::shared_dir() + "/decks/inputs/MPM/Impact");
  const double multiplier = deck->root.require_child("Time").get_double("timestep_multiplier");
  auto c = make_mpm_component(*deck);
  c->initialize();
  const std::set<std::string> labels = {"KineticEnergy", "ContactKineticEnergyRemoved",
                                           "BoundaryKineticEnergyRemoved", "GridForceWork",
                                           "TransferKineticEnergyLoss"};
  const double ke0 = c->reductions(labels).at("KineticEnergy")[0];
  // The seeded rod: its particle rows (spacing h/3) and top y, for the first-step capture.
  const Particles& rod = c->materials()[1].particles;
  double y_top = 0;
  for (std::size_t i = 0; i < rod.size(); ++i) y_top = std::max(y_top, rod.x[i][1]);
  const double h = 1e-3, L_seed = y_top + h / 6;  // the top row's centre + half its spacing
  double t = 0, worst = 0, prev_contact = 0, first_capture = 0, min_transfer_step = 1, prev_transfer = 0;
  double boundary = 0;
  int step = 0;
  while (t < 3e-6) {
    const double dt = std::min(multiplier * c->stable_timestep(), 3e-6 - t);
    c->advance(t, dt, ++step);
    t += dt;
    const auto r = c->reductions(labels);
    const double ke = r.at("KineticEnergy")[0], contact = r.at("ContactKineticEnergyRemoved")[0];
    const double work = r.at("GridForceWork")[0], transfer = r.at("TransferKineticEnergyLoss")[0];
    boundary = r.at("BoundaryKineticEnergyRemoved")[0];
    worst = std::max(worst, std::abs((ke - ke0) - (work - contact - boundary - transfer)) / ke0);
    EXPECT_GE(contact, prev_contact - 1e-12 * ke0) << "step " << step;
    min_transfer_step = std::min(min_transfer_step, (transfer - prev_transfer) / ke0);
    if (step == 1) first_capture = contact;
    prev_contact = contact;
    prev_transfer = transfer;
  }
  const auto r = c->reductions(labels);
  const double ke = r.at("KineticEnergy")[0];
  const double estimate = 1.5 * (h / 3) / L_seed;
  std::printf("ledger A5 h = 1 mm, %d steps to 3 us: KE0 %.4f J, KE %.4f J; contact %.4f J (%.3f %% KE0; step 1 "
              "%.3f %% vs 1.5 (h/3)/L_seed = %.3f %%), boundary %.3e J, grid-force work %.4f J, transfer %.4e J; "
              "max |identity residual|/KE0 %.2e, min transfer step %.2e KE0\n",
              step, ke0, ke, prev_contact, 100 * prev_contact / ke0, 100 * first_capture / ke0, 100 * estimate,
              boundary, r.at("GridForceWork")[0], prev_transfer, worst, min_transfer_step);
  EXPECT_LT(worst, 1e-11);
  EXPECT_GE(min_transfer_step, -1e-14);
  EXPECT_NEAR(first_capture / ke0, estimate, 1e-9 * estimate);  // sigma_0 = 0: no force yet, exact
  EXPECT_LT(std::abs(boundary), 1e-6 * ke0);
}

// The frictionless wall as the grid's y- symmetry face (the study's --wall symmetry variant,
// docs/models/taylor-impact.md "Session 15": the variant that meets the 2 % budget at h = 0.5625 mm).
// The grid BCs act on the P2G velocity v_g as well as on v*_g, and the increment a_g dt is taken
// against the corrected v_g, so the wall node's normal velocity is never passed to the particles
// as an increment: no capture. Oracles: the same identity at every step to round-off; no contact
// (C = 0 exactly); the BCs remove nothing (B = 0 to round-off: v_g,y = 0 at the wall nodes before
// and after the forces); and at step 1 (sigma = 0: no node force) the particles keep their
// kinetic energy exactly (KE = KE0 to round-off), where the rigid wall's first step removes
// 1.5 (h/3)/L_seed of it (test above).
TEST(MpmEnergyLedger, SymmetryFaceWallCapturesNothingAndKeepsTheIdentity) {
  const std::string xml = a5_coarse_text("symmetry");
  ASSERT_FALSE(xml.empty());
  auto deck = load_deck_from_string(xml, "cylinderImpact_A_JC_h1_symmetry.ups",
                                    test::shared_dir() + "/decks/inputs/MPM/Impact");
  const double multiplier = deck->root.require_child("Time").get_double("timestep_multiplier");
  auto c = make_mpm_component(*deck);
  c->initialize();
  ASSERT_EQ(c->materials().size(), 1u);
  const std::set<std::string> labels = {"KineticEnergy", "ContactKineticEnergyRemoved",
                                           "BoundaryKineticEnergyRemoved", "GridForceWork",
                                           "TransferKineticEnergyLoss"};
  const double ke0 = c->reductions(labels).at("KineticEnergy")[0];
  EXPECT_NEAR(ke0, 58.687, 1e-3);  // the h = 1 mm seeded rod of the study (docs/models/taylor-impact.md)
  double t = 0, worst = 0, ke1 = 0, worst_boundary = 0, worst_contact = 0;
  int step = 0;
  while (t < 1e-6) {
    const double dt = std::min(multiplier * c->stable_timestep(), 1e-6 - t);
    c->advance(t, dt, ++step);
    t += dt;
    const auto r = c->reductions(labels);
    const double ke = r.at("KineticEnergy")[0];
    worst = std::max(worst, std::abs((ke - ke0) - (r.at("GridForceWork")[0] - r.at("ContactKineticEnergyRemoved")[0] -
                                                   r.at("BoundaryKineticEnergyRemoved")[0] -
                                                   r.at("TransferKineticEnergyLoss")[0])) / ke0);
    worst_contact = std::max(worst_contact, std::abs(r.at("ContactKineticEnergyRemoved")[0]));
    worst_boundary = std::max(worst_boundary, std::abs(r.at("BoundaryKineticEnergyRemoved")[0]) / ke0);
    if (step == 1) ke1 = ke;
  }
  std::printf("ledger A5 symmetry wall h = 1 mm, %d steps to 1 us: KE0 %.4f J, step-1 KE change %.2e KE0, max "
              "|identity residual| %.2e KE0, |B| <= %.2e KE0, |C| <= %.2e J\n",
              step, ke0, (ke1 - ke0) / ke0, worst, worst_boundary, worst_contact);
  EXPECT_LT(worst, 1e-11);
  EXPECT_EQ(worst_contact, 0.0);
  EXPECT_LT(worst_boundary, 1e-12);
  EXPECT_NEAR(ke1, ke0, 1e-12 * ke0);
}

}  // namespace
}  // namespace tephra
