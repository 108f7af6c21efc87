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


// <useInductionTime> (Uintah's DDT1; Son's surface flame spread):
// S_f = Fb (p/PS)^Fc, A(theta) = (1 + IC)/2 + (1 - IC)/2 sin(2 theta - pi/2),
// tau = dx_mean A/S_f.
TEST(MpmIceDdt1Induction, FlameSpeedIsSonsPowerLaw) {
  Ddt1InductionParams prm;
  prm.Fb = 0.03, prm.PS = 1e5, prm.Fc = 0.8;
  EXPECT_NEAR(ddt1_flame_speed(prm, 4e6), 0.03 * std::pow(40.0, 0.8), 1e-15);
  EXPECT_DOUBLE_EQ(ddt1_flame_speed(prm, 1e5), 0.03);  // p = PS
}

TEST(MpmIceDdt1Induction, DirectionFactorRunsFromIcAlongTheNormalToOneAlongTheSurface) {
  const double IC = 0.3, pi = std::acos(-1.0);
  EXPECT_NEAR(ddt1_induction_factor(IC, 0.0), IC, 1e-15);         // sin(-pi/2) = -1
  EXPECT_NEAR(ddt1_induction_factor(IC, pi / 2), 1.0, 1e-15);     // sin(pi/2) = 1
  EXPECT_NEAR(ddt1_induction_factor(IC, pi / 4), (1 + IC) / 2, 1e-15);  // sin(0) = 0
  // sin(2 theta - pi/2) = -cos(2 theta): A = (1 + IC)/2 - (1 - IC)/2 cos(2 theta).
  for (double th = 0; th <= pi / 2; th += 0.1)
    EXPECT_NEAR(ddt1_induction_factor(IC, th), (1 + IC) / 2 - (1 - IC) / 2 * std::cos(2 * th), 1e-15);
}

TEST(MpmIceDdt1Induction, AngleBetweenTheNormalAndTheHotCell) {
  double c = 0;
  const double pi = std::acos(-1.0);
  // Hot cell straight along the normal (either sign: |n.h|): theta = 0.
  EXPECT_NEAR(ddt1_induction_angle(Vec3(1, 0, 0), Vec3(-0.5, 0, 0), c), 0.0, 1e-8);
  EXPECT_DOUBLE_EQ(c, 1.0);
  // Beside the surface: 90 degrees.
  EXPECT_NEAR(ddt1_induction_angle(Vec3(0, 0, 1), Vec3(0.5, 0, 0), c), pi / 2, 1e-15);
  // Diagonal neighbour of a face normal: 45 degrees (cos = 1/sqrt 2).
  EXPECT_NEAR(ddt1_induction_angle(Vec3(1, 0, 0), Vec3(0.5, 0.5, 0), c), pi / 4, 1e-15);
  EXPECT_NEAR(c, 1 / std::sqrt(2.0), 1e-15);
  // Cube-corner normal (1,1,1)/sqrt 3 and an edge neighbour (1,1,0): cos = 2/sqrt 6.
  EXPECT_NEAR(ddt1_induction_angle(Vec3(1, 1, 1) / std::sqrt(3.0), Vec3(1, 1, 0), c), std::acos(2 / std::sqrt(6.0)), 1e-15);
  // No gradient (inside the solid): NaN, as Uintah's 0/0 (no comparison takes it).
  EXPECT_TRUE(std::isnan(ddt1_induction_angle(Vec3::Zero(), Vec3(1, 0, 0), c)));
  EXPECT_FALSE(c > -1);
}

TEST(MpmIceDdt1Induction, InductionTimeIsTheCellCrossingTimeOfTheFlame) {
  Ddt1InductionParams prm;
  prm.Fb = 0.02, prm.PS = 101325, prm.Fc = 1.0;
  // 1 mm cells, flame along the normal with IC = 0.5 at p = 10 PS: S_f = 0.2 m/s, tau = 1e-3 * 0.5 / 0.2.
  EXPECT_NEAR(ddt1_induction_time(prm, 1e-3, ddt1_induction_factor(0.5, 0.0), 10 * 101325.0), 2.5e-3, 1e-17);
}

}  // namespace
}  // namespace tephra
