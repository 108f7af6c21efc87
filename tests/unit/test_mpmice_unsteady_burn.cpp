// The unsteady WSB burn rate (mpmice/UnsteadyBurn.h, Uintah's
// Unsteady_Burn equations) with the HMX constants of the WSB decks
// (tests/unit/test_mpmice_steady_burn.cpp), rho_c = 1832 kg/m^3, T0 = 298 K,
// CondUnsteadyCoef Nc = 2, GasUnsteadyCoef Ng = 1.5 (distinct, so the two
// relaxation times are told apart). With Ng < 1 (Ts relaxing faster than
// beta) a pressure rise from 1 to 2 MPa leaves a state (beta lagging, Ts
// ahead) where m^2 - b m + c = 0 has no real root (measured with Ng = 0.5:
// b^2 - 4c = -0.153 at Ts = 755.5 K, beta = 1.479e7 K/m): the model needs
// Ng >~ 1 for pressure rises.
//
// Oracles:
//  (1) a fresh surface burns at the steady WSB rate and takes beta* =
//      (Ts* - T0) m* Cp/kc, Ts*;
//  (2) the steady state is a fixed point: at (beta*, Ts*) the unsteady
//      condensed-phase balance m^2 - b m + c = 0 has the root m* (Lengelle's
//      relation with kc beta* = m* Cp (Ts* - T0)), for any dt;
//  (3) at constant p the forward-Euler relaxation has the closed form
//      beta_k = beta* + (beta_0 - beta*)(1 - 1/n)^k, n = Nc kc/(Cp vc dt m*^2)
//      (Ts with n_T = Ng n), and m -> m*(p);
//  (4) as dt -> 0 it is exp(-t/tau), tau = Nc kc/(Cp vc m*^2): the error at
//      t = tau is first order in dt;
//  (5) the returned flux is the smaller root of m^2 - b m + c = 0; BurnrateModCoef
//      Bm gives m* (m/m*)^Bm; b^2 < 4c is a NumericalFailure.
#include <gtest/gtest.h>

#include <cmath>

#include "core/base/Errors.h"
#include "mpmice/UnsteadyBurn.h"

