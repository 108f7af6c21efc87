// Burn models in axisymmetric MPMICE (session 23, issue 6; mpmice/AxisymmetricBurn.h):
// inputs/mpmice/burning_cylinder_axisym.ups, a solid cylinder r < R = 0.2 m
// filling the height L = 0.5 m of a closed can (r < 0.5 m; the z ends are
// symmetry planes, so the only burning surface is the mantle r = R), in air
// at 101325 Pa, 300 K; 10 x 10 x 1 cells of 5 cm, 2 x 2 particles per cell.
// Simple_Burn steel -> air, BurnCoeff 10 kg/(m^2 s) at refPressure 101325 Pa.
//
// Oracles:
//  * Burn law: the surface cells are the column i = 3 (r_c = 0.175 m; the
//    corner test on the planar-equivalent node masses, whose outer node
//    r = R holds half a node's mass: (max - min)/max = 1/2); each burns
//    dt A_rad BurnCoeff (p/refPressure)^0.778 with A_rad = dy R (the face at
//    r = R per radian), so the step burns dt BurnCoeff (p/p_ref)^0.778 R L per
//    radian (2 pi R L in all).
//  * Planar twin: the same deck with <axisymmetric>false (the slab |x| < R,
//    mirrored at x = 0, one cell dz = 0.05 m deep) burns dt BurnCoeff
//    (p/p_ref)^0.778 L dz; the ratio is R/dz = 4.
//  * Mass: the particles' per-radian mass plus the air's sum_c rho_c r_c dx dy
//    is conserved while the solid burns (ICE takes dm_rad as the content
//    dm_rad dz/r_c), and the air gains what the particles lose.
//  * Steady_Burn: the same cylinder, ignited by the 300 K air (IgnitionTemp
//    299 K), burns dt m_WSB(p, T0, v_s) R L (mpmice/SteadyBurn.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "mpmice/SteadyBurn.h"
#include "tests/support/CoupledRuns.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::CoupledRun;

constexpr double kR = 0.2, kL = 0.5, kDz = 0.05, kBurnCoeff = 1.0, kPref = 101325.0;

DeckNode leaf(const std::string& name, const std::string& text) {
  DeckNode n;
  n.name = name;
  n.text = text;
  return n;
}

// The deck as Steady_Burn (the WSB constants of inputs/validation/cookoff2d.ups).
void make_steady_burn(DeckNode& root) {
  DeckNode& m = test::deck_node(root, {"Models", "Model"});
  for (auto& [k, v] : m.attributes)
    if (k == "type") v = "Steady_Burn";
  m.children = {leaf("fromMaterial", "steel"),     leaf("toMaterial", "air"),
                leaf("IdealGasConst", "8.314"),    leaf("PreExpCondPh", "1.637e15"),
                leaf("ActEnergyCondPh", "1.76e5"), leaf("PreExpGasPh", "1.6e-3"),
                leaf("CondPhaseHeat", "4.0e5"),    leaf("GasPhaseHeat", "3.018e6"),
                leaf("HeatConductGasPh", "0.07"),  leaf("HeatConductCondPh", "0.2"),
                leaf("SpecificHeatBoth", "1.4e3"), leaf("MoleWeightGasPh", "0.0342"),
                leaf("BoundaryParticles", "3"),    leaf("ThresholdPressure", "50000"),
                leaf("IgnitionTemp", "299.0")};
}

CoupledRun make_run(bool axi = true, bool steady = false) {
  return test::make_coupled_run(test::source_dir() + "/inputs/mpmice/burning_cylinder_axisym.ups", [&](DeckNode& root) {
    if (!axi) test::deck_node(root, {"MPM", "axisymmetric"}).text = "false";
    if (steady) make_steady_burn(root);
  });
}

const SolidBurnModel& burn_model(const CoupledRun& r) {
  for (const IceModelP& m : r.c->ice().models())
    if (auto* b = dynamic_cast<const SolidBurnModel*>(m.get())) return *b;
  throw std::logic_error("no burn model");
}

