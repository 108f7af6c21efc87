// The ICE starter decks (decks README A10, A11) in-process, and restart.
//
// advect.ups (A10): uniform air moving at (1,1,1) m/s with Neumann BCs. Every
// discrete operator of the step maps a uniform state to itself (face
// velocities = u, no pressure gradient, zero flux divergence of a uniform
// field, exchange idle), so rho, u, T, p stay uniform to round-off and
// KineticEnergy and TotalIntEng are constant to round-off.
//
// hotBlob2mat.ups (A11): two ideal gases, a 400 K blob at the centre of a 300 K
// box, exchange coefficients 1e10. Oracles: the Newton equilibration converges
// every step (else the run throws); with the box walls made reflecting
// (symmetry on every face, a test edit) nothing crosses the boundary, so the
// total mass is conserved to round-off and the total momentum stays 0 by the
// mirror symmetry of the problem about x, y, z = 0.5; the fields are
// symmetric under each mirror. Total energy (KE + internal) is not a discrete
// invariant of ICE (the internal-energy form with p dV work): its drift is
// bounded by the truncation error, here asserted below 1e-3 of the total.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/grid/Loop.h"
#include "core/io/OutputFrame.h"
#include "core/io/StateArchive.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

const std::set<std::string> kSums = {"KineticEnergy", "TotalMass", "TotalIntEng", "TotalMomentum"};

TEST(IceDecks, AdvectStaysUniformToRoundOff) {
  set_thread_count(1);  // tiny grids: loop-helper threads cost more than they save
  test::IceRun r = test::make_ice_run(test::shared_dir() + "/decks/inputs/ICE/advect.ups");
  auto s0 = r.ice->reductions(kSums);
  test::run_to(r);
  EXPECT_GE(r.steps, 7);
  auto s1 = r.ice->reductions(kSums);
  EXPECT_NEAR(s1["KineticEnergy"][0], s0["KineticEnergy"][0], 1e-12 * s0["KineticEnergy"][0]);
  EXPECT_NEAR(s1["TotalIntEng"][0], s0["TotalIntEng"][0], 1e-12 * s0["TotalIntEng"][0]);
  EXPECT_NEAR(s1["TotalMass"][0], s0["TotalMass"][0], 1e-12 * s0["TotalMass"][0]);
  const IceMaterialFields& f = r.ice->fields()[0];
  const double rho0 = 1.1792946927374306, p0 = 0.4 * rho0 * 716.0 * 300.0;
  double worst = 0;
  for_each_cell_serial(r.ice->grid().patches[0].cells_with_extra(), [&](int i, int j, int k) {
    worst = std::max(worst, std::abs(f.rho_CC[0](i, j, k) / rho0 - 1));
    worst = std::max(worst, std::abs(f.temp_CC[0](i, j, k) / 300.0 - 1));
    worst = std::max(worst, (f.vel_CC[0](i, j, k) - Vec3(1, 1, 1)).cwiseAbs().maxCoeff());
    worst = std::max(worst, std::abs(r.ice->press_CC()[0](i, j, k) / p0 - 1));
  });
  EXPECT_LT(worst, 1e-12);
}

// The Lagrangian labels (mass_L_CC, mom_L_CC, int_eng_L_CC; saved by the
// LightTime and rate-stick decks) on advect.ups: a uniform state has no
// pressure gradient and no dilatation, so eq. 26.8-26.10 give
// M_L = rho V, (Mu)_L = M u and (M e)_L = M c_v T exactly.
TEST(IceDecks, LagrangianLabelsOfAUniformFlow) {
  set_thread_count(1);
  test::IceRun r = test::make_ice_run(test::shared_dir() + "/decks/inputs/ICE/advect.ups");
  test::run_to(r, -1, 3);
  OutputFrame frame;
  r.ice->fill_output({"mass_L_CC", "mom_L_CC", "int_eng_L_CC"}, frame);
  ASSERT_EQ(frame.grid_fields.size(), 3u);
  const Grid& g = r.ice->grid();
  const double V = g.cell_volume(), rho = r.ice->fields()[0].rho_CC[0](2, 2, 2), M = rho * V;
  const double T = r.ice->fields()[0].temp_CC[0](2, 2, 2);
  const double expected[3] = {M, M * 1.0, M * 716.0 * T};  // advect.ups: u = (1,1,1), c_v = 716
  const long long interior = static_cast<long long>(g.cells.prod());
  for (int f = 0; f < 3; ++f) {
    const FieldArray& a = frame.grid_fields[f].data;
    long long hits = 0;
    for (double v : a.values)
      if (std::abs(v / expected[f] - 1) < 1e-12) ++hits;
    EXPECT_GE(hits, interior * a.components) << a.label;
  }
}

