// jwlpp_mpm (models/solid/JwlppMPM.h): VT §3.5 eqs. 3.12-3.17. Oracles: the
// inventory's ANFO values of the JWL products curve, the Murnaghan reactant and
// the rate G p^b (seed-inventory-vaango-theory.md, "Consistency oracles"), and
// the exact solution of the burn ODE at fixed J for b = 1:
//   df/dt = G (1 - f) (a + D f),  a = p_m, D = p_jwl - p_m,  f(0) = 0
//   => ln[(a + D f) / (a (1 - f))] = (a + D) G t = p_jwl G t
//   => f(t) = a (e^s - 1) / (a e^s + D),  s = p_jwl G t.
#include <gtest/gtest.h>

#include <cmath>

#include "models/solid/JwlppMPM.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kRho0 = 1160.0;

// ANFO (inputs/ICE/EOSData: Souers' JWL++ constants) with the deck's rate law.
JwlppParams anfo() {
  JwlppParams p;
  p.ignition_pressure = 2.0e8 * 0.5;
  p.kappa = 3.9e-10;
  p.n = 7.4;
  p.A = 2.9867e11;
  p.B = 4.11706e9;
  p.C = 7.206147e8;
  p.R1 = 4.95;
  p.R2 = 1.15;
  p.omega = 0.35;
  p.G = 3.5083e-7;
  p.b = 1.3;
  return p;
}

test::MapModelParameters deck_params() {
  const JwlppParams a = anfo();
  return test::MapModelParameters({{"ignition_pressure", a.ignition_pressure}, {"viscosity", 0.0},
                                   {"murnaghan_K", a.kappa}, {"murnaghan_n", a.n}, {"jwl_A", a.A},
                                   {"jwl_B", a.B}, {"jwl_C", a.C}, {"jwl_R1", a.R1}, {"jwl_R2", a.R2},
                                   {"jwl_om", a.omega}, {"reaction_G", a.G}, {"reaction_b", a.b},
                                   {"max_burn_timestep_size", 1e-9}});
}

TEST(ModelJwlpp, PressuresMatchTheInventoryOracles) {
  const JwlppParams p = anfo();
  const double v[5] = {0.5, 0.75, 1.0, 2.0, 5.0};
  const double jwl[5] = {2.929058e10, 1.009288e10, 4.139829e9, 7.104488e8, 9.515654e7};
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(jwlpp_jwl_pressure(v[k], p), jwl[k], 2e-6 * jwl[k]) << v[k];
  EXPECT_NEAR(jwlpp_murnaghan_pressure(0.95, p), 1.599641e8, 1e-6 * 1.599641e8);
  EXPECT_NEAR(jwlpp_murnaghan_pressure(0.9, p), 4.091295e8, 1e-6 * 4.091295e8);
  EXPECT_NEAR(jwlpp_murnaghan_pressure(0.8, p), 1.459999e9, 1e-6 * 1.459999e9);
}

TEST(ModelJwlpp, FastSchemeRateIsGpb) {
  // One two-stage step from f = 0: f = fac / (1 + fac), fac = dt G p^b, so G p^b = f / ((1 - f) dt).
  // Inventory: G p^b = 2.169880e4 /s at 200 MPa, 1.758315e5 at 1 GPa (ANFO).
  JwlppParams p = anfo();
  p.fast_compute = true;
  p.max_burn_timestep = 1.0;
  const double dt = 1e-7;
  for (auto [pr, rate] : {std::pair{2.0e8, 2.169880e4}, std::pair{1.0e9, 1.758315e5}}) {
    double f = 0, pn = 0;
    ASSERT_TRUE(jwlpp_burn_update(0.9, 0.9, 0.0, pr, dt, p, f, pn));
    EXPECT_NEAR(f / ((1 - f) * dt), rate, 1e-6 * rate);
    // p = (1 - f) p_m + f p_jwl (eq. 3.15)
    EXPECT_NEAR(pn, (1 - f) * jwlpp_murnaghan_pressure(0.9, p) + f * jwlpp_jwl_pressure(0.9, p), 1e-6);
  }
}

TEST(ModelJwlpp, BackwardEulerConvergesToTheExactBurnAtFixedJ) {
  JwlppParams p = anfo();
  p.b = 1.0;
  p.G = 1.0e-4 / 4.0e9;  // G p ~ 1e-4 /s ... scaled below by the time
  const double J = 0.9;
  const double a = jwlpp_murnaghan_pressure(J, p), pj = jwlpp_jwl_pressure(J, p), D = pj - a;
  const double t = 1.5 / (pj * p.G);  // s = 1.5
  const double s = pj * p.G * t;
  const double exact = a * std::expm1(s) / (a * std::exp(s) + D);
  double err[3];
  for (int k = 0; k < 3; ++k) {
    p.max_burn_timestep = t / (50 << k);
    double f = 0, pn = 0;
    ASSERT_TRUE(jwlpp_burn_update(J, J, 0.0, a, t, p, f, pn));
    err[k] = std::abs(f - exact);
    EXPECT_NEAR(pn, (1 - f) * a + f * pj, 1e-6 * pj);
  }
  std::printf("jwlpp burn at J = 0.9: f exact %.8f, errors %.3e %.3e %.3e (50/100/200 substeps)\n", exact, err[0],
              err[1], err[2]);
  EXPECT_LT(err[2], 2e-3);
  EXPECT_NEAR(err[0] / err[1], 2.0, 0.15);  // backward Euler: first order
  EXPECT_NEAR(err[1] / err[2], 2.0, 0.15);
}