double particle_mass(const MpmIceComponent& c) {
  double sum = 0;
  for (double m : c.mpm().materials()[0].particles.mass) sum += m;
  return sum;
}

// sum_p (m_p^0 - m_p) over the particles (no particle is deleted in these
// runs): each difference exact, unlike the difference of the two ~89 kg sums.
double mass_lost(const std::vector<double>& m0, const MpmIceComponent& c) {
  const std::vector<double>& m = c.mpm().materials()[0].particles.mass;
  if (m.size() != m0.size()) throw std::logic_error("particles deleted");
  double sum = 0;
  for (std::size_t i = 0; i < m.size(); ++i) sum += m0[i] - m[i];
  return sum;
}

// The round-off of storing m_p^0 - dm_p: half an ulp of m_p^0 per particle
// that burned (~1e-16 kg for the ~1 kg/rad particles); summed as a bound.
double storage_roundoff(const std::vector<double>& m0, const MpmIceComponent& c) {
  const std::vector<double>& m = c.mpm().materials()[0].particles.mass;
  double sum = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i] != m0[i]) sum += 0.5 * (std::nextafter(m0[i], 2 * m0[i]) - m0[i]);
  return sum;
}

// The air's mass: per radian sum rho r_c dx dy (axisymmetric), else rho V.
double air_mass(const MpmIceComponent& c, bool axi) {
  const Grid& g = c.ice().grid();
  double sum = 0;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    const double rho = c.ice().fields()[1].rho_CC[0](i, j, k);
    sum += rho * (axi ? g.cell_center(i, j, k)[0] * g.dx[0] * g.dx[1] : g.cell_volume());
  });
  return sum;
}

// Step 1 (dt = delt_init = 1e-6 s): the burning cells must be the column
// i = 3 and the burned mass the law on them.
struct StepOne {
  double burned = 0, lost = 0, roundoff = 0, expected = 0, closed_form = 0, dp = 0;  // dp: max |p/p_ref - 1| on the surface
  int surface_cells = 0, wrong_cells = 0;
};

StepOne simple_burn_step_one(bool axi) {
  set_thread_count(1);
  CoupledRun r = make_run(axi);
  const std::vector<double> m0 = r.c->mpm().materials()[0].particles.mass;
  test::run_to(r, 1.0, 1);
  const double dt = r.time;
  const Grid& g = r.c->ice().grid();
  const SolidBurnModel& b = burn_model(r);
  StepOne s;
  s.burned = b.mass_burned_last_step();
  s.lost = mass_lost(m0, *r.c);
  s.roundoff = storage_roundoff(m0, *r.c);
  // Per cell: A = dy R per radian (axisymmetric), dy dz planar.
  const double A = axi ? g.dx[1] * kR : g.dx[1] * g.dx[2];
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    const bool burning = b.on_surface()[0](i, j, k) > 0;
    if (i == 3) {
      s.surface_cells += burning;
      const double p = r.c->ice().press_equil_CC()[0](i, j, k);
      s.dp = std::max(s.dp, std::abs(p / kPref - 1));
      s.expected += dt * A * kBurnCoeff * std::pow(p / kPref, 0.778);
    } else {
      s.wrong_cells += burning;
    }
  });
  s.closed_form = dt * kBurnCoeff * (axi ? kR * kL : kL * kDz);  // p = p_ref = 101325 Pa
  return s;
}

