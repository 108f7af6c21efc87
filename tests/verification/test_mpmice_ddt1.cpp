// DDT1 and Unsteady_Burn in the coupled MPMICE step on MPMICE/massX.ups with
// its Simple_Burn block replaced (the WSB constants of BurnRate.ups;
// IgnitionTemp 299 K below the gas's 300 K, BoundaryParticles 3).
//
// Oracles (the cube's 8 cells are the only cells with particles; at step 1
// the pressure is uniform, p_ref, as test_mpmice_steady_burn checks):
//  * DDT1 below ThresholdPressureJWL (1e12 Pa) burns as Steady_Burn: step-1
//    mass = 8 dt A m_WSB(p, 300 K, v_s), A = dx^2 3^(1/6)/sqrt 3;
//  * DDT1 with ThresholdPressureJWL = 5e4 Pa < p_ref: every cell with
//    theta_r > 0.01 detonates (JWL++): delF_c = G p_c^b (1 - F_c) dt with
//    F_c = M_p/(M_r + M_p), and the burned mass is sum_c delF_c (M_r + M_p)
//    = sum_c delF_c M_p,c/F_c (M_p,c the product's cell mass, which the
//    equilibration does not change); heat released E0 x burned mass;
//  * both branches conserve the total mass (particles + cells) in a closed
//    box to round-off, and the particles lose exactly the burned mass;
//  * Unsteady_Burn: a fresh surface burns at the steady WSB rate (step 1 as
//    Steady_Burn); its cells count their burning steps (1, 2) and keep the
//    surface temperature of the WSB solution.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "mpmice/SteadyBurn.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

std::string wsb_block() {
  return R"(
        <IdealGasConst>        8.314        </IdealGasConst>
        <PreExpCondPh>         1.637e15     </PreExpCondPh>
        <ActEnergyCondPh>      1.76e5       </ActEnergyCondPh>
        <PreExpGasPh>          1.6e-3       </PreExpGasPh>
        <CondPhaseHeat>        4.0e5        </CondPhaseHeat>
        <GasPhaseHeat>         3.018e6      </GasPhaseHeat>
        <HeatConductGasPh>     0.07         </HeatConductGasPh>
        <HeatConductCondPh>    0.2          </HeatConductCondPh>
        <SpecificHeatBoth>     1.4e3        </SpecificHeatBoth>
        <MoleWeightGasPh>      0.0342       </MoleWeightGasPh>
        <BoundaryParticles>    3            </BoundaryParticles>
        <IgnitionTemp>         299.0        </IgnitionTemp>)";
}

std::string ddt1_model(const char* jwl_threshold) {
  return std::string(R"(<Models><Model type="DDT1">
        <fromMaterial> reactant </fromMaterial>
        <toMaterial>   product  </toMaterial>
        <G> 2.33e-6 </G> <b> 1.2 </b> <rho0> 1832.0 </rho0> <E0> 5.0e6 </E0>
        <ThresholdPressureJWL> )") +
         jwl_threshold + "</ThresholdPressureJWL>\n<ThresholdPressureSB> 500 </ThresholdPressureSB>" + wsb_block() +
         "</Model></Models>";
}

// DDT1 with <useInductionTime>: S_f = Fb (p/PS)^Fc with PS = p_ref and
// Fc = 1, IgnitionConst IC.
std::string ddt1_induction_model(const char* Fb, const char* IC) {
  return std::string(R"(<Models><Model type="DDT1">
        <fromMaterial> reactant </fromMaterial>
        <toMaterial>   product  </toMaterial>
        <G> 2.33e-6 </G> <b> 1.2 </b> <E0> 5.0e6 </E0>
        <ThresholdPressureJWL> 1e12 </ThresholdPressureJWL>
        <ThresholdPressureSB> 500 </ThresholdPressureSB>
        <useInductionTime> true </useInductionTime>
        <IgnitionConst> )") + IC + "</IgnitionConst>\n<PressureShift> 101325 </PressureShift>\n<PreexpoConst> " + Fb +
         "</PreexpoConst>\n<ExponentialConst> 1 </ExponentialConst>" + wsb_block() + "</Model></Models>";
}

std::string unsteady_model() {
  return std::string(R"(<Models><Model type="Unsteady_Burn">
        <fromMaterial> reactant </fromMaterial>
        <toMaterial>   product  </toMaterial>
        <BurnrateModCoef> 1.0 </BurnrateModCoef>
        <CondUnsteadyCoef> 2.0 </CondUnsteadyCoef>
        <GasUnsteadyCoef> 1.5 </GasUnsteadyCoef>
        <ThresholdPressure> 500 </ThresholdPressure>)") +
         wsb_block() + "</Model></Models>";
}

