// visco_scram <useJWLEOS> (models/solid/ViscoScramJwl.h; Vaango
// ViscoScram::computePressEOSCM / computeRhoMicroCM): the MPMICE hooks in
// absolute pressure, with the PBX 9501 constants of MPMICE/BurnRate.ups.
//
// Closed forms (written out here independently of the model):
//   p(rho, T) = A e^{-R1 V} + B e^{-R2 V} + om Cv T / V,   V = rho0/rho
//   dp/drho   = (R1 rho0 P1 + R2 rho0 P2)/rho^2 + om Cv T/rho0
// modified EOS (useModifiedEOS): rho_ref with p(rho_ref, T) = p_ref,
//   K0 = rho_ref dp/drho(rho_ref), p = p_ref (rho/rho_ref)^{K0/p_ref} below rho_ref.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/base/Errors.h"
#include "models/solid/AbsolutePressureEos.h"
#include "models/solid/ModifiedEos.h"
#include "models/solid/ViscoScram.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kRho0 = 1832.0, kPref = 101325.0;
// BurnRate.ups (PBX 9501).
constexpr double kA = 732000e9, kB = -5.2645e9, kR1 = 14.1, kR2 = 1.41, kOm = 0.8867, kCv = 2.780236e6;

double p_closed(double rho, double T) {
  const double V = kRho0 / rho;
  return kA * std::exp(-kR1 * V) + kB * std::exp(-kR2 * V) + kOm * kCv * T / V;
}
double dp_closed(double rho, double T) {
  const double V = kRho0 / rho;
  return (kR1 * kRho0 * kA * std::exp(-kR1 * V) + kR2 * kRho0 * kB * std::exp(-kR2 * V)) / (rho * rho) +
         kOm * kCv * T / kRho0;
}
// The size of the terms (the sum cancels near rho0).
double p_scale(double rho, double T) {
  const double V = kRho0 / rho;
  return kA * std::exp(-kR1 * V) + std::abs(kB) * std::exp(-kR2 * V) + kOm * kCv * T / V;
}

const AbsolutePressureEos& abs_eos(const ConstitutiveModel& m) {
  const AbsolutePressureEos* a = absolute_pressure_eos(m);
  if (!a) throw std::runtime_error("no absolute-pressure EOS");
  return *a;
}

ConstitutiveModelP jwl_scram(bool modified) {
  MapModelParameters p({{"PR", 0.3}, {"CrackParameterA", 1e-3}, {"CrackPowerValue", 10.0},
                        {"CrackMaxGrowthRate", 300.0}, {"StressIntensityF", 500.0}, {"CrackFriction", 0.35},
                        {"InitialCrackRadius", 3e-15}, {"CrackGrowthRate", 12.0}, {"Beta", 1.5e-4},
                        {"Gamma", 1.0}, {"DCp_DTemperature", 3.30773}, {"useJWLEOS", 1}, {"A", kA},
                        {"B", kB}, {"R1", kR1}, {"R2", kR2}, {"om", kOm}, {"Cv", kCv}, {"rho0", kRho0},
                        {"useModifiedEOS", modified ? 1.0 : 0.0}});
  const double G[5] = {3.5e8, 1.739e8, 5.212e8, 9.085e8, 6.875e8}, R[5] = {0.0, 7.32e3, 7.32e4, 7.32e5, 2.e6};
  for (int i = 0; i < 5; ++i) {
    p.values["G" + std::to_string(i + 1)] = G[i];
    p.values["RTau" + std::to_string(i + 1)] = R[i];
  }
  p.enclosing = {{"specific_heat", 996.0}};
  return ViscoScram::create(p);
}

