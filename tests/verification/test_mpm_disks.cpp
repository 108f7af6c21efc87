// The colliding-disks deck (inputs/mpm/disks.ups) run in-process with the
// deck's time-step rule: dt = min(timestep_multiplier * stable dt, delt_max).
//
// Oracles:
//  * TotalMass is the sum of constant particle masses: equal to the bit.
//  * TotalMomentum: the internal forces sum to zero over the nodes and no
//    particle touches a wall node before t = 2 (the disks start 0.05 from the
//    walls, move inward, and are back near their start at t = 2), so
//    sum m v changes only by round-off; it starts at 0 (point-symmetric disks).
//  * CenterOfMassPosition: with zero momentum it stays at the symmetry centre
//    (0.5, 0.5, 0.025).
//  * Energy: before contact (t < 0.6, the gap closes at ~0.3 / 0.283 s^-1 ~ 1.08 s
//    minus the 0.05-cell reach of the shape functions) the disks translate
//    rigidly, the stress is 0, a_g = 0 and FLIP leaves v unchanged, so KE is
//    constant to round-off and SE = 0. Through the impact, explicit MPM with one
//    velocity field is not energy conserving: the nodes shared by both disks
//    average their velocities (an inelastic projection), which removes energy;
//    it should not add any beyond the O(dt) error of the forward-Euler grid
//    update (the step is 0.2 of the CFL limit). Bounds: KE + SE within
//    [0.9, 1.01] E0; at maximum compression most of E0 is strain energy (> 0.8 E0).
//
// Limitation (reported): run on to the deck's maxTime = 3, the particle at the
// disk edge that re-enters a node's support with a tiny weight gets a huge v*_g
// (a = f_int / m_g with m_g -> 0: the cell-crossing weakness of linear-shape
// USL) and the run stops at t ~ 2.5 with det F < 0. This test therefore stops at t = 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

TEST(MpmDisks, ConservesMassMomentumCentreOfMassAndBoundsEnergy) {
  auto deck = load_deck(test::source_dir() + "/inputs/mpm/disks.ups");
  const DeckNode& time = deck->root.require_child("Time");
  const double multiplier = time.get_double("timestep_multiplier");
  const double delt_max = time.get_double("delt_max");
  auto c = make_mpm_component(*deck);
  c->initialize();
  const std::set<std::string> labels = {"KineticEnergy", "StrainEnergy", "TotalMass", "TotalMomentum",
                                        "CenterOfMassPosition"};
  auto r0 = c->reductions(labels);
  const double m0 = r0["TotalMass"][0];
  const double e0 = r0["KineticEnergy"][0];
  // 0.5 m |v|^2 with |v|^2 = 0.02 for every particle; a sum of 832 terms
  // carries up to ~n eps ~ 1e-13 relative round-off.
  EXPECT_NEAR(e0, 0.5 * m0 * 0.02, 1e-13 * e0);
  const double momentum_scale = m0 * std::sqrt(0.02);  // sum m |v|
  double t = 0, max_se = 0;
  int step = 0;
  while (t < 2.0) {
    const double dt = std::min(multiplier * c->stable_timestep(), delt_max);
    c->advance(t, dt, ++step);
    t += dt;
    auto r = c->reductions(labels);
    EXPECT_EQ(r["TotalMass"][0], m0) << "step " << step;
    const Vec3 p(r["TotalMomentum"][0], r["TotalMomentum"][1], r["TotalMomentum"][2]);
    EXPECT_LT(p.norm(), 1e-14 * momentum_scale) << "step " << step;
    const Vec3 com(r["CenterOfMassPosition"][0], r["CenterOfMassPosition"][1], r["CenterOfMassPosition"][2]);
    EXPECT_LT((com - Vec3(0.5, 0.5, 0.025)).norm(), 1e-13) << "step " << step;
    const double ke = r["KineticEnergy"][0], se = r["StrainEnergy"][0];
    if (t < 0.6) {
      EXPECT_NEAR(ke, e0, 1e-13 * e0) << "step " << step;
      EXPECT_EQ(se, 0.0) << "step " << step;
    }
    EXPECT_GT(ke + se, 0.9 * e0) << "step " << step;
    EXPECT_LT(ke + se, 1.01 * e0) << "step " << step;
    max_se = std::max(max_se, se);
  }
  EXPECT_GT(max_se, 0.8 * e0);
  EXPECT_GT(step, 200);
}

}  // namespace
}  // namespace tephra