test::IceRun closed_hot_blob() {
  auto edit = [](DeckNode& root) {
    for (DeckNode& face : test::deck_node(root, {"Grid", "BoundaryConditions"}).children) {
      face.children.erase(face.children.begin() + 1, face.children.end());
      DeckNode& bc = face.children[0];
      bc.children.clear();
      bc.attributes = {{"id", "all"}, {"label", "Symmetric"}, {"var", "symmetry"}};
    }
  };
  return test::make_ice_run(test::shared_dir() + "/decks/inputs/ICE/hotBlob2mat.ups", edit);
}

TEST(IceDecks, HotBlobConservesMassMomentumAndIsSymmetric) {
  set_thread_count(1);
  test::IceRun r = closed_hot_blob();
  auto s0 = r.ice->reductions(kSums);
  test::run_to(r);
  auto s1 = r.ice->reductions(kSums);
  const double e0 = s0["KineticEnergy"][0] + s0["TotalIntEng"][0], e1 = s1["KineticEnergy"][0] + s1["TotalIntEng"][0];
  std::printf("hotBlob: %d steps, mass rel. change %.3g, |momentum| %.3g, energy rel. change %.3g, KE %.3g\n",
              r.steps, s1["TotalMass"][0] / s0["TotalMass"][0] - 1,
              Vec3(s1["TotalMomentum"][0], s1["TotalMomentum"][1], s1["TotalMomentum"][2]).norm(), e1 / e0 - 1,
              s1["KineticEnergy"][0]);
  EXPECT_NEAR(s1["TotalMass"][0], s0["TotalMass"][0], 1e-13 * s0["TotalMass"][0]);
  EXPECT_GT(s1["KineticEnergy"][0], 0.0);  // the blob did expand
  const double p_scale = s1["TotalMass"][0] * 400.0;  // mass x a speed scale: momentum round-off unit
  for (int d = 0; d < 3; ++d) EXPECT_LT(std::abs(s1["TotalMomentum"][d]), 1e-12 * p_scale);
  EXPECT_LT(std::abs(e1 / e0 - 1), 1e-3);
  // Mirror symmetry: cell i <-> 9 - i in each direction.
  const Grid& g = r.ice->grid();
  double worst = 0;
  for (const IceMaterialFields& f : r.ice->fields())
    for_each_cell_serial(g.interior_cells(), [&](int i, int j, int k) {
      const double a = f.rho_CC[0](i, j, k);
      worst = std::max({worst, std::abs(f.rho_CC[0](9 - i, j, k) - a) / a, std::abs(f.rho_CC[0](i, 9 - j, k) - a) / a,
                        std::abs(f.rho_CC[0](i, j, 9 - k) - a) / a, std::abs(f.rho_CC[0](k, i, j) - a) / a});
    });
  EXPECT_LT(worst, 1e-10);
}

// A checkpoint after step 4 restored into a fresh component continues bit
// for bit (DESIGN.md §2.9).
TEST(IceDecks, RestartContinuesBitForBit) {
  set_thread_count(1);
  const std::string deck = test::shared_dir() + "/decks/inputs/ICE/hotBlob2mat.ups";
  test::IceRun a = test::make_ice_run(deck);
  test::run_to(a, -1, 4);
  StateArchive ar;
  a.ice->save_state(ar);
  test::IceRun b = test::make_ice_run(deck);
  b.ice->load_state(ar);
  b.time = a.time;
  b.steps = a.steps;
  test::run_to(a, -1, 8);
  test::run_to(b, -1, 8);
  for (std::size_t m = 0; m < 2; ++m) {
    const auto& fa = a.ice->fields()[m].rho_CC[0];
    const auto& fb = b.ice->fields()[m].rho_CC[0];
    for (std::size_t i = 0; i < fa.size(); ++i) ASSERT_EQ(fa.data()[i], fb.data()[i]);
    const auto& ta = a.ice->fields()[m].temp_CC[0];
    const auto& tb = b.ice->fields()[m].temp_CC[0];
    for (std::size_t i = 0; i < ta.size(); ++i) ASSERT_EQ(ta.data()[i], tb.data()[i]);
  }
}

// The decks run unchanged through the executable (exit 0).
TEST(IceDecks, StarterDecksRunThroughTheExecutable) {
  const std::string dir = test::scratch_dir("ice_decks");
  for (const char* d : {"inputs/ICE/advect.ups", "inputs/ICE/hotBlob2mat.ups", "orderAccuracy/ICE/riemann.ups"}) {
    std::string out;
    EXPECT_EQ(test::run_tephra(test::shared_dir() + "/decks/" + d + " --quiet --threads 1 --output " + dir + "/" +
                                   std::to_string(std::hash<std::string>{}(d)), &out), 0)
        << d << "\n" << out;
  }
}

}  // namespace
}  // namespace tephra