TEST(ViscoScramJwl, PressureIsTheJwlClosedForm) {
  const ConstitutiveModelP m = jwl_scram(false);
  EXPECT_FALSE(m->pressure_at_density(kRho0, kRho0, 298.0).has_value());  // gauge hooks: not with JWL
  for (double T : {298.0, 600.0, 3000.0})
    for (double x : {0.5, 0.9, 1.0, 1.05, 1.2, 1.5, 2.0}) {
      const double rho = x * kRho0;
      const SolidEosPoint e = abs_eos(*m).absolute_pressure_at_density(rho, kRho0, T, kPref);
      EXPECT_NEAR(e.pressure, p_closed(rho, T), 1e-14 * p_scale(rho, T)) << x << " " << T;
      EXPECT_NEAR(e.dp_drho, dp_closed(rho, T), 1e-13 * std::abs(dp_closed(rho, T))) << x << " " << T;
      EXPECT_EQ(e.c2, e.dp_drho);  // Vaango: tmp = dp_drho
      // The MPMICE hooks: absolute as is (no p_ref added), gauge = absolute - p_ref.
      EXPECT_EQ(mpmice_absolute_pressure_at_density(*m, rho, kRho0, T, kPref)->pressure, e.pressure);
      EXPECT_EQ(mpmice_pressure_at_density(*m, rho, kRho0, T, kPref)->pressure, e.pressure - kPref);
    }
  // Hand value at rho0, 298 K: A e^-14.1 + B e^-1.41 + om Cv 298 = 103348.70 Pa
  // (the deck's constants put the unstressed solid at about p_ref).
  EXPECT_NEAR(abs_eos(*m).absolute_pressure_at_density(kRho0, kRho0, 298.0, kPref).pressure, 103348.70, 0.01);
}

TEST(ViscoScramJwl, DpDrhoMatchesFiniteDifferences) {
  for (bool modified : {false, true}) {
    const ConstitutiveModelP m = jwl_scram(modified);
    for (double T : {298.0, 600.0})
      for (double x : {0.5, 0.93, 1.01, 1.1, 1.4, 2.0}) {  // 1.01: clear of the kink at rho_ref
        const double rho = x * kRho0, h = 1e-6 * rho;
        auto p = [&](double r) { return abs_eos(*m).absolute_pressure_at_density(r, kRho0, T, kPref).pressure; };
        const double fd = (p(rho + h) - p(rho - h)) / (2 * h);
        const double dp = abs_eos(*m).absolute_pressure_at_density(rho, kRho0, T, kPref).dp_drho;
        // O(h^2) truncation + round-off eps p_scale/h: both below 1e-7 of |dp| here.
        EXPECT_NEAR(dp, fd, 1e-7 * std::abs(dp) + 1e-16 * p_scale(rho, T) / h) << modified << " " << x << " " << T;
      }
  }
}

// At 298 K p(rho) rises from 0 to 1.73e8 Pa (rho = 0.30 rho0), falls to
// -3.35e8 Pa (0.87 rho0) and rises steeply through p_ref near rho0: three
// roots for 0 < p < 1.73e8 Pa; at 600 K it is monotone.
// rho(p): p(rho(p)) = p on the compression branch (dp/drho > 0 there), the
// root nearest rho0 for atmospheric pressure (a bisection on [0.95, 1.2] rho0
// of the closed form gives the reference), and rho(p(rho)) = rho for rho on
// that branch.
TEST(ViscoScramJwl, DensityAtPressureRoundTrip) {
  const ConstitutiveModelP m = jwl_scram(false);
  for (double T : {298.0, 600.0}) {
    for (double p : {-1e8, 1.0, 1e3, kPref, 1e6, 4.83e6, 1e8, 1e10, 3e10}) {
      if (p < 0 && T > 300) continue;  // no negative pressure at 600 K
      const double rho = abs_eos(*m).density_at_absolute_pressure(p, kRho0, T, kPref);
      const SolidEosPoint e = abs_eos(*m).absolute_pressure_at_density(rho, kRho0, T, kPref);
      EXPECT_NEAR(e.pressure, p, 1e-12 * p_scale(rho, T)) << p << " " << T;
      EXPECT_GT(e.dp_drho, 0.0) << p << " " << T;
      EXPECT_EQ(*mpmice_density_at_absolute_pressure(*m, p, kRho0, T, kPref), rho);
      EXPECT_EQ(*mpmice_density_at_pressure(*m, p - kPref, kRho0, T, kPref), rho);
    }
    // The bracket holds one root: [0.95, 1.2] rho0 at 298 K (above the dip);
    // at 600 K p(rho) is monotone and p_ref is reached far below rho0.
    double lo = (T < 300 ? 0.95 : 1e-5) * kRho0, hi = 1.2 * kRho0;
    ASSERT_LT(p_closed(lo, T), kPref);
    ASSERT_GT(p_closed(hi, T), kPref);
    for (int i = 0; i < 200; ++i) (p_closed(0.5 * (lo + hi), T) < kPref ? lo : hi) = 0.5 * (lo + hi);
    EXPECT_NEAR(abs_eos(*m).density_at_absolute_pressure(kPref, kRho0, T, kPref), 0.5 * (lo + hi), 1e-13 * kRho0) << T;
    for (double x : {0.97, 1.0, 1.02, 1.1, 1.3, 1.7}) {
      const double rho = x * kRho0;
      const double p = p_closed(rho, T);
      EXPECT_NEAR(abs_eos(*m).density_at_absolute_pressure(p, kRho0, T, kPref), rho, 1e-13 * rho) << x << " " << T;
    }
  }
}