namespace tephra {
namespace {

constexpr double kRho = 1832.0, kT0 = 298.0, kVc = 1 / kRho;

UnsteadyBurnParams hmx(double Bm = 1.0) {
  UnsteadyBurnParams u;
  WsbParams& q = u.wsb;
  q.R = 8.314, q.Ac = 1.637e15, q.Ec = 1.76e5, q.Bg = 1.6e-3, q.Qc = 4.0e5, q.Qg = 3.018e6;
  q.kg = 0.07, q.kc = 0.2, q.Cp = 1.4e3, q.W = 0.0342;
  u.Bm = Bm, u.Nc = 2.0, u.Ng = 1.5;
  return u;
}

// The steady state at p: (beta*, Ts*) and m*.
UnsteadyBurnState steady_state(const UnsteadyBurnParams& u, double p, double* m = nullptr) {
  const WsbState w = wsb_burn_rate(u.wsb, p, kT0, kVc);
  if (m) *m = w.mass_flux;
  UnsteadyBurnState s;
  s.Ts = w.surface_temperature;
  s.beta = (w.surface_temperature - kT0) * w.mass_flux * u.wsb.Cp / u.wsb.kc;
  return s;
}

TEST(UnsteadyBurnRate, FreshSurfaceBurnsAtTheSteadyRate) {
  const UnsteadyBurnParams u = hmx();
  UnsteadyBurnState s;  // no history
  ASSERT_FALSE(s.has_history());
  const UnsteadyBurnRate r = unsteady_burn_rate(u, 2e6, kT0, kVc, 1e-6, s);
  double m = 0;
  const UnsteadyBurnState ss = steady_state(u, 2e6, &m);
  EXPECT_EQ(r.mass_flux, m);
  EXPECT_EQ(r.steady_flux, m);
  EXPECT_DOUBLE_EQ(s.Ts, ss.Ts);
  EXPECT_DOUBLE_EQ(s.beta, ss.beta);
  EXPECT_TRUE(s.has_history());
}

TEST(UnsteadyBurnRate, SteadyStateIsAFixedPoint) {
  const UnsteadyBurnParams u = hmx();
  for (double p : {0.24e6, 2e6, 4.83e6, 5e7})
    for (double dt : {1e-9, 1e-6, 1e-3}) {
      double m = 0;
      UnsteadyBurnState s = steady_state(u, p, &m);
      const UnsteadyBurnState s0 = s;
      const UnsteadyBurnRate r = unsteady_burn_rate(u, p, kT0, kVc, dt, s);
      // Ts* is found to 1e-12 relative; m depends on it through exp(-Ec/(R Ts)) (x Ec/(R Ts) ~ 30).
      EXPECT_NEAR(r.mass_flux, m, 1e-9 * m) << p << " " << dt;
      EXPECT_NEAR(s.beta, s0.beta, 1e-12 * s0.beta);
      EXPECT_NEAR(s.Ts, s0.Ts, 1e-12 * s0.Ts);
    }
}

TEST(UnsteadyBurnRate, ConstantPressureRelaxesAsTheDiscreteClosedForm) {
  const UnsteadyBurnParams u = hmx();
  UnsteadyBurnState s = steady_state(u, 1e6);  // burning steadily at 1 MPa
  const UnsteadyBurnState s0 = s;
  const double p = 2e6, dt = 2e-5;  // then the pressure steps to 2 MPa
  double m2 = 0;
  const UnsteadyBurnState target = steady_state(u, p, &m2);
  const double n = u.Nc * u.wsb.kc / (u.wsb.Cp * kVc) / (dt * m2 * m2), nT = u.Ng * n;
  ASSERT_GT(nT, 1.0);
  double m = 0;
  for (int k = 1; k <= 8000; ++k) {
    m = unsteady_burn_rate(u, p, kT0, kVc, dt, s).mass_flux;
    const double beta_k = target.beta + (s0.beta - target.beta) * std::pow(1 - 1 / n, k);
    const double Ts_k = target.Ts + (s0.Ts - target.Ts) * std::pow(1 - 1 / nT, k);
    ASSERT_NEAR(s.beta, beta_k, 1e-10 * target.beta) << k;
    ASSERT_NEAR(s.Ts, Ts_k, 1e-10 * target.Ts) << k;
  }
  // 8000 steps = 0.16 s, about 12 tau_beta (tau = n dt, about 0.013 s at 2 MPa): converged.
  EXPECT_NEAR(m, m2, 1e-3 * m2);
}

TEST(UnsteadyBurnRate, PressureStepRelaxesWithTheCondensedPhaseTime) {
  const UnsteadyBurnParams u = hmx();
  const double p = 2e6;
  double m2 = 0;
  const UnsteadyBurnState target = steady_state(u, p, &m2);
  const double tau = u.Nc * u.wsb.kc / (u.wsb.Cp * kVc) / (m2 * m2);
  double err[2];
  for (int level = 0; level < 2; ++level) {
    const int steps = 200 << level;
    const double dt = tau / steps;
    UnsteadyBurnState s = steady_state(u, 1e6);
    const double beta0 = s.beta;
    for (int k = 0; k < steps; ++k) unsteady_burn_rate(u, p, kT0, kVc, dt, s);
    // d beta/dt = (beta* - beta)/tau: beta(tau) = beta* + (beta0 - beta*) e^-1.
    const double exact = target.beta + (beta0 - target.beta) * std::exp(-1.0);
    err[level] = std::abs(s.beta - exact) / std::abs(beta0 - target.beta);
  }
  // Forward Euler: (1 - dt/tau)^(tau/dt) = e^-1 (1 - dt/(2 tau) + ...): error ~ e^-1 dt/(2 tau).
  EXPECT_NEAR(err[0], std::exp(-1.0) / (2 * 200), 0.01 * std::exp(-1.0) / 400);
  EXPECT_NEAR(err[0] / err[1], 2.0, 0.01);
}

TEST(UnsteadyBurnRate, FluxIsTheSmallerRootAndBurnrateModCoefScalesIt) {
  const UnsteadyBurnParams u = hmx();
  UnsteadyBurnState s = steady_state(u, 1e6);
  const UnsteadyBurnState s1 = s;
  const UnsteadyBurnRate r = unsteady_burn_rate(u, 3e6, kT0, kVc, 1e-4, s);
  const WsbParams& q = u.wsb;
  const double b = 2 * q.kc * s.beta / q.Qc;
  const double c = 2 * q.Ac * q.R * q.kc * s.Ts * s.Ts * std::exp(-q.Ec / (q.R * s.Ts)) / (q.Ec * q.Qc * kVc);
  const double m = r.mass_flux;
  EXPECT_NEAR(m * m - b * m + c, 0.0, 1e-12 * c);
  EXPECT_LT(m, b / 2);  // the smaller root
  // Lagging the pressure rise, the unsteady rate is below the new steady one.
  EXPECT_LT(m, r.steady_flux);
  // Bm = 0.5: m*(m/m*)^0.5 from the same state.
  UnsteadyBurnState s2 = s1;
  const UnsteadyBurnRate r2 = unsteady_burn_rate(hmx(0.5), 3e6, kT0, kVc, 1e-4, s2);
  EXPECT_NEAR(r2.mass_flux, r.steady_flux * std::sqrt(m / r.steady_flux), 1e-12 * r.steady_flux);
}

TEST(UnsteadyBurnRate, NoRealRootIsANumericalFailure) {
  // beta = 1 K/m with Ts = 800 K: b^2 = (2 kc/Qc)^2 = 1e-12 << 4c.
  EXPECT_THROW(unsteady_condensed_flux(hmx().wsb, 1.0, 800.0, kVc), NumericalFailure);
}

}  // namespace
}  // namespace tephra