TEST(MpmIceAxisymmetricBurn, SimpleBurnStepIsTheLawTimesRL) {
  const StepOne s = simple_burn_step_one(true);
  std::printf("[mpmice axisym burn] Simple_Burn step 1: surface cells %d (others %d), burned %.17g kg/rad, "
              "law on the cells %.17g, closed form dt k R L %.17g (rel %.2e; p_equil - p_ref %.2e), particles lost %.17g\n",
              s.surface_cells, s.wrong_cells, s.burned, s.expected, s.closed_form,
              s.burned / s.closed_form - 1, s.dp, s.lost);
  EXPECT_EQ(s.surface_cells, 10);
  EXPECT_EQ(s.wrong_cells, 0);
  EXPECT_NEAR(s.burned, s.expected, 1e-12 * s.expected);
  // The closed form at p = p_ref: the surface cells' p_equil is p_ref to
  // 1.16e-8 (measured; planar: 0), the steel's K = 1.17e9 Pa times a 1e-12
  // relative round-off of its projected density (K 1e-12 / p_ref = 1.2e-8), so
  // (p/p_ref)^0.778 = 1 + 0.778 x that.
  EXPECT_LT(s.dp, 1e-7);
  EXPECT_NEAR(s.burned, s.closed_form, (0.778 * s.dp + 1e-12) * s.closed_form);
  EXPECT_NEAR(s.lost, s.burned, s.roundoff + 1e-12 * s.burned);
}

TEST(MpmIceAxisymmetricBurn, PlanarTwinBurnsRoverDzLess) {
  const StepOne a = simple_burn_step_one(true), p = simple_burn_step_one(false);
  std::printf("[mpmice axisym burn] step 1 burned: axisymmetric %.17g kg/rad, planar %.17g kg; ratio %.15g "
              "(R/dz = %.15g)\n",
              a.burned, p.burned, a.burned / p.burned, kR / kDz);
  EXPECT_EQ(p.surface_cells, 10);
  EXPECT_EQ(p.wrong_cells, 0);
  // Equal laws on equal pressures but for the axisymmetric cells' 1.16e-8
  // p_equil round-off (SimpleBurnStepIsTheLawTimesRL): 0.778 x 1.16e-8 = 9e-9.
  EXPECT_NEAR(a.burned / p.burned, kR / kDz, (0.778 * (a.dp + p.dp) + 1e-12) * kR / kDz);
}

// Total per-radian mass while the solid burns, 40 steps.
TEST(MpmIceAxisymmetricBurn, TotalPerRadianMassIsConservedWhileBurning) {
  set_thread_count(1);
  CoupledRun r = make_run();
  const SolidBurnModel& b = burn_model(r);
  const std::vector<double> m0 = r.c->mpm().materials()[0].particles.mass;
  const double mp0 = particle_mass(*r.c), ma0 = air_mass(*r.c, true), M0 = mp0 + ma0;
  double burned = 0, worst = 0, roundoff = 0;
  while (r.steps < 40) {
    const std::vector<double> before = r.c->mpm().materials()[0].particles.mass;
    test::run_to(r, 1.0, r.steps + 1);
    roundoff += storage_roundoff(before, *r.c);
    burned += b.mass_burned_last_step();
    const double M = particle_mass(*r.c) + air_mass(*r.c, true);
    worst = std::max(worst, std::abs(M / M0 - 1));
  }
  const double lost = mass_lost(m0, *r.c), gained = air_mass(*r.c, true) - ma0;
  std::printf("[mpmice axisym burn] 40 steps (t = %.4g s): burned %.6e kg/rad, particles lost %.6e, air gained %.6e "
              "(rel %.2e); total mass max rel change %.2e\n",
              r.time, burned, lost, gained, gained / lost - 1, worst);
  EXPECT_GT(burned, 1e-5);
  EXPECT_NEAR(lost, burned, roundoff + 1e-12 * burned);
  // The air's sum (100 cells of ~0.005 kg/rad) carries ~1e-16 x 0.06 kg of
  // round-off per step: 1e-9 of the burned 1e-4 kg/rad is ample and a
  // missing dz/r_c (x r_c/dz = 3.5) or double count fails by O(1).
  EXPECT_NEAR(gained, lost, 1e-9 * lost);
  EXPECT_LT(worst, 1e-13);
}

