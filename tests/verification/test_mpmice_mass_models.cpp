// DDT0, Test and SolidReactionModel in the coupled MPMICE step
// (mpmice/Ddt0Model.cpp, TestMassModel.cpp, SolidReactionModel.cpp) on
// MPMICE/massX.ups (decks README A13: a 1 m^3 cube of solid, rho 1.179 kg/m^3,
// 64 particles, cells of 0.5 m, in gas at 300 K) with its <Models> replaced,
// in a closed box (faces made walls, as test_mpmice_burn.cpp does, so no gas
// crosses the faces).
//
// Oracles:
//  * Mass: TotalMass = sum p.mass + sum_fluid rho_CC V is constant to
//    round-off while the solid converts, and the particles lose exactly what
//    the model reports (ParticleBurn.cpp's per-cell rule).
//  * Test: the particles' share of a cell is its projected mass M_c
//    (ParticleBurn.cpp), so each step removes min(rate dt, 1) of the solid:
//    M(t_n) = M0 (1 - rate dt)^n (Uintah's TestModel law summed over cells).
//  * SolidReactionModel, NthOrder n = 1: dm_c = k f(F) dt (M_r + M_p) with
//    f = 1 - F = M_r/(M_r + M_p), so dm_c = k dt M_r,c and, with Ea = 0
//    (k = A), M(t_n) = M0 (1 - A dt)^n. With Ea = 2 R T0 in step 1, where the
//    solid is at T0 = 300 K: dm = A e^-2 dt M0.
//  * DDT0, deflagration (p < ThresholdPressureJWL): the Simple_Burn law on
//    the 8 surface cells of the cube, dm = dt A BurnCoeff (p/refPressure)^0.778
//    with A = dx^2/sqrt 3 x (sqrt 3)^(1/3) (test_mpmice_burn.cpp's oracle).
//  * DDT0, detonation (ThresholdPressureJWL below the ambient pressure, b = 0):
//    in each detonating cell delF = G (1 - F) dt with F = M_p/(M_r + M_p), so
//    dm_c = G dt M_r,c: a step burns at most G dt M(t) (the cells below
//    ThresholdVolFrac or past F = 0.99 do not detonate), and the cells that do
//    hold all but a measured small share of the solid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

constexpr double kDt = 1e-4;  // massX's delt_init and delt_max

struct ModelRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
  const SolidBurnModel* model = nullptr;
  double time = 0;
  int step = 0;
  void advance() {
    ++step;
    c->advance(time, kDt, step);
    time += kDt;
  }
};

ModelRun make_run(const std::string& models, const char* temperature = nullptr) {
  std::ifstream in(test::shared_dir() + "/decks/inputs/MPMICE/massX.ups");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  s = s.substr(0, s.find("<Models>")) + "<Models>" + models + s.substr(s.find("</Models>"));
  ModelRun r;
  r.deck = load_deck_from_string(s, "massX_models.ups", test::shared_dir() + "/decks/inputs/MPMICE");
  for (DeckNode& face : test::deck_node(r.deck->root, {"Grid", "BoundaryConditions"}).children)
    for (DeckNode& bc : face.children) {
      std::string label;
      for (auto& [k, v] : bc.attributes)
        if (k == "label") label = v;
      for (auto& [k, v] : bc.attributes)
        if (k == "var" && label == "Pressure") v = "Neumann";
        else if (k == "var" && label == "Velocity") v = "Dirichlet";
      if (label == "Pressure") bc.children.at(0).text = "0.0";
    }
  if (temperature) {
    test::deck_node(r.deck->root, {"MaterialProperties", "MPM", "material", "geom_object", "temperature"}).text = temperature;
    test::deck_node(r.deck->root, {"MaterialProperties", "ICE", "material", "geom_object", "temperature"}).text = temperature;
  }
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  for (const IceModelP& m : r.c->ice().models())
    if (auto* b = dynamic_cast<const SolidBurnModel*>(m.get())) r.model = b;
  return r;
}

