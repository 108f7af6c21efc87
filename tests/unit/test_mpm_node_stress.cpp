// g.stressFS is summed only when something reads it (NodeGrid::node_stress,
// mpm/Transfers.h). Claims:
//   * with node_stress = false the grid's stress array stays empty and every
//     other P2G sum (m_g, V_g, v_g, f_ext,g) and the internal force are the
//     same bits as with node_stress = true (the stress sums are independent);
//   * with node_stress = true, sigma_g of a uniformly stressed cloud is that
//     stress (sum V_p sigma S / sum V_p S = sigma) at every node with V_g > 0;
//   * the deck reader turns it on only when the deck saves g.stressFS.
#include <gtest/gtest.h>

#include <random>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "mpm/Transfers.h"

namespace tephra {
namespace {

TEST(MpmNodeStress, SkippedSumsLeaveTheOthersUnchanged) {
  NodeGrid on;
  on.origin = Vec3(0.0, 0.0, 0.0);
  on.h = Vec3(0.1, 0.1, 0.1);
  on.n = IntVec3(10, 9, 8);
  NodeGrid off = on;
  off.node_stress = false;
  on.reset();
  off.reset();
  EXPECT_TRUE(off.stress.empty());
  EXPECT_EQ(on.stress.size(), on.count());
  Particles p;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Mat3 sigma;
  sigma << 1.0, 2.0, 3.0, 2.0, -4.0, 5.0, 3.0, 5.0, 6.0;
  for (int i = 0; i < 5000; ++i) {
    p.add(Vec3((1.5 + 6 * u(rng)) * 0.1, (1.5 + 5 * u(rng)) * 0.1, (1.5 + 4 * u(rng)) * 0.1),
          Vec3(u(rng), -u(rng), u(rng)), 1.0 + u(rng), 1e-3 * (1.0 + u(rng)), 300.0, 0.0, i, Mat3::Identity() * 0.5);
    p.stress.back() = sigma;
  }
  Stencils s;
  ASSERT_TRUE(compute_axis_stencils(p, on, {InterpolatorKind::Gimp, 1e10}, s));
  particles_to_grid(p, s, Vec3(0.0, 0.0, -9.81), on);
  particles_to_grid(p, s, Vec3(0.0, 0.0, -9.81), off);
  compute_internal_force(p, s, on);
  compute_internal_force(p, s, off);
  EXPECT_TRUE(off.stress.empty());
  EXPECT_EQ(on.mass, off.mass);
  EXPECT_EQ(on.volume, off.volume);
  EXPECT_EQ(on.velocity, off.velocity);
  EXPECT_EQ(on.external_force, off.external_force);
  EXPECT_EQ(on.internal_force, off.internal_force);
  std::size_t filled = 0;
  for (std::size_t n = 0; n < on.count(); ++n)
    if (on.volume[n] > 0.0) {
      EXPECT_LE((on.stress[n] - sigma).cwiseAbs().maxCoeff(), 1e-13 * sigma.cwiseAbs().maxCoeff()) << n;
      ++filled;
    }
  EXPECT_GT(filled, 100u);
}

std::string deck(const std::string& save) {
  return "<Uintah_specification><DataArchiver><save label='" + save +
         "'/></DataArchiver><MPM><interpolator>gimp</interpolator></MPM>"
         "<MaterialProperties><MPM><material><density>1000</density>"
         "<constitutive_model type='hypo_elastic'><G>1e6</G><K>2e6</K>"
         "</constitutive_model><thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
         "<geom_object><box><min>[0.1,0.1,0.1]</min><max>[0.3,0.4,0.2]</max></box><res>[2,2,2]</res>"
         "<velocity>[1,0,0]</velocity><temperature>300</temperature></geom_object></material></MPM>"
         "</MaterialProperties><Grid><Level><Box><lower>[0,0,0]</lower><upper>[0.5,0.5,0.5]</upper>"
         "<resolution>[5,5,5]</resolution><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box></Level>"
         "</Grid></Uintah_specification>";
}

TEST(MpmNodeStress, OnlyWhenTheDeckSavesIt) {
  for (bool saved : {false, true}) {
    auto d = load_deck_from_string(deck(saved ? "g.stressFS" : "g.mass"), "node_stress.ups", ".");
    auto c = make_mpm_component(*d);
    EXPECT_EQ(c->setup().node_stress, saved);
    c->initialize();
    c->advance(0.0, 1e-6, 1);
    EXPECT_EQ(c->materials().front().grid.stress.size(), saved ? c->materials().front().grid.count() : 0u);
  }
}

}  // namespace
}  // namespace tephra