TEST(ModelJwlpp, NoBurnBelowIgnitionAndTheFractionIsCapped) {
  JwlppParams p = anfo();
  p.max_burn_timestep = 1e-8;
  double f = 0, pn = 0;
  ASSERT_TRUE(jwlpp_burn_update(0.95, 0.9, 0.2, 0.5 * p.ignition_pressure, 1e-6, p, f, pn));
  EXPECT_EQ(f, 0.2);
  EXPECT_NEAR(pn, 0.8 * jwlpp_murnaghan_pressure(0.9, p) + 0.2 * jwlpp_jwl_pressure(0.9, p), 1e-6);
  p.max_burned_fraction = 0.3;
  ASSERT_TRUE(jwlpp_burn_update(0.9, 0.9, 0.0, 1e9, 1e-3, p, f, pn));  // would burn out
  EXPECT_EQ(f, 0.3);
}

TEST(ModelJwlpp, SpanUpdateCarriesTheBurnFraction) {
  auto params = deck_params();
  const auto m = create_constitutive_model("jwlpp_mpm", params);
  ASSERT_EQ(m->history().size(), 2u);
  EXPECT_EQ(m->history()[0].name, "progressF");
  EXPECT_EQ(m->history()[1].name, "progressdelF");
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const M3 F = Eigen::Vector3d(0.9, 1, 1).asDiagonal();
  // Step 1 compresses: p_n = 0 < ignition, no burn; sigma = -p_m(0.9) I.
  ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-7), -1);
  const JwlppParams p = anfo();
  EXPECT_EQ(s.history[0][0], 0.0);
  EXPECT_NEAR(-s.stress(0, 0), jwlpp_murnaghan_pressure(0.9, p), 1e-6);
  // c^2 = (1/(kappa rho0)) (rho/rho0)^{n-1} for f = 0 (Vaango's wave speed).
  EXPECT_NEAR(s.wave_speed * s.wave_speed, std::pow(1 / 0.9, p.n - 1) / (p.kappa * kRho0), 1e-6);
  // Step 2 at fixed J: p_n = 4.09e8 > ignition: burns; f and delF recorded.
  ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-6), -1);
  EXPECT_GT(s.history[0][0], 0.0);
  EXPECT_EQ(s.history[1][0], s.history[0][0]);
  double f = 0, pn = 0;
  JwlppParams q = p;
  q.max_burn_timestep = 1e-9;
  ASSERT_TRUE(jwlpp_burn_update(0.9, 0.9, 0.0, jwlpp_murnaghan_pressure(0.9, p), 1e-6, q, f, pn));
  EXPECT_NEAR(s.history[0][0], f, 1e-14);
  EXPECT_NEAR(-s.stress(1, 1), pn, 1e-6 * pn);
}

TEST(ModelJwlpp, MpmIceHooksAreTheUnreactedMurnaghan) {
  const auto m = create_constitutive_model("jwlpp_mpm", deck_params());
  const JwlppParams p = anfo();
  for (double x : {0.9, 1.0, 1.1, 1.25}) {
    const double rho = x * kRho0;
    const SolidEosPoint e = *m->pressure_at_density(rho, kRho0, 300);
    EXPECT_NEAR(e.pressure, jwlpp_murnaghan_pressure(1 / x, p), 1e-6 * (1 + std::abs(e.pressure)));
    EXPECT_NEAR(e.dp_drho, std::pow(x, p.n - 1) / (p.kappa * kRho0), 1e-9 * e.dp_drho);
    EXPECT_NEAR(*m->density_at_pressure(e.pressure, kRho0, 300), rho, 1e-10 * rho);
  }
}

TEST(ModelJwlpp, BadParametersAreErrorsAndMissingFeatures) {
  auto p = deck_params();
  p.values.erase("jwl_A");
  EXPECT_THROW(create_constitutive_model("jwlpp_mpm", p), std::invalid_argument);
  p = deck_params();
  p.values["max_burned_fraction"] = 1.5;
  EXPECT_THROW(create_constitutive_model("jwlpp_mpm", p), std::invalid_argument);
  p = deck_params();
  p.values["useInitialStress"] = 1;
  EXPECT_THROW(create_constitutive_model("jwlpp_mpm", p), std::logic_error);
  p = deck_params();
  p.values["jwl_rho0"] = kRho0;
  p.enclosing = {{"density", kRho0}};
  EXPECT_NO_THROW(create_constitutive_model("jwlpp_mpm", p));
  p.enclosing = {{"density", 2 * kRho0}};
  EXPECT_THROW(create_constitutive_model("jwlpp_mpm", p), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