double particle_mass(const MpmIceComponent& c) {
  double m = 0;
  for (double x : c.mpm().materials()[0].particles.mass) m += x;
  return m;
}

double total_mass(const MpmIceComponent& c) { return c.reductions({"TotalMass"})["TotalMass"][0]; }

std::string test_model(const char* rate, const char* start) {
  return std::string("<Model type=\"Test\"><Test><fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>"
                     "<rate>") + rate + "</rate><startTime>" + start + "</startTime></Test></Model>";
}

std::string srm_model(const char* A, const char* Ea) {
  return std::string("<Model type=\"SolidReactionModel\"><SolidReactionModel><fromMaterial>reactant</fromMaterial>"
                     "<toMaterial>product</toMaterial><E0>0</E0><RateConstantModel type=\"Arrhenius\"><A>") +
         A + "</A><Ea>" + Ea + "</Ea></RateConstantModel><RateModel type=\"NthOrder\"><n>1</n></RateModel>"
         "</SolidReactionModel></Model>";
}

std::string ddt0_model(const char* jwl, const char* burn_coeff, const char* G) {
  return std::string("<Model type=\"DDT0\"><DDT0><fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>"
                     "<ThresholdPressureJWL>") + jwl + "</ThresholdPressureJWL><G>" + G +
         "</G><b>0</b><E0>0</E0><Enthalpy>0</Enthalpy><BurnCoeff>" + burn_coeff +
         "</BurnCoeff><refPressure>1</refPressure><ThresholdTemp>299</ThresholdTemp>"
         "<ThresholdPressureSB>500</ThresholdPressureSB></DDT0></Model>";
}

// First-order loss M(t_n) = M0 (1 - k dt)^n, and TotalMass constant.
void expect_first_order(ModelRun& r, double k, int steps) {
  ASSERT_NE(r.model, nullptr);
  const double M0 = total_mass(*r.c), mp0 = particle_mass(*r.c);
  double burned = 0;
  for (int n = 1; n <= steps; ++n) {
    r.advance();
    burned += r.model->mass_burned_last_step();
    const double expected = mp0 * std::pow(1 - k * kDt, n);
    // Round-off: sums over 64 particles and 1000 cells (measured below 1e-14 relative).
    EXPECT_NEAR(particle_mass(*r.c), expected, 1e-12 * mp0) << "step " << n;
    EXPECT_NEAR(total_mass(*r.c), M0, 1e-13 * M0) << "step " << n;
  }
  EXPECT_NEAR(mp0 - particle_mass(*r.c), burned, 1e-13 * mp0);
}

TEST(MpmIceMassModels, TestModelRemovesRateDtOfTheSolidPerStep) {
  set_thread_count(1);
  ModelRun r = make_run(test_model("1000", "0"));  // rate dt = 0.1
  expect_first_order(r, 1000.0, 5);
}

TEST(MpmIceMassModels, TestModelStartsAtStartTime) {
  set_thread_count(1);
  ModelRun r = make_run(test_model("1000", "2.5e-4"));
  const double mp0 = particle_mass(*r.c);
  for (int n = 1; n <= 3; ++n) r.advance();  // steps starting at t = 0, 1e-4, 2e-4 < startTime
  EXPECT_EQ(particle_mass(*r.c), mp0);
  for (int n = 4; n <= 5; ++n) r.advance();  // t = 3e-4, 4e-4: two steps of 10 %
  EXPECT_NEAR(particle_mass(*r.c), mp0 * 0.81, 1e-12 * mp0);
}

TEST(MpmIceMassModels, SolidReactionFirstOrderFollowsItsIntegral) {
  set_thread_count(1);
  ModelRun r = make_run(srm_model("1000", "0"));  // k = A = 1000/s, k dt = 0.1
  expect_first_order(r, 1000.0, 5);
}