TEST(MpmIceAxisymmetricBurn, SteadyBurnStepIsTheWsbRateTimesRL) {
  set_thread_count(1);
  CoupledRun r = make_run(true, true);
  const std::vector<double> m0 = r.c->mpm().materials()[0].particles.mass;
  test::run_to(r, 1.0, 1);
  const double dt = r.time;
  const Grid& g = r.c->ice().grid();
  const SolidBurnModel& b = burn_model(r);
  const double roundoff = storage_roundoff(m0, *r.c);
  WsbParams w;
  w.R = 8.314, w.Ac = 1.637e15, w.Ec = 1.76e5, w.Bg = 1.6e-3, w.Qc = 4.0e5, w.Qg = 3.018e6;
  w.kg = 0.07, w.kc = 0.2, w.Cp = 1.4e3, w.W = 0.0342;
  int surface = 0, wrong = 0;
  double expected = 0;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    const bool burning = b.on_surface()[0](i, j, k) > 0;
    if (i != 3) {
      wrong += burning;
      return;
    }
    surface += burning;
    // WSB inputs (mpmice/WsbSurfaceCell.h): p of the air cell beside it (the
    // largest product fraction), T0 of the steel, v_s the steel's specific volume.
    const double p = r.c->ice().press_equil_CC()[0](i + 1, j, k);
    const double T0 = r.c->ice().fields()[0].temp_CC[0](i, j, k);
    const double vs = r.c->ice().fields()[0].sp_vol_CC[0](i, j, k);
    expected += dt * g.dx[1] * kR * wsb_burn_rate(w, p, T0, vs).mass_flux;
  });
  const double closed = dt * kR * kL * wsb_burn_rate(w, kPref, 300.0, 1.0 / 8900.0).mass_flux;
  std::printf("[mpmice axisym burn] Steady_Burn step 1: surface cells %d (others %d), burned %.17g kg/rad, "
              "WSB on the cells %.17g, closed form dt m(p0, 300 K, 1/8900) R L %.17g (rel %.2e)\n",
              surface, wrong, b.mass_burned_last_step(), expected, closed, b.mass_burned_last_step() / closed - 1);
  EXPECT_EQ(surface, 10);
  EXPECT_EQ(wrong, 0);
  EXPECT_NEAR(b.mass_burned_last_step(), expected, 1e-12 * expected);
  EXPECT_NEAR(b.mass_burned_last_step(), closed, 1e-6 * closed);
  EXPECT_NEAR(mass_lost(m0, *r.c), b.mass_burned_last_step(), roundoff + 1e-12 * expected);
}

