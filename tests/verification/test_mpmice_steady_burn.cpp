// Steady_Burn in the coupled MPMICE step (mpmice/SteadyBurnModel.cpp) on
// MPMICE/massX.ups with its Simple_Burn block replaced by Steady_Burn (the
// WSB constants of SteadyBurn_2dRT.ups; IgnitionTemp 299 K below the gas's
// 300 K, ThresholdPressure 500 Pa, BoundaryParticles 3).
//
// Oracle: the cells Steady_Burn selects are the 8 cells of the cube (the
// only cells with particles; each a corner cell, min/max corner mass < 0.7;
// each next to a particle-free gas cell hotter than IgnitionTemp). At step 1
// the pressure is uniform (gas and solid at p_ref), so each burns
// dm = dt A m_WSB(p, T0 = 300 K, v_s) with A = dx^2 3^(1/6)/sqrt 3 (diagonal
// normal, as for Simple_Burn) and v_s the solid's specific volume; the total
// is 8 dm, m_WSB from wsb_burn_rate (its equations are checked in
// tests/unit/test_mpmice_steady_burn.cpp). Also: the particles lose exactly
// what the model reports, and the heat (Qc + Qg) dm goes to the product.
#include <gtest/gtest.h>

#include <cmath>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "mpmice/SteadyBurn.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

const char* kSteadyBurn = R"(<Models>
      <Model type="Steady_Burn">
        <fromMaterial> reactant </fromMaterial>
        <toMaterial>   product  </toMaterial>
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
        <ThresholdPressure>    500          </ThresholdPressure>
        <IgnitionTemp>         299.0        </IgnitionTemp>
      </Model>
    </Models>)";

TEST(MpmIceSteadyBurn, MassXBurnsAtTheWsbRate) {
  set_thread_count(1);
  std::string xml = test::slurp(test::shared_dir() + "/decks/inputs/MPMICE/massX.ups");
  const std::size_t a = xml.find("<Models>"), b = xml.find("</Models>");
  ASSERT_NE(a, std::string::npos);
  xml.replace(a, b + 9 - a, kSteadyBurn);
  auto deck = load_deck_from_string(xml, "massX_steady_burn.ups", test::shared_dir() + "/decks/inputs/MPMICE");
  deck->root.finalize_parents();
  auto c = make_mpmice_component(*deck);
  c->initialize();
  const SolidBurnModel* burn = nullptr;
  for (const IceModelP& m : c->ice().models()) burn = dynamic_cast<const SolidBurnModel*>(m.get());
  ASSERT_NE(burn, nullptr);
  ASSERT_EQ(burn->type(), "Steady_Burn");
  const Grid& g = c->ice().grid();
  // The state the model reads at step 1 (start of the step = initial state):
  // uniform pressure p_ref and the solid at rho0, v_s = 1/rho0.
  const double p = c->ice().press_CC()[0](4, 4, 4);
  double pmax = 0, pmin = 1e300;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    pmax = std::max(pmax, c->ice().press_CC()[0](i, j, k));
    pmin = std::min(pmin, c->ice().press_CC()[0](i, j, k));
  });
  ASSERT_LT(pmax / pmin - 1, 1e-12);
  const double vs = 1.0 / 1.1792946927374306;  // the deck's solid density
  double mp0 = 0;
  for (double m : c->mpm().materials()[0].particles.mass) mp0 += m;
  const double dt = 1e-4;
  c->advance(0.0, dt, 1);
  WsbParams w;
  w.R = 8.314, w.Ac = 1.637e15, w.Ec = 1.76e5, w.Bg = 1.6e-3, w.Qc = 4.0e5, w.Qg = 3.018e6;
  w.kg = 0.07, w.kc = 0.2, w.Cp = 1.4e3, w.W = 0.0342;
  const double dx = g.dx[0];
  const double A = dx * dx / std::sqrt(3.0) * std::cbrt(std::sqrt(3.0));
  const double expected = 8 * dt * A * wsb_burn_rate(w, p, 300.0, vs).mass_flux;
  // The equilibration pressure of step 1 equals the initial uniform p to
  // round-off, and the solid's v_s to ~1e-12: 1e-9 covers both.
  EXPECT_NEAR(burn->mass_burned_last_step(), expected, 1e-9 * expected);
  double mp1 = 0;
  for (double m : c->mpm().materials()[0].particles.mass) mp1 += m;
  // Round-off of the difference of two sums of 64 masses ~0.02 kg: 1e-14 mp0.
  EXPECT_NEAR(mp0 - mp1, burn->mass_burned_last_step(), 1e-14 * mp0);
  auto red = c->reductions({"totalHeatReleased"});
  EXPECT_NEAR(red["totalHeatReleased"][0], (4.0e5 + 3.018e6) * burn->mass_burned_last_step(), 1e-9 * red["totalHeatReleased"][0]);
}

}  // namespace
}  // namespace tephra