struct BurnRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<MpmIceComponent> c;
  const SolidBurnModel* burn = nullptr;
};

BurnRun make_run(const std::string& models, bool closed) {
  BurnRun r;
  std::string xml = test::slurp(test::shared_dir() + "/decks/inputs/MPMICE/massX.ups");
  const std::size_t a = xml.find("<Models>"), b = xml.find("</Models>");
  xml.replace(a, b + 9 - a, models);
  r.deck = load_deck_from_string(xml, "massX_ddt1.ups", test::shared_dir() + "/decks/inputs/MPMICE");
  if (closed)  // walls: u = 0 Dirichlet, pressure Neumann (as test_mpmice_burn)
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
  r.deck->root.finalize_parents();
  r.c = make_mpmice_component(*r.deck);
  r.c->initialize();
  for (const IceModelP& m : r.c->ice().models())
    if (auto* s = dynamic_cast<const SolidBurnModel*>(m.get())) r.burn = s;
  return r;
}

double particle_mass(const MpmIceComponent& c) {
  double m = 0;
  for (double x : c.mpm().materials()[0].particles.mass) m += x;
  return m;
}

const CellScalars& field(const SolidBurnModel& m, const std::string& label) {
  for (const ModelField& f : m.fields())
    if (f.label == label) return *f.field;
  throw std::runtime_error("no field " + label);
}

WsbParams hmx() {
  WsbParams w;
  w.R = 8.314, w.Ac = 1.637e15, w.Ec = 1.76e5, w.Bg = 1.6e-3, w.Qc = 4.0e5, w.Qg = 3.018e6;
  w.kg = 0.07, w.kc = 0.2, w.Cp = 1.4e3, w.W = 0.0342;
  return w;
}

// Step 1 of a WSB surface burn on the cube's 8 corner cells (see
// test_mpmice_steady_burn): 8 dt A m_WSB(p_ref, 300 K, 1/rho_s).
double expected_step1_wsb_mass(const BurnRun& r, double dt) {
  const double p = r.c->ice().press_CC()[0](4, 4, 4);
  const double vs = 1.0 / 1.1792946927374306;  // the deck's solid density
  const double dx = r.c->ice().grid().dx[0];
  const double A = dx * dx / std::sqrt(3.0) * std::cbrt(std::sqrt(3.0));
  return 8 * dt * A * wsb_burn_rate(hmx(), p, 300.0, vs).mass_flux;
}

TEST(MpmIceDdt1, BelowTheJwlThresholdItBurnsAtTheWsbRate) {
  set_thread_count(1);
  BurnRun r = make_run(ddt1_model("1e12"), false);
  ASSERT_NE(r.burn, nullptr);
  ASSERT_EQ(r.burn->type(), "DDT1");
  const double expected = expected_step1_wsb_mass(r, 1e-4);
  const double mp0 = particle_mass(*r.c);
  r.c->advance(0.0, 1e-4, 1);
  // As test_mpmice_steady_burn: p and v_s of step 1 equal the initial ones to ~1e-12.
  EXPECT_NEAR(r.burn->mass_burned_last_step(), expected, 1e-9 * expected);
  EXPECT_NEAR(mp0 - particle_mass(*r.c), r.burn->mass_burned_last_step(), 1e-14 * mp0);
  const CellScalars& burning = field(*r.burn, "burning");
  EXPECT_EQ(burning[0](4, 4, 4), 2.0);  // Vaango's CONDUCTIVE
  EXPECT_EQ(field(*r.burn, "detonating")[0](4, 4, 4), 0.0);
  auto red = r.c->reductions({"totalHeatReleased"});
  EXPECT_NEAR(red["totalHeatReleased"][0], (4.0e5 + 3.018e6) * r.burn->mass_burned_last_step(),
              1e-12 * red["totalHeatReleased"][0]);
}