// An ICE reaction between ICE materials in axisymmetric MPMICE (session 24):
// inputs/mpmice/jwlpp_axisym.ups, the same can with the steel cylinder at rest
// and ANFO reactant (Murnaghan at its P0 = 101325 Pa) outside it, JWL++ to
// JWLC products with ThresholdPressure 0. Step 1 has no flow (p_equil is
// uniform, so the face velocities are zero) and F = 0, so each reactant cell
// converts dF = G p^b (1 - F_0) dt of its mass (Souers' JWL++ law, the 20 %
// cap far away; F_0 ~ 1e-15 is the product's initial trace), so after the
// step F - F_0 = G p^b (1 - F_0) dt in every cell, at every radius: the model acts on the cell's own masses, so the
// per-radian weight r_c must not enter. A source weighted by r (or 1/r) once
// too often makes F grow (or fall) with r by the factor r_9/r_4 = 2.1.
// Then 40 steps: the per-radian mass sum_c (rho_r + rho_p) r_c dx dy is
// conserved (closed can: x+ wall, symmetric y and z faces).
TEST(MpmIceAxisymmetricBurn, JwlppBetweenIceMaterialsGivesTheLawAtEveryRadius) {
  set_thread_count(1);
  CoupledRun r = test::make_coupled_run(test::source_dir() + "/inputs/mpmice/jwlpp_axisym.ups");
  const Grid& g = r.c->ice().grid();
  auto ice_mass = [&] {  // per radian, reactant + product
    double sum = 0;
    for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
      const double rho = r.c->ice().fields()[1].rho_CC[0](i, j, k) + r.c->ice().fields()[2].rho_CC[0](i, j, k);
      sum += rho * g.cell_center(i, j, k)[0] * g.dx[0] * g.dx[1];
    });
    return sum;
  };
  const double M0 = ice_mass();
  // The product starts as a trace in every cell (rho ~ 1e-15 of the
  // reactant's), so F_0 = rho_p / (rho_r + rho_p) before the step is kept.
  auto F_of = [&](int i, int j, int k) {
    const double rr = r.c->ice().fields()[1].rho_CC[0](i, j, k), rp = r.c->ice().fields()[2].rho_CC[0](i, j, k);
    return rp / (rr + rp);
  };
  CellScalars F0(g, 0);
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) { F0[0](i, j, k) = F_of(i, j, k); });
  test::run_to(r, 1.0, 1);
  const double dt = r.time, G = 1.0e-9, b = 1.3;
  double worst = 0, f_min = 1, f_max = 0;
  int cells = 0;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    if (i < 4) return;  // r < 0.2 m: the steel
    const double f0 = F0[0](i, j, k), p = r.c->ice().press_equil_CC()[0](i, j, k);
    const double F = F_of(i, j, k) - f0;  // the converted share of the cell's mass
    const double law = G * std::pow(p, b) * (1 - f0) * dt;
    worst = std::max(worst, std::abs(F / law - 1));
    f_min = std::min(f_min, F), f_max = std::max(f_max, F);
    ++cells;
  });
  std::printf("[mpmice axisym jwlpp] step 1 (dt %.3g s): %d reactant cells, F in [%.17g, %.17g], "
              "max |F / (G p^b dt) - 1| = %.2e\n", dt, cells, f_min, f_max, worst);
  EXPECT_EQ(cells, 60);
  EXPECT_GT(f_min, 1e-10);  // it reacted (G p0^b dt = 3.3e-9 at dt = 1e-6 s)
  EXPECT_LT(worst, 1e-9);   // rho_p = dm / V and rho_r = (m - dm) / V: round-off of F ~ 1e-16 / 3e-9
  EXPECT_LT(f_max / f_min - 1, 1e-9);
  double drift = 0;
  while (r.steps < 40) {
    test::run_to(r, 1.0, r.steps + 1);
    drift = std::max(drift, std::abs(ice_mass() / M0 - 1));
  }
  std::printf("[mpmice axisym jwlpp] 40 steps (t = %.4g s): max rel change of the per-radian ICE mass %.2e\n",
              r.time, drift);
  EXPECT_LT(drift, 1e-13);
}

// <res> z = 2 in an axisymmetric deck (a planar deck's [2,2,2] kept): each
// z-layer holds a full radian (Vaango's rule, mpm/Axisymmetric.cpp), so the
// solid's mass doubles; the reader warns, naming the file and the rule.
TEST(MpmIceAxisymmetricBurn, ResZTwoDoublesTheMassAndWarns) {
  set_thread_count(1);
  const double m1 = particle_mass(*make_run().c);
  testing::internal::CaptureStderr();
  CoupledRun r2 = test::make_coupled_run(
      test::source_dir() + "/inputs/mpmice/burning_cylinder_axisym.ups", [](DeckNode& root) {
        test::deck_node(root, {"MaterialProperties", "MPM", "material", "geom_object", "res"}).text = "[2,2,2]";
      });
  const std::string err = testing::internal::GetCapturedStderr();
  const double m2 = particle_mass(*r2.c);
  // Per radian: rho R^2 / 2 L = 8900 x 0.02 x 0.5 = 89 kg with res z = 1.
  EXPECT_NEAR(m1, 8900.0 * kR * kR / 2 * kL, 1e-9 * m1);
  EXPECT_NEAR(m2 / m1, 2.0, 1e-14);
  EXPECT_NE(err.find("burning_cylinder_axisym.ups:"), std::string::npos) << err;
  EXPECT_NE(err.find("<res> z = 2"), std::string::npos) << err;
}

