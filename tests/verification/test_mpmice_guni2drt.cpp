// MPMICE/guni2dRT.ups (decks README A14), the unchanged deck: a quarter of a
// steel cylinder (elastic_plastic_hp, r 50.8-57.15 mm) filled with PBX 9501
// (visco_scram) at 600 K > ThresholdTemp 450 K, so Simple_Burn turns the PBX
// surface into product gas from the first step; 51 x 51 x 1 cells of 1.69 mm,
// every face closed (symmetry planes, or u = 0 and zero pressure gradient).
//
// Before this test the deck stopped with exit 4: at step 0 in the cells
// filled by steel and PBX (equilibration: a round-off limit cycle, see
// tests/unit/test_ice_equilibration_stiff.cpp), at step 5 with a negative
// specific volume of the trace air inside the steel (second-order content
// fluxes, ice/IceAdvectContent.cpp), at step 19 with sp_vol = inf of an
// expanded PBX at 1e-12 Pa (test_mpmice_solid_eos_low_pressure.cpp).
//
// Oracles over the first 20 steps (of the deck's 61; t = 1.1 us):
//  * mass: the box is closed, the particles lose exactly what the product
//    gains (ParticleBurn.cpp), so TotalMass = sum p.mass + sum_fluid rho_CC V
//    is constant to round-off (sums over 7.2k particles and 2.7k cells);
//  * the particles' loss = sum of totalMassBurned over the steps (round-off of
//    the particle mass sums);
//  * the rate law, step by step: totalMassBurned = sum over the burning cells
//    of dt A_c BurnCoeff (p_c/refPressure)^0.778 (A_c the cell's burning
//    area, the model's SimpleBurn.onSurface field; p_c = press_equil_CC;
//    BurnCoeff 75.3, refPressure 101325): the integrated law equals the
//    burned mass (no cell reaches the mass cap);
//  * the burning area (reported, not asserted: Simple_Burn's cell area is
//    Vaango's heuristic of the smeared corner masses, with no exact value):
//    sum_c A_c over the burning cells against the quarter-circle arc area
//    (pi/2) R dz of the PBX boundary r = 50.8 mm (measured 0.881 at step 20);
//  * the pressure inside rises: the mean equilibration pressure of the cells
//    with burning grows step over step and ends above the initial 101325 Pa.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

double particle_mass(const MpmIceComponent& c, std::size_t m) {
  double s = 0;
  for (double x : c.mpm().materials()[m].particles.mass) s += x;
  return s;
}

TEST(MpmIceGuni2dRT, BurnsByTheSimpleBurnLawAndConservesMass) {
  auto deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/guni2dRT.ups");
  auto c = make_mpmice_component(*deck);
  c->initialize();
  const SolidBurnModel* burn = nullptr;
  for (const IceModelP& m : c->ice().models())
    if (auto* b = dynamic_cast<const SolidBurnModel*>(m.get())) burn = b;
  ASSERT_NE(burn, nullptr);
  const CellScalars *area = nullptr, *burning = nullptr;
  for (const ModelField& f : burn->fields()) {
    if (f.label == "SimpleBurn.onSurface") area = f.field;
    if (f.label == "SimpleBurn.BurningCell") burning = f.field;
  }
  ASSERT_TRUE(area && burning);
  const Grid& g = c->ice().grid();
  const std::set<std::string> sums = {"TotalMass"};
  const double M0 = c->reductions(sums)["TotalMass"][0];
  const std::size_t pbx = burn->reactant();
  const double mp0 = particle_mass(*c, pbx);
  double t = 0, burned = 0, p_first = 0, p_last = 0, area_sum = 0;
  const int steps = 20;
  for (int step = 1; step <= steps; ++step) {
    const double dt = step == 1 ? 2.1e-8 : c->stable_timestep();  // delt_init, then the stable step
    c->advance(t, dt, step);
    t += dt;
    burned += burn->mass_burned_last_step();
    const double M = c->reductions(sums)["TotalMass"][0];
    EXPECT_NEAR(M, M0, 1e-13 * M0) << "step " << step;
    // The rate law over the burning cells of the step.
    double law = 0, p_sum = 0, A = 0;
    int n = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        if ((*burning)[pi](i, j, k) == 0.0) return;
        const double p = c->ice().press_equil_CC()[pi](i, j, k);
        law += dt * (*area)[pi](i, j, k) * 75.3 * std::pow(p / 101325.0, 0.778);
        A += (*area)[pi](i, j, k);
        p_sum += p;
        ++n;
      });
    ASSERT_GT(n, 0) << "step " << step;
    EXPECT_NEAR(burn->mass_burned_last_step(), law, 1e-12 * law) << "step " << step;
    if (step == 1) p_first = p_sum / n;
    p_last = p_sum / n;
    area_sum = A;
  }
  const double mp = particle_mass(*c, pbx);
  // mp0 - mp is the difference of two sums of ~3.6k particle masses (6.3e-3 kg): its round-off
  // scales with mp0 (measured 5.5e-17 kg = 8.7e-15 mp0), as in test_mpmice_burn.
  EXPECT_NEAR(mp0 - mp, burned, 1e-13 * mp0) << "particles lost " << mp0 - mp << " kg, burned " << burned;
  const double arc = 0.5 * std::numbers::pi * 0.0508 * g.dx[2];
  std::printf("guni2dRT %d steps, t = %.4g s: burned %.6g kg (PBX %.6g kg), burning area %.5g m^2 vs arc %.5g m^2 "
              "(%.3f), mean p of the burning cells %.6g -> %.6g Pa\n",
              steps, t, burned, mp0, area_sum, arc, area_sum / arc, p_first, p_last);
  EXPECT_GT(p_last, 1.5 * p_first);
}

}  // namespace
}  // namespace tephra