TEST(MpmIceDdt1, AboveTheJwlThresholdItDetonatesAtTheJwlppRate) {
  set_thread_count(1);
  BurnRun r = make_run(ddt1_model("5e4"), false);
  ASSERT_NE(r.burn, nullptr);
  const Grid& g = r.c->ice().grid();
  const double V = g.cell_volume(), dt = 1e-6;
  const CellScalars product_rho = r.c->ice().fields()[1].rho_CC;  // before the step
  r.c->advance(0.0, dt, 1);
  const CellScalars& F = field(*r.burn, "F");
  const CellScalars& delF = field(*r.burn, "delF");
  const CellScalars& det = field(*r.burn, "detonating");
  const CellScalars& theta_r = r.c->ice().fields()[0].vol_frac_CC;  // this step's equilibration
  double expected = 0;
  int cells = 0;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    const double p = r.c->ice().press_equil_CC()[0](i, j, k);
    if (det[0](i, j, k) == 0) {
      EXPECT_LE(theta_r[0](i, j, k), 0.01 + 1e-12) << i << j << k;
      return;
    }
    ++cells;
    EXPECT_GT(theta_r[0](i, j, k), 0.01);
    EXPECT_GT(F[0](i, j, k), 0.0);
    const double want = 2.33e-6 * std::pow(p, 1.2) * (1 - F[0](i, j, k)) * dt;
    EXPECT_NEAR(delF[0](i, j, k), want, 1e-13 * want);
    expected += delF[0](i, j, k) * product_rho[0](i, j, k) * V / F[0](i, j, k);
  });
  EXPECT_GT(cells, 8);  // the smeared solid reaches beyond the cube's cells
  EXPECT_NEAR(r.burn->mass_burned_last_step(), expected, 1e-12 * expected);
  auto red = r.c->reductions({"totalHeatReleased"});
  EXPECT_NEAR(red["totalHeatReleased"][0], 5.0e6 * expected, 1e-12 * 5.0e6 * expected);
}

// Both branches: total mass (particles + cells) constant to round-off in a
// closed box over 5 steps, the particles lose exactly the burned mass.
void expect_mass_conserved(const std::string& models, double dt, const char* what) {
  set_thread_count(1);
  BurnRun r = make_run(models, true);
  ASSERT_NE(r.burn, nullptr);
  const std::set<std::string> sums = {"TotalMass"};
  const double M0 = r.c->reductions(sums)["TotalMass"][0];
  const double mp0 = particle_mass(*r.c);
  double burned = 0, t = 0;
  for (int step = 1; step <= 5; ++step) {
    r.c->advance(t, dt, step);
    t += dt;
    burned += r.burn->mass_burned_last_step();
    EXPECT_NEAR(r.c->reductions(sums)["TotalMass"][0], M0, 1e-13 * M0) << what << " step " << step;
  }
  EXPECT_GT(burned, 1e-6 * mp0) << what;
  EXPECT_NEAR(mp0 - particle_mass(*r.c), burned, 1e-14 * mp0) << what;
}

TEST(MpmIceDdt1, ConservesMassInAClosedBoxInBothBranches) {
  expect_mass_conserved(ddt1_model("1e12"), 1e-4, "deflagration");
  expect_mass_conserved(ddt1_model("5e4"), 1e-6, "detonation");
}

TEST(MpmIceUnsteadyBurn, FreshSurfaceBurnsAtTheSteadyRateThenCountsItsSteps) {
  set_thread_count(1);
  BurnRun r = make_run(unsteady_model(), true);
  ASSERT_NE(r.burn, nullptr);
  ASSERT_EQ(r.burn->type(), "Unsteady_Burn");
  const double expected = expected_step1_wsb_mass(r, 1e-4);
  const double p = r.c->ice().press_CC()[0](4, 4, 4);
  r.c->advance(0.0, 1e-4, 1);
  EXPECT_NEAR(r.burn->mass_burned_last_step(), expected, 1e-9 * expected);
  const CellScalars& count = field(*r.burn, "UnsteadyBurn.BurningCell");
  const CellScalars& Ts = field(*r.burn, "UnsteadyBurn.SurfTemp");
  EXPECT_EQ(count[0](4, 4, 4), 1.0);
  const double Ts_wsb = wsb_burn_rate(hmx(), p, 300.0, 1.0 / 1.1792946927374306).surface_temperature;
  EXPECT_NEAR(Ts[0](4, 4, 4), Ts_wsb, 1e-9 * Ts_wsb);
  r.c->advance(1e-4, 1e-4, 2);
  EXPECT_EQ(count[0](4, 4, 4), 2.0);
  EXPECT_GT(r.burn->mass_burned_last_step(), 0.0);
}

TEST(MpmIceUnsteadyBurn, ConservesMassInAClosedBox) { expect_mass_conserved(unsteady_model(), 1e-4, "unsteady"); }