// DDT1 and DDT0 in axisymmetric MPMICE (session 25): their cell volume,
// masses and areas are per radian (BurnCell::volume = r_c dx dy).
// The model block: the WSB constants of make_steady_burn, DDT1's thresholds.
void make_ddt(DeckNode& root, const std::string& type, const std::string& jwl_pressure, const std::string& G) {
  DeckNode& m = test::deck_node(root, {"Models", "Model"});
  if (type == "DDT1") {
    make_steady_burn(root);
    for (DeckNode& c : m.children)
      if (c.name == "ThresholdPressure") c.name = "ThresholdPressureSB";  // DDT1's name for the WSB threshold
  } else {  // DDT0: Simple_Burn's constants
    m.children = {leaf("fromMaterial", "steel"), leaf("toMaterial", "air"),    leaf("Enthalpy", "0"),
                  leaf("BurnCoeff", "1"),        leaf("refPressure", "101325"), leaf("ThresholdTemp", "299"),
                  leaf("ThresholdPressureSB", "50000")};
  }
  for (auto& [k, v] : m.attributes)
    if (k == "type") v = type;
  // E0 = 0: no heat of detonation, so a detonating step stays mild.
  for (const DeckNode& n : {leaf("ThresholdPressureJWL", jwl_pressure), leaf("G", G), leaf("b", "1"), leaf("E0", "0")})
    m.children.push_back(n);
}

CoupledRun make_ddt_run(const std::string& type, const std::string& jwl_pressure, const std::string& G) {
  return test::make_coupled_run(test::source_dir() + "/inputs/mpmice/burning_cylinder_axisym.ups",
                                [&](DeckNode& root) { make_ddt(root, type, jwl_pressure, G); });
}

// DDT1 below ThresholdPressureJWL (5.3 GPa) and above ThresholdPressureSB
// (50 kPa), ignited by the 300 K air: the conductive branch, which is
// Steady_Burn's WSB burning of the mantle, dt m_WSB R L per radian; the same
// mass as the Steady_Burn run of SteadyBurnStepIsTheWsbRateTimesRL.
TEST(MpmIceAxisymmetricBurn, Ddt1ConductiveBranchIsTheWsbRateTimesRL) {
  set_thread_count(1);
  CoupledRun steady = make_run(true, true), ddt1 = make_ddt_run("DDT1", "5.3e9", "2.33e-6");
  test::run_to(steady, 1.0, 1);
  test::run_to(ddt1, 1.0, 1);
  const double ws = burn_model(steady).mass_burned_last_step(), wd = burn_model(ddt1).mass_burned_last_step();
  WsbParams w;
  w.R = 8.314, w.Ac = 1.637e15, w.Ec = 1.76e5, w.Bg = 1.6e-3, w.Qc = 4.0e5, w.Qg = 3.018e6;
  w.kg = 0.07, w.kc = 0.2, w.Cp = 1.4e3, w.W = 0.0342;
  const double closed = ddt1.time * kR * kL * wsb_burn_rate(w, kPref, 300.0, 1.0 / 8900.0).mass_flux;
  std::printf("[mpmice axisym burn] DDT1 conductive step 1: %.17g kg/rad, Steady_Burn %.17g, closed form dt m R L "
              "%.17g (rel %.2e)\n", wd, ws, closed, wd / closed - 1);
  EXPECT_GT(wd, 0.0);
  EXPECT_NEAR(wd, ws, 1e-14 * ws);
  EXPECT_NEAR(wd, closed, 1e-6 * closed);  // as SteadyBurnStepIsTheWsbRateTimesRL (p_equil round-off)
}