// The modified EOS: C^1 at rho_ref, the power law below it (closed form with
// K0 from the closed-form derivative), positive for any expansion, and its
// inverse.
TEST(ViscoScramJwl, ModifiedEosBelowTheReferenceDensity) {
  const ConstitutiveModelP m = jwl_scram(true);
  const double T = 298.0;
  const double rho_ref = abs_eos(*m).density_at_absolute_pressure(kPref, kRho0, T, kPref);
  EXPECT_NEAR(p_closed(rho_ref, T), kPref, 1e-12 * p_scale(rho_ref, T));
  const double K0 = rho_ref * dp_closed(rho_ref, T);
  const SolidEosPoint below = abs_eos(*m).absolute_pressure_at_density(rho_ref * (1 - 1e-12), kRho0, T, kPref);
  const SolidEosPoint above = abs_eos(*m).absolute_pressure_at_density(rho_ref * (1 + 1e-12), kRho0, T, kPref);
  // Across the gap 2e-12 rho_ref the power law's slope itself changes by
  // n 2e-12 relative (n = K0/p_ref = 6.6e4 here, 1.3e-7); a K0 other than
  // rho_ref dp/drho(rho_ref) (e.g. the hypoelastic K) would jump by ~10 %.
  const double n = K0 / kPref;
  EXPECT_NEAR(below.pressure, above.pressure, 1e-6 * kPref);
  EXPECT_NEAR(below.dp_drho, above.dp_drho, 2 * n * 2e-12 * above.dp_drho);
  for (double x : {1e-6, 0.1, 0.5, 0.8, 0.99}) {
    const double rho = x * rho_ref;
    const double p = kPref * std::pow(x, K0 / kPref);
    const SolidEosPoint e = abs_eos(*m).absolute_pressure_at_density(rho, kRho0, T, kPref);
    EXPECT_NEAR(e.pressure, p, 1e-12 * p) << x;
    EXPECT_NEAR(e.dp_drho, K0 / rho * std::pow(x, K0 / kPref), 1e-12 * e.dp_drho) << x;
    EXPECT_GE(e.pressure, 0.0) << x;
  }
  for (double p : {1e-30, 1e-12, 1.0, 5e4, 1e5}) {
    const double rho = abs_eos(*m).density_at_absolute_pressure(p, kRho0, T, kPref);
    EXPECT_NEAR(rho, rho_ref * std::pow(p / kPref, kPref / K0), 1e-12 * rho) << p;
    EXPECT_LT(rho, rho_ref);
  }
  EXPECT_THROW(static_cast<const ViscoScram&>(*m).modified_eos_pressure(kRho0, kRho0, kPref), std::logic_error);
}

// useJWLEOS needs its constants: a missing one is a deck error naming it.
TEST(ViscoScramJwl, MissingConstantIsADeckError) {
  MapModelParameters p({{"PR", 0.3}, {"CrackParameterA", 1e-3}, {"CrackPowerValue", 10.0},
                        {"CrackMaxGrowthRate", 300.0}, {"StressIntensityF", 500.0}, {"CrackFriction", 0.35},
                        {"InitialCrackRadius", 3e-15}, {"CrackGrowthRate", 12.0}, {"Beta", 1.5e-4},
                        {"Gamma", 1.0}, {"DCp_DTemperature", 3.30773}, {"useJWLEOS", 1}, {"A", kA},
                        {"B", kB}, {"R1", kR1}, {"R2", kR2}, {"om", kOm}});
  for (int i = 0; i < 5; ++i) {
    p.values["G" + std::to_string(i + 1)] = 1e8;
    p.values["RTau" + std::to_string(i + 1)] = 0.0;
  }
  p.enclosing = {{"specific_heat", 996.0}};
  EXPECT_THROW(ViscoScram::create(p), std::invalid_argument);  // no <Cv>
}

}  // namespace
}  // namespace tephra