// <useInductionTime> on massX (open faces as BelowTheJwlThreshold...). The
// cube's 8 cells are ignited surface cells from step 1 (hot gas beside them);
// each holds its own solid at 300 K > IgnitionTemp with theta > 0.2, so
// Uintah's rule sets theta = 0 and A = IC: the induction time is
//   tau = dx_mean IC / S_f,  S_f = Fb p/p_ref,
// constant while nothing burns (p = p_ref, quiescent), and, started at
// Uintah's first-step sentinel, tau_k = tau in every step (0.2 tau + 0.8 tau).
// The exposure time after step k is k dt, so the first burning step is the
// first k with k dt >= tau: with tau = 4.5 dt, steps 1-4 burn nothing (the
// cells are "warming up", burning = 1, countTime = k dt) and step 5 burns what
// step 1 burns without induction, 8 dt A m_WSB (the state is unchanged until
// then: p and v_s of step 5 equal the initial ones to round-off).
TEST(MpmIceDdt1, InductionTimeDelaysTheIgnitionByTau) {
  set_thread_count(1);
  const double dt = 1e-4, dx = 0.5, IC = 0.5, tau = 4.5 * dt;
  const double Fb = dx * IC / tau;  // S_f at p = p_ref
  char fb[64];
  std::snprintf(fb, sizeof fb, "%.17g", Fb);
  BurnRun r = make_run(ddt1_induction_model(fb, "0.5"), false);
  ASSERT_NE(r.burn, nullptr);
  const double expected = expected_step1_wsb_mass(r, dt);
  const double p0 = r.c->ice().press_CC()[0](4, 4, 4);
  const double mp0 = particle_mass(*r.c);
  const CellScalars& burning = field(*r.burn, "burning");
  const CellScalars& induction = field(*r.burn, "inductionTime");
  const CellScalars& count = field(*r.burn, "countTime");
  const double tau_p = dx * IC / (Fb * p0 / 101325.0);  // p0 = p_ref to round-off
  for (int k = 1; k <= 4; ++k) {
    r.c->advance((k - 1) * dt, dt, k);
    EXPECT_EQ(r.burn->mass_burned_last_step(), 0.0) << "step " << k;
    EXPECT_EQ(particle_mass(*r.c), mp0) << "step " << k;
    for (int c = 0; c < 8; ++c) {
      const IntVec3 cell(4 + (c & 1), 4 + ((c >> 1) & 1), 4 + ((c >> 2) & 1));
      EXPECT_EQ(burning[0](cell), 1.0) << "warming up, step " << k;  // Uintah's WARMINGUP
      // p of steps 1-4 equals p_ref to ~1e-12 (nothing burns, nothing moves).
      EXPECT_NEAR(induction[0](cell), tau_p, 1e-10 * tau_p) << "step " << k;
      EXPECT_NEAR(count[0](cell), k * dt, 1e-15) << "step " << k;
    }
  }
  r.c->advance(4 * dt, dt, 5);
  EXPECT_NEAR(r.burn->mass_burned_last_step(), expected, 1e-9 * expected);
  EXPECT_NEAR(mp0 - particle_mass(*r.c), r.burn->mass_burned_last_step(), 1e-14 * mp0);
  EXPECT_EQ(burning[0](4, 4, 4), 2.0);  // CONDUCTIVE
  // Once burning the cell carries tau and counts on.
  r.c->advance(5 * dt, dt, 6);
  EXPECT_EQ(burning[0](4, 4, 4), 2.0);
  EXPECT_NEAR(count[0](4, 4, 4), 6 * dt, 1e-15);
  EXPECT_GT(r.burn->mass_burned_last_step(), 0.0);
}

// The same with IC = 1 (A = 1 for any angle) and tau = 2.5 dt: the first burn
// comes at step 3.
TEST(MpmIceDdt1, InductionTimeScalesWithTheIgnitionConstant) {
  set_thread_count(1);
  const double dt = 1e-4, dx = 0.5;
  char fb[64];
  std::snprintf(fb, sizeof fb, "%.17g", dx * 1.0 / (2.5 * dt));
  BurnRun r = make_run(ddt1_induction_model(fb, "1"), false);
  ASSERT_NE(r.burn, nullptr);
  const double expected = expected_step1_wsb_mass(r, dt);
  for (int k = 1; k <= 2; ++k) {
    r.c->advance((k - 1) * dt, dt, k);
    EXPECT_EQ(r.burn->mass_burned_last_step(), 0.0) << "step " << k;
  }
  r.c->advance(2 * dt, dt, 3);
  EXPECT_NEAR(r.burn->mass_burned_last_step(), expected, 1e-9 * expected);
}

}  // namespace
}  // namespace tephra