// Above ThresholdPressureJWL (50 kPa < p0) every cell with reactant volume
// fraction > ThresholdVolFrac (0.01) detonates: dm = min(G p^b (1 - F) dt
// (M_r + M_p), M_r, 0.2 rho0 V). With G = 10 /(s Pa), b = 1, dt = 1e-6 s,
// G p dt = 1.01, so Souers' 20 % cap binds: dm = 0.2 rho0 V with the
// per-radian V = r_c dx dy. The steel fills the columns r < R completely
// (rho_CC = rho0 = 8900), so the step burns 0.2 rho0 sum_c r_c dx dy =
// 0.2 rho0 R^2 L / 2 per radian (= 17.8 kg/rad); with the Cartesian
// V = dx dy dz it would be 0.2 rho0 (R/dx) (L/dy) dx dy dz = 8.9 kg.
// DDT0 has the same law (and its cut-off at F >= 0.99, far away here).
void detonation_step_one(const std::string& type) {
  set_thread_count(1);
  CoupledRun r = make_ddt_run(type, "50000", "10");
  const std::vector<double> m0 = r.c->mpm().materials()[0].particles.mass;
  test::run_to(r, 1.0, 1);
  const SolidBurnModel& b = burn_model(r);
  const CellScalars* det = nullptr;
  for (const ModelField& f : b.fields())
    if (f.label == "detonating") det = f.field;
  ASSERT_NE(det, nullptr);
  const Grid& g = r.c->ice().grid();
  int inside = 0, outside = 0;
  for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
    ((i < 4) ? inside : outside) += (*det)[0](i, j, k) > 0;
  });
  const double closed = 0.2 * 8900.0 * kR * kR * kL / 2;
  const double burned = b.mass_burned_last_step(), lost = mass_lost(m0, *r.c);
  std::printf("[mpmice axisym burn] %s detonation step 1: detonating cells %d inside r < R, %d outside; burned %.17g "
              "kg/rad, 0.2 rho0 R^2 L / 2 = %.17g (rel %.2e), particles lost %.17g\n",
              type.c_str(), inside, outside, burned, closed, burned / closed - 1, lost);
  EXPECT_EQ(inside, 40);
  EXPECT_EQ(outside, 0);
  // rho_CC of the steel = 8900 to 6.7e-16 in every covered cell (test_mpmice_axisymmetric).
  EXPECT_NEAR(burned, closed, 1e-13 * closed);
  EXPECT_NEAR(lost, burned, storage_roundoff(m0, *r.c) + 1e-12 * burned);
}