TEST(MpmIceMassModels, SolidReactionArrheniusRateAtTheSolidTemperature) {
  set_thread_count(1);
  const double R = 8.314462175, T0 = 300, A = 1000;
  const std::string Ea = std::to_string(2 * R * T0);  // k = A e^-2 at T0 (to_string: 6 decimals)
  ModelRun r = make_run(srm_model("1000", Ea.c_str()));
  const double mp0 = particle_mass(*r.c);
  r.advance();
  const double k = A * std::exp(-std::stod(Ea) / (R * T0));
  // The solid's cell temperature in step 1 is T0 to round-off (measured 1e-13 relative).
  EXPECT_NEAR(mp0 - particle_mass(*r.c), k * kDt * mp0, 1e-10 * k * kDt * mp0);
}

TEST(MpmIceMassModels, Ddt0DeflagrationIsTheSimpleBurnLaw) {
  set_thread_count(1);
  ModelRun r = make_run(ddt0_model("1e9", "1e-3", "1"));
  ASSERT_NE(r.model, nullptr);
  const double mp0 = particle_mass(*r.c);
  r.advance();
  const Grid& g = r.c->ice().grid();
  const double dx = g.dx[0];
  int cells = 0;
  double expected = 0;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    if (!(i >= 4 && i <= 5 && j >= 4 && j <= 5 && k >= 4 && k <= 5)) return;
    ++cells;
    const double p = r.c->ice().press_equil_CC()[0](i, j, k);
    const double A = dx * dx / std::sqrt(3.0) * std::cbrt(std::sqrt(3.0));
    expected += kDt * A * 1e-3 * std::pow(p / 1.0, 0.778);
  });
  ASSERT_EQ(cells, 8);
  EXPECT_NEAR(r.model->mass_burned_last_step(), expected, 1e-12 * expected);
  EXPECT_NEAR(mp0 - particle_mass(*r.c), expected, 1e-12 * expected);
}

TEST(MpmIceMassModels, Ddt0DeflagrationConservesTotalMass) {
  set_thread_count(1);
  ModelRun r = make_run(ddt0_model("1e9", "1", "1"));
  const double M0 = total_mass(*r.c), mp0 = particle_mass(*r.c);
  double burned = 0;
  for (int n = 1; n <= 5; ++n) {
    r.advance();
    burned += r.model->mass_burned_last_step();
    EXPECT_NEAR(total_mass(*r.c), M0, 1e-13 * M0) << "step " << n;
  }
  EXPECT_GT(burned, 0.5 * mp0);
  EXPECT_NEAR(mp0 - particle_mass(*r.c), burned, 1e-13 * mp0);
}

TEST(MpmIceMassModels, Ddt0DetonationBurnsGDtOfTheDetonatingSolid) {
  set_thread_count(1);
  ModelRun r = make_run(ddt0_model("1", "0", "1000"));  // every cell with theta_r > 0.01 detonates; G dt = 0.1
  const double M0 = total_mass(*r.c);
  for (int n = 1; n <= 5; ++n) {
    const double before = particle_mass(*r.c);
    r.advance();
    const double dm = before - particle_mass(*r.c);
    EXPECT_NEAR(dm, r.model->mass_burned_last_step(), 1e-13 * before);
    // Every cell holding reactant detonates (b = 0, no cell past F = 0.99, the
    // 20 % cap not reached with G dt = 0.1): dm_c = G dt (1 - F)(M_r + M_p) and
    // F = rho_p/(rho_r + rho_p) in the one cell volume give (1 - F)(M_r + M_p)
    // = M_r, so the step burns G dt of the whole solid; the cell sum of
    // products rounds to ~1e-14 of it (measured 1.3e-14 .. 1.8e-14).
    std::printf("DDT0 detonation step %d: dm/(G dt M) = %.15f\n", n, dm / (0.1 * before));
    EXPECT_NEAR(dm, 0.1 * before, 1e-13 * before) << "step " << n;
    EXPECT_NEAR(total_mass(*r.c), M0, 1e-13 * M0) << "step " << n;
  }
}

}  // namespace
}  // namespace tephra
