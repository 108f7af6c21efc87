// DDT1's point functions (mpmice/Ddt1.h): the JWL++ detonation branch
// against its closed form on a single cell, the branch switch at the
// thresholds, Vaango's crack-width threshold.
#include <gtest/gtest.h>

#include <cmath>

#include "mpmice/Ddt1.h"

namespace tephra {
namespace {

// BurnRate.ups: G = 2.33e-6, b = 1.2, rho0 = 1832; a 1 mm cell, dt = 1 ns.
constexpr double kG = 2.33e-6, kB = 1.2, kRho0 = 1832.0, kV = 1e-9, kDt = 1e-9;

TEST(Ddt1Detonation, JwlppRateOnASingleCell) {
  const double p = 6e9, Mr = 1.5e-6, Mp = 1.5e-7;
  const Ddt1Detonation d = ddt1_detonation(kG, kB, p, Mr, Mp, kRho0, kV, kDt);
  const double F = Mp / (Mr + Mp);  // = 1/11
  EXPECT_NEAR(d.F, 1.0 / 11.0, 1e-15);
  // delF = G p^b (1 - F) dt, written with exp/log.
  const double delF = kG * std::exp(kB * std::log(p)) * (1 - F) * kDt;
  EXPECT_NEAR(d.delF, delF, 1e-13 * delF);
  EXPECT_NEAR(d.mass, delF * (Mr + Mp), 1e-13 * delF * (Mr + Mp));
  EXPECT_LT(d.mass, 0.2 * kRho0 * kV);  // no cap active
}

TEST(Ddt1Detonation, CapsAtTheReactantMassAndAtTwentyPercentOfRho0V) {
  // A long step: delF (Mr + Mp) exceeds both caps.
  const Ddt1Detonation a = ddt1_detonation(kG, kB, 6e9, 1.5e-6, 1.5e-7, kRho0, kV, 1e-3);
  EXPECT_EQ(a.mass, 0.2 * kRho0 * kV);  // 3.664e-7 kg < Mr
  const Ddt1Detonation b = ddt1_detonation(kG, kB, 6e9, 1e-8, 1.5e-7, kRho0, kV, 1e-3);
  EXPECT_EQ(b.mass, 1e-8);  // the reactant's mass
  const Ddt1Detonation c = ddt1_detonation(kG, kB, 6e9, 0.0, 1.5e-7, kRho0, kV, kDt);
  EXPECT_EQ(c.F, 1.0);
  EXPECT_EQ(c.delF, 0.0);  // fully reacted
  EXPECT_EQ(c.mass, 0.0);
}

TEST(Ddt1Branch, SwitchesAtTheThresholds) {
  Ddt1Thresholds t;
  t.jwl_pressure = 5.3e9, t.sb_pressure = 5e4;
  Ddt1CellState s;
  s.reactant_fraction = 0.5, s.ignited_surface = true, s.gas_pressure = 1e6;
  s.p = 5.3e9 * (1 + 1e-12);
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::Detonating);
  s.p = 5.3e9 * (1 - 1e-12);
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::Conductive);
  s.p = 5.3e9;  // neither above nor below the JWL threshold (Vaango's strict tests)
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
  // Too little reactant to detonate (ThresholdVolFrac 0.01); above the JWL
  // threshold it does not deflagrate either.
  s.p = 6e9, s.reactant_fraction = 0.005;
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
  s.reactant_fraction = 1e-11;  // no reactant
  s.p = 1e6;
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
  s.reactant_fraction = 0.5;
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::Conductive);
  s.detonation_next = true;  // a detonating neighbour suppresses the burn
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
  s.detonation_next = false;
  s.p = 5e4;  // at the SB threshold: not above it
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
  s.p = 1e6, s.gas_pressure = 4e4;  // the gas above the surface below ThresholdPressureSB
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
  // Crack burning: needs the model, a cracked cell and a hot neighbour.
  s.ignited_surface = false, s.cracked = true, s.hot_neighbour = true;
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
  t.crack_model = true;
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::Convective);
  s.hot_neighbour = false;
  EXPECT_EQ(ddt1_branch(t, s), Ddt1Branch::None);
}

TEST(Ddt1Crack, WidthThresholdAndConvectiveArea) {
  // w = sqrt(8e8/p^2.84) = sqrt(8e8) p^-1.42: at 1 MPa 8.5418e-5 m.
  for (double p : {1e5, 1e6, 1e8})
    EXPECT_NEAR(ddt1_crack_threshold(p), std::sqrt(8e8) * std::pow(p, -1.42), 1e-14 * std::sqrt(8e8) * std::pow(p, -1.42));
  EXPECT_NEAR(ddt1_crack_threshold(1e6), 8.5418e-5, 1e-9);
  EXPECT_DOUBLE_EQ(ddt1_convective_area(1e-9), 5e-7);  // V/2 mm
}

}  // namespace
}  // namespace tephra