// DDT1 with <useInductionTime> per radian (session 27). The mantle cells
// are ignited surface cells from step 1 (the steel at 300 K > IgnitionTemp,
// theta_s > 0.2 in its own cell, so A = IC), p = p_ref while nothing burns:
// the induction time is tau = dx_mean IC / S_f, S_f = PreexpoConst (p /
// PressureShift)^1, dx_mean = (dx + dy + dz)/3 = 0.05 m here. With tau = 2.5
// dt (dt = 1e-6 s) steps 1-2 burn nothing and step 3 burns the conductive
// branch's per-radian mass of step 1, dt m_WSB R L (Ddt1ConductiveBranch...
// above, the state unchanged while the cells warm up); the particles lose it.
// What is per radian here is the burned mass (area R dy per radian); the
// induction time itself has no volume or area in it.
TEST(MpmIceAxisymmetricBurn, Ddt1InductionDelaysTheConductiveBranchPerRadian) {
  set_thread_count(1);
  const double dt = 1e-6, IC = 1.0, dx_mean = 0.05, tau = 2.5 * dt;
  char fb[64];
  std::snprintf(fb, sizeof fb, "%.17g", dx_mean * IC / tau);
  CoupledRun r = test::make_coupled_run(test::source_dir() + "/inputs/mpmice/burning_cylinder_axisym.ups", [&](DeckNode& root) {
    make_ddt(root, "DDT1", "5.3e9", "2.33e-6");
    DeckNode& m = test::deck_node(root, {"Models", "Model"});
    for (const DeckNode& n : {leaf("useInductionTime", "true"), leaf("IgnitionConst", "1"), leaf("PressureShift", "101325"),
                              leaf("PreexpoConst", fb), leaf("ExponentialConst", "1")})
      m.children.push_back(n);
  });
  const Grid& g = r.c->ice().grid();
  ASSERT_NEAR((g.dx[0] + g.dx[1] + g.dx[2]) / 3, dx_mean, 1e-15);
  double mp0 = 0;
  for (double m : r.c->mpm().materials()[0].particles.mass) mp0 += m;
  for (int k = 1; k <= 2; ++k) {
    r.c->advance((k - 1) * dt, dt, k);
    EXPECT_EQ(burn_model(r).mass_burned_last_step(), 0.0) << "step " << k;
  }
  r.c->advance(2 * dt, dt, 3);
  WsbParams w;
  w.R = 8.314, w.Ac = 1.637e15, w.Ec = 1.76e5, w.Bg = 1.6e-3, w.Qc = 4.0e5, w.Qg = 3.018e6;
  w.kg = 0.07, w.kc = 0.2, w.Cp = 1.4e3, w.W = 0.0342;
  const double closed = dt * kR * kL * wsb_burn_rate(w, kPref, 300.0, 1.0 / 8900.0).mass_flux;
  const double burned = burn_model(r).mass_burned_last_step();
  double mp = 0;
  for (double m : r.c->mpm().materials()[0].particles.mass) mp += m;
  std::printf("[mpmice axisym burn] DDT1 induction (tau = 2.5 dt): steps 1-2 burn 0, step 3 %.17g kg/rad, "
              "closed form dt m R L %.17g (rel %.2e), particles lost %.17g\n",
              burned, closed, burned / closed - 1, mp0 - mp);
  EXPECT_NEAR(burned, closed, 1e-6 * closed);
  EXPECT_NEAR(mp0 - mp, burned, 1e-13 * mp0);
}

TEST(MpmIceAxisymmetricBurn, Ddt1DetonationCapIsPerRadian) { detonation_step_one("DDT1"); }
TEST(MpmIceAxisymmetricBurn, Ddt0DetonationCapIsPerRadian) { detonation_step_one("DDT0"); }

// MesoBurn (per-particle induction clocks) has no per-radian verification:
// with <axisymmetric> the deck reader stops, MissingFeature (exit 3) naming it.
TEST(MpmIceAxisymmetricBurn, MesoBurnWithAxisymmetricIsAMissingFeatureNamingIt) {
  std::unique_ptr<Deck> deck = load_deck(test::source_dir() + "/inputs/mpmice/burning_cylinder_axisym.ups");
  make_steady_burn(deck->root);
  DeckNode& m = test::deck_node(deck->root, {"Models", "Model"});
  for (auto& [k, v] : m.attributes)
    if (k == "type") v = "MesoBurn";
  std::erase_if(m.children, [](const DeckNode& c) { return c.name == "IgnitionTemp"; });  // not a MesoBurn parameter
  for (const DeckNode& n : {leaf("Ta", "1000"), leaf("k", "1e-3"), leaf("Cv", "1500")}) m.children.push_back(n);
  deck->root.finalize_parents();
  try {
    make_mpmice_component(*deck);
    ADD_FAILURE() << "MesoBurn with <axisymmetric> was accepted";
  } catch (const MissingFeature& e) {
    const std::string what = e.what();
    std::printf("[mpmice axisym burn] MesoBurn: %s\n", what.c_str());
    EXPECT_NE(what.find("MesoBurn"), std::string::npos);
    EXPECT_NE(what.find("axisymmetric"), std::string::npos);
  }
}

}  // namespace
}  // namespace tephra
