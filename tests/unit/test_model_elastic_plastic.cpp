// elastic_plastic (VT ch. 18, J2 return with the temperature of eq. 18.55 in the
// backward-Euler system): closed forms, the consistency of the return, the
// adiabatic Johnson-Cook point against an offline integration, the thermal
// pressure of eq. 18.81, damage and porosity evolution, MTS, missing features.
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/ElasticPlastic.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

double von_mises(const Eigen::Matrix3d& s) {
  const Eigen::Matrix3d d = s - (s.trace() / 3.0) * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * d.squaredNorm());
}

// Copper-tube values of the inventory (ch. 17 oracle): K = 117 GPa, G = 43.8 GPa, sigma_0 = 70 MPa.
constexpr double kK = 117e9, kG = 43.8e9, kS0 = 70e6;

MapModelParameters linear_parameters(double H) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"isothermal", 1.0},
                        {"coeff_thermal_expansion", 0.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", H}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}};
  return p;
}

// Uniaxial strain F = diag(lambda, 1, 1), eps = ln(lambda). J2 with linear
// isotropic hardening sigma_y = s0 + H ep (the ch. 17 inventory oracle's derivation):
//   ep = max(0, (2G eps - s0)/(3G + H)),  y = 2G eps (elastic) or s0 + H ep,
//   sigma_11 = K eps + 2/3 y,  sigma_22 = K eps - 1/3 y  (default_hypo: tr(sigma)/3 = K eps).
// The return is exact on a proportional path: round-off and the O(h^3) midpoint kinematics remain.
TEST(ElasticPlastic, UniaxialStrainLinearHardeningClosedForm) {
  for (const double H : {0.0, 1.0e9, 2.0e10}) {
    const auto m = create_constitutive_model("elastic_plastic", linear_parameters(H));
    ASSERT_TRUE(m);
    test::PointState s(*m);
    const int n = 400;
    for (int k = 1; k <= n; ++k) {
      const double eps = 0.01 * k / n;
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(0, 0) = std::exp(eps);
      ASSERT_EQ(test::step_point(*m, 8930.0, s, F, 1e-6), -1);
      const double ep = std::max(0.0, (2 * kG * eps - kS0) / (3 * kG + H));
      const double y = 2 * kG * eps <= kS0 ? 2 * kG * eps : kS0 + H * ep;
      EXPECT_NEAR(s.stress(0, 0), kK * eps + 2.0 / 3.0 * y, 1e-9 * 1.2e9) << "H " << H << " eps " << eps;
      EXPECT_NEAR(s.stress(1, 1), kK * eps - 1.0 / 3.0 * y, 1e-9 * 1.2e9) << "H " << H << " eps " << eps;
      EXPECT_NEAR(s.history[0][0], ep, 1e-12) << "H " << H << " eps " << eps;
      EXPECT_EQ(s.heating, 0.0);  // isothermal
    }
  }
  // The inventory's printed perfect-plasticity rows (7 significant digits).
  const auto m = create_constitutive_model("elastic_plastic", linear_parameters(0.0));
  const double rows[3][3] = {{0.001, 1.636667e8, 9.366667e7}, {0.002, 2.806667e8, 2.106667e8},
                             {0.01, 1.216667e9, 1.146667e9}};
  for (const auto& r : rows) {
    test::PointState s(*m);
    for (int k = 1; k <= 100; ++k) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(0, 0) = std::exp(r[0] * k / 100);
      ASSERT_EQ(test::step_point(*m, 8930.0, s, F, 1e-6), -1);
    }
    EXPECT_NEAR(s.stress(0, 0) / r[1], 1.0, 5e-7);
    EXPECT_NEAR(s.stress(1, 1) / r[2], 1.0, 5e-7);
  }
}

// A4 constants (decks README): OFHC Cu, Johnson-Cook, chi = 0.9, rho = 8930, cp = 414, T0 = 696 K;
// JC's T_r = 298, T_m = 1793 (Vaango's defaults; the deck leaves them out).
constexpr double kA = 90e6, kB = 292e6, kC = 0.025, kN = 0.31, kM = 1.09, kTr = 298, kTm = 1793;
constexpr double kRho = 8930, kCp = 414, kChi = 0.9, kT0 = 696, kRate = 4000;

double jc(double ep, double rate, double T) {  // VT eq. 10.2-10.3 (rate* > 1 here)
  const double Ts = (T - kTr) / (kTm - kTr);
  return (kA + kB * std::pow(ep, kN)) * (1 + kC * std::log(rate)) * (1 - std::pow(Ts, kM));
}

MapModelParameters jc_parameters(bool isothermal, double alpha = 0.0) {
  MapModelParameters p({{"bulk_modulus", 129e9}, {"shear_modulus", 46e9}, {"taylor_quinney_coeff", kChi},
                        {"isothermal", isothermal ? 1.0 : 0.0}, {"coeff_thermal_expansion", alpha},
                        {"evolve_porosity", 0.0}, {"evolve_damage", 0.0}, {"tolerance", 1e-12}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "johnson_cook", {{"A", kA}, {"B", kB}, {"C", kC}, {"n", kN}, {"m", kM}});
  p.add_block("equation_of_state", "mie_gruneisen", {{"C_0", 3940}, {"Gamma_0", 2.02}, {"S_alpha", 1.489}, {"rho_0", kRho}});
  p.add_block("shear_modulus_model", "constant_shear", {{"shear_modulus", 46e9}});
  p.add_block("melting_temp_model", "constant_Tm");
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", kCp}, {"density", kRho}};
  return p;
}

// Consistency of the return (VT §18.7.3 at convergence), for random trial states
// of the rate- and temperature-dependent JC law with adiabatic heating:
//   (a) the returned deviator is on the yield surface: |q - sigma_y(eps_p, eps_p_dot, T_{n+1})| <= 1e-10 sigma_y;
//   (b) the plastic strain increment obeys the flow rule: Dg = (q_trial - q)/(3 mu), s parallel to s_trial;
//   (c) the temperature obeys (18.55): T_{n+1} - T_n = Dg chi sigma_y/(rho C_p) = heating dt.
TEST(ElasticPlastic, RadialReturnIsConsistent) {
  const auto base = create_constitutive_model("elastic_plastic", jc_parameters(false));
  const auto& m = static_cast<const ElasticPlastic&>(*base);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int plastic = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double dt = 1e-7 * (1.5 + u(rng));
    Eigen::Matrix3d D;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) D(i, j) = u(rng);
    D = (0.5 * (D + D.transpose())).eval();  // eval: D appears on both sides
    D *= 2e4 / D.norm();  // |d| ~ 2e4 /s
    const Eigen::Matrix3d F_old = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d F_new = Eigen::Matrix3d::Identity() + D * dt;  // symmetric: U_{n+1} = F, R = I
    Eigen::Matrix3d s_old;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s_old(i, j) = u(rng);
    s_old = (0.5 * (s_old + s_old.transpose())).eval();
    s_old -= s_old.trace() / 3.0 * Eigen::Matrix3d::Identity();
    const double ep_n = 0.5 * (1 + u(rng));
    s_old *= 0.9 * jc(ep_n, kRate, kT0) / von_mises(s_old);  // inside the current surface
    double hist[6] = {ep_n, 0, 0, 0, 0, 0};
    ElasticPlastic::PointOut out;
    ASSERT_TRUE(m.update_point(F_old, F_new, s_old, kT0, dt, kRho, hist, out));
    const double dg = hist[0] - ep_n;
    if (dg <= 0) continue;
    ++plastic;
    const double T1 = kT0 + out.heating * dt;
    const double q = von_mises(out.r.stress);
    const double rate = dg / dt;
    const double sy = jc(hist[0], std::max(rate, 1.0), T1);
    EXPECT_NEAR(q / sy, 1.0, 1e-10) << trial;                                      // (a)
    const double rho = kRho / F_new.determinant();  // current density
    EXPECT_NEAR(T1 - kT0, dg * kChi * sy / (rho * kCp), 1e-12 * kT0) << trial;     // (c)
    // (b): the trial deviator of the unrotated increment (F_old = I: U_n = I, midpoint rule).
    const Eigen::Matrix3d G = (F_new - Eigen::Matrix3d::Identity()) * (0.5 * (F_new + Eigen::Matrix3d::Identity())).inverse();
    const Eigen::Matrix3d de = 0.5 * (G + G.transpose());
    const Eigen::Matrix3d s_trial = s_old + 2 * 46e9 * (de - de.trace() / 3 * Eigen::Matrix3d::Identity());
    const Eigen::Matrix3d s_new = out.r.stress - out.r.stress.trace() / 3 * Eigen::Matrix3d::Identity();
    // round-off of q, recovered from the rotated total stress: ~1e-12 of the trial scale q_trial/(3 mu)
    EXPECT_NEAR(dg, (von_mises(s_trial) - q) / (3 * 46e9), 1e-12 * von_mises(s_trial) / (3 * 46e9)) << trial;
    EXPECT_LT((s_new / q - s_trial / von_mises(s_trial)).norm(), 1e-12) << trial;
    EXPECT_NEAR(out.plastic_work, F_new.determinant() * sy * dg, 1e-9 * sy * dg);  // J sigma_y Dg
  }
  EXPECT_GT(plastic, 100);  // most trials load plastically
}

double offline_temperature(double ep_end) {  // dT/d ep = chi sigma(ep, eps_dot, T)/(rho cp), RK4 from (0, T0)
  const int n = 20000;
  const double h = ep_end / n;
  double T = kT0;
  auto f = [](double ep, double T) { return kChi * jc(ep, kRate, T) / (kRho * kCp); };
  for (int i = 0; i < n; ++i) {
    const double e = i * h;
    const double k1 = f(e, T), k2 = f(e + h / 2, T + h / 2 * k1), k3 = f(e + h / 2, T + h / 2 * k2),
                 k4 = f(e + h, T + h * k3);
    T += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return T;
}

struct JcRun {
  double q, ep, T;
};
// Isochoric stretch F = diag(l, l^-1/2, l^-1/2), l = exp(eps_dot t): equivalent rate eps_dot,
// p = 0, so q = sigma_y after yield; the driver's explicit update T += heating dt.
JcRun run_jc(int n, bool isothermal) {
  const auto m = create_constitutive_model("elastic_plastic", jc_parameters(isothermal));
  test::PointState s(*m);
  s.temperature = kT0;
  const double t_end = 0.3 / kRate, dt = t_end / n;
  for (int k = 1; k <= n; ++k) {
    const double l = std::exp(kRate * dt * k);
    const Eigen::Matrix3d F = Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal();
    if (test::step_point(*m, kRho, s, F, dt) != -1) throw std::runtime_error("step failed");
    s.temperature += s.heating * dt;
  }
  return {von_mises(s.stress), s.history[0][0], s.temperature};
}

// A4's point: the coupled return integrates dT = chi sigma_y d eps_p/(rho c_p) by backward
// Euler in eps_p, so the temperature error against the offline RK4 curve is first order
// in dt (halves with dt) and the stress stays on the JC curve at the run's own T to 1e-10.
TEST(ElasticPlastic, JohnsonCookAdiabaticMatchesOfflineIntegration) {
  double prev_err = 0;
  for (const int n : {1000, 2000}) {
    const JcRun r = run_jc(n, false);
    const double T_off = offline_temperature(r.ep);
    const double err_T = std::abs(r.T - T_off);
    std::printf("n %d: ep %.6f  T %.5f (offline %.5f)  q %.6e (JC at T_off %.6e)\n", n, r.ep, r.T, T_off, r.q,
                jc(r.ep, kRate, T_off));
    EXPECT_GT(r.T - kT0, 5.0);
    // eps_p_dot differs from eps_dot by the elastic rate q_dot/(3G) (~1e-3 relative; C ln: ~3e-5).
    EXPECT_NEAR(r.q / jc(r.ep, kRate, T_off), 1.0, 5e-5);
    EXPECT_LT(err_T, 0.01);
    if (prev_err > 0) EXPECT_LT(err_T, 0.6 * prev_err);
    prev_err = err_T;
  }
  const JcRun iso = run_jc(1000, true), adi = run_jc(1000, false);
  EXPECT_DOUBLE_EQ(iso.T, kT0);
  EXPECT_NEAR(iso.q / jc(iso.ep, kRate, kT0), 1.0, 1e-4);
  EXPECT_LT(adi.q, iso.q);  // README A4: stress at fixed strain decreases with the temperature rise
}

// VT eq. 18.81 with default_hypo (kappa = K): heating an unstrained point by dT from its
// first temperature T_0 gives sigma = -3 K alpha dT I, and cooling back gives 0.
TEST(ElasticPlastic, ThermalPressureOfEquation18_81) {
  auto p = linear_parameters(0.0);
  p.values["coeff_thermal_expansion"] = 2e-5;
  const auto m = create_constitutive_model("elastic_plastic", p);
  test::PointState s(*m);
  s.temperature = 400;
  ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Matrix3d::Identity(), 0.0), -1);
  EXPECT_EQ(s.stress.norm(), 0.0);
  s.temperature = 410;
  ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Matrix3d::Identity(), 1e-6), -1);
  EXPECT_NEAR(s.stress(0, 0), -3 * kK * 2e-5 * 10, 1e-9 * kK * 6e-4);
  EXPECT_NEAR(s.stress(0, 1), 0.0, 1e-6);
  ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Matrix3d::Identity(), 1e-6), -1);  // same T: unchanged
  EXPECT_NEAR(s.stress(1, 1), -3 * kK * 2e-5 * 10, 1e-9 * kK * 6e-4);
  s.temperature = 400;
  ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Matrix3d::Identity(), 1e-6), -1);
  EXPECT_NEAR(s.stress.norm(), 0.0, 1e-6);
}

// Hancock-MacKenzie damage (VT 15.1-15.2) in isochoric stretch with p ~ 0 (triaxiality
// sigma* = tr(sigma)/(3 q) = p/q ~ 0): D = D0 + int eps_p_dot exp(3 sigma*/2)/1.65 dt.
// Void nucleation (VT 12.9) with f_n, eps_n, s_n: phi = f0 + int A(eps_p) d eps_p =
// f0 + f_n/2 [erf((eps_p - eps_n)/(s_n sqrt 2)) - erf(-eps_n/(s_n sqrt 2))].
TEST(ElasticPlastic, DamageAndPorosityEvolution) {
  auto p = linear_parameters(1e9);
  p.values["evolve_damage"] = 1.0;
  p.values["evolve_porosity"] = 1.0;
  p.values["frac_nucleation"] = 0.04;
  p.values["meanstrain_nucleation"] = 0.05;
  p.values["stddevstrain_nucleation"] = 0.02;
  p.values["initial_mean_porosity"] = 0.001;
  p.values["check_max_stress_failure"] = 0.0;
  p.add_block("damage_model", "hancock_mackenzie", {{"D0", 1e-4}, {"Dc", 0.7}});
  const auto m = create_constitutive_model("elastic_plastic", p);
  test::PointState s(*m);
  EXPECT_EQ(s.history[4][0], 1e-4);   // D0 of the damage model
  EXPECT_EQ(s.history[3][0], 0.001);  // f0
  const int n = 4000;
  double D = 1e-4;
  for (int k = 1; k <= n; ++k) {
    const double l = std::exp(0.1 * k / n);
    const double ep_old = s.history[0][0];
    ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal().toDenseMatrix(), 1e-6), -1);
    const double q = von_mises(s.stress), sstar = s.stress.trace() / (3 * q);
    D += (s.history[0][0] - ep_old) * std::exp(1.5 * sstar) / 1.65;
  }
  const double ep = s.history[0][0];
  EXPECT_GT(ep, 0.09);
  EXPECT_NEAR(s.history[4][0], D, 1e-12);
  EXPECT_NEAR(s.history[4][0] - 1e-4, ep / 1.65, 1e-3 * ep);  // sigma* ~ 0
  const double phi = 0.001 + 0.02 * (std::erf((ep - 0.05) / (0.02 * std::sqrt(2.0))) - std::erf(-0.05 / (0.02 * std::sqrt(2.0))));
  EXPECT_NEAR(s.history[3][0], phi, 2e-4 * 0.04);  // explicit Euler in eps_p, d eps_p = 2.5e-5
  EXPECT_EQ(s.history[5][0], 0.0);  // TEPLA (phi/0.5)^2 + D^2 ~ 4e-3: intact
}

// TEPLA failure: porosity past the critical value flags the point ("localized" = 1).
TEST(ElasticPlastic, TeplaFailureFlagsThePoint) {
  auto p = linear_parameters(1e9);
  p.values["initial_mean_porosity"] = 0.6;  // phi/f_c = 1.2 > 1 at the first plastic step
  p.values["check_max_stress_failure"] = 0.0;
  const auto m = create_constitutive_model("elastic_plastic", p);
  test::PointState s(*m);
  const double l = std::exp(0.0005);  // elastic (2G eps = 44 MPa < 70 MPa): not checked
  ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal().toDenseMatrix(), 1e-6), -1);
  EXPECT_EQ(s.history[5][0], 0.0);
  const double l2 = std::exp(0.01);  // plastic
  ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Vector3d(l2, 1 / std::sqrt(l2), 1 / std::sqrt(l2)).asDiagonal().toDenseMatrix(), 1e-6), -1);
  EXPECT_EQ(s.history[5][0], 1.0);
}

// <critical_porosity> is the phi_c of the TEPLA criterion (VT eq. 16.1, Vaango's form
// (phi/phi_c)^2 + D^2 > 1 after a plastic step; no damage model: D = 0). phi_0 = 0.3 and no
// nucleation (frac_nucleation 0; J2 flow is isochoric, so no growth): with the default
// phi_c = 0.5, (0.3/0.5)^2 = 0.36 < 1, not failed; with phi_c = 0.25, (0.3/0.25)^2 = 1.44 > 1, failed.
TEST(ElasticPlastic, TeplaCriterionUsesTheCriticalPorosity) {
  for (const double fc : {0.0, 0.25}) {  // 0: the tag absent (default 0.5)
    auto p = linear_parameters(1e9);
    p.values["initial_mean_porosity"] = 0.3;
    p.values["frac_nucleation"] = 0.0;
    p.values["check_max_stress_failure"] = 0.0;
    if (fc > 0) p.values["critical_porosity"] = fc;
    const auto m = create_constitutive_model("elastic_plastic", p);
    test::PointState s(*m);
    const double l2 = std::exp(0.01);  // plastic
    ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Vector3d(l2, 1 / std::sqrt(l2), 1 / std::sqrt(l2)).asDiagonal().toDenseMatrix(), 1e-6), -1);
    EXPECT_GT(s.history[0][0], 0.0) << "the step must be plastic";
    EXPECT_EQ(s.history[5][0], fc > 0 ? 1.0 : 0.0) << "critical_porosity " << fc;
  }
}

// <compute_specific_heat> true (both metal models, as Vaango's ElasticPlastic and ElasticPlasticHP):
// the heating uses the <specific_heat_model> (here copper_Cp,
// VT eq. 14.2 above T_0 = 270 K: C_p = A_1 T + B_1 = 0.1009 * 300 + 358.4 = 388.67 J/(kg K) with
// Vaango's constants), false: the material's <specific_heat> 414. With the linear (temperature-free)
// flow law the return is the same, so heating ratio = 414 / 388.67 (eq. 18.20: chi sigma_y eps_p_dot/(rho C_p)).
TEST(ElasticPlastic, ComputeSpecificHeatSelectsTheSpecificHeatModel) {
  for (const char* type : {"elastic_plastic", "elastic_plastic_hp"}) {
  SCOPED_TRACE(type);
  double heat[2];
  for (int c = 0; c < 2; ++c) {
    auto p = linear_parameters(1e9);
    p.values["isothermal"] = 0.0;
    p.values["compute_specific_heat"] = c;
    p.add_block("specific_heat_model", "copper_Cp");
    const auto m = create_constitutive_model(type, p);
    test::PointState s(*m);
    s.temperature = 300.0;
    const double l = std::exp(0.01);  // plastic
    ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal().toDenseMatrix(), 1e-6), -1);
    heat[c] = s.heating;
  }
  ASSERT_GT(heat[0], 0.0);
  EXPECT_NEAR(heat[1] / heat[0], 414.0 / (0.1009 * 300 + 358.4), 1e-12);
  }
}

// MTS (VT 10.16-10.23) in the composite: sigma_e is history and grows with eps_p; the
// returned deviator lies on sigma_y(sigma_e,n+1) (the flow law's own value).
TEST(ElasticPlastic, MtsFlowCarriesTheStructureStress) {
  MapModelParameters p({{"bulk_modulus", 129e9}, {"shear_modulus", 46e9}, {"isothermal", 1.0},
                        {"coeff_thermal_expansion", 0.0}, {"tolerance", 1e-12}});
  p.add_block("yield_condition", "von_mises");
  // ETP copper MTS constants (decks MaterialData/MTSPlasticETPCu.xml).
  p.add_block("flow_model", "mts_model",
              {{"sigma_a", 40e6}, {"mu_0", 47.7e9}, {"D", 3.0e9}, {"T_0", 180}, {"koverbcubed", 0.823e6},
               {"g_0i", 0}, {"g_0e", 1.6}, {"edot_0i", 0}, {"edot_0e", 1e7}, {"p_i", 0}, {"q_i", 0},
               {"p_e", 0.667}, {"q_e", 1}, {"sigma_i", 0}, {"a_0", 2390e6}, {"a_1", 12e6}, {"a_2", 1.696e6},
               {"a_3", 0}, {"theta_IV", 0}, {"alpha", 2}, {"edot_es0", 1e7}, {"g_0es", 0.2625}, {"sigma_es0", 770e6}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}, {"density", kRho}};
  const auto m = create_constitutive_model("elastic_plastic", p);
  ASSERT_TRUE(m);
  const auto h = m->history();
  ASSERT_EQ(h.size(), 7u);
  EXPECT_EQ(h[6].name, "mtsStructureStress");
  test::PointState s(*m);
  s.temperature = 296;
  double prev_se = 0;
  for (int k = 1; k <= 200; ++k) {
    const double l = std::exp(0.1 * k / 200);
    ASSERT_EQ(test::step_point(*m, kRho, s, Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal().toDenseMatrix(), 2.5e-7), -1);
    EXPECT_GE(s.history[6][0], prev_se);
    prev_se = s.history[6][0];
  }
  EXPECT_GT(s.history[0][0], 0.09);
  EXPECT_GT(prev_se, 50e6);  // the structure stress has grown (theta_0 ~ 2.5 GPa)
  // q on the flow law at the final state.
  PlasticState st;
  st.eps_p = s.history[0][0];
  st.eps_p_rate = s.history[1][0];
  st.temperature = 296;
  st.sigma_e = s.history[6][0];
  st.density = st.density0 = kRho;
  st.shear_modulus = 46e9;
  const auto& ep = static_cast<const ElasticPlastic&>(*m);
  EXPECT_NEAR(von_mises(s.stress) / ep.flow_->evaluate(st).sigma_y, 1.0, 1e-9);
}

bool is_missing_feature(const MapModelParameters& p) {
  try {
    create_constitutive_model("elastic_plastic", p);
  } catch (const std::invalid_argument&) {
    return false;
  } catch (const std::logic_error&) {
    return true;
  }
  return false;
}

TEST(ElasticPlastic, UnimplementedOptionsAreMissingFeaturesAndBadInputFails) {
  auto g = linear_parameters(0);  // a porous yield with a stability check: the J2-I1 tangent
  g.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
  g.add_block("stability_check", "drucker");
  EXPECT_FALSE(is_missing_feature(g));
  g.add_block("flow_model", "mts_model",  // MTS with a porous yield (test_model_metal_modified_eos_thermal)
              {{"sigma_a", 40e6}, {"mu_0", 47.7e9}, {"D", 3.0e9}, {"T_0", 180}, {"koverbcubed", 0.823e6},
               {"g_0i", 0}, {"g_0e", 1.6}, {"edot_0i", 0}, {"edot_0e", 1e7}, {"p_i", 0}, {"q_i", 0},
               {"p_e", 0.667}, {"q_e", 1}, {"sigma_i", 0}, {"a_0", 2390e6}, {"a_1", 12e6}, {"a_2", 1.696e6},
               {"a_3", 0}, {"theta_IV", 0}, {"alpha", 2}, {"edot_es0", 1e7}, {"g_0es", 0.2625}, {"sigma_es0", 770e6}});
  EXPECT_FALSE(is_missing_feature(g));
  auto k = linear_parameters(0);  // kinematic hardening works with von Mises (test_model_elastic_plastic_kinematic) ...
  k.add_block("kinematic_hardening_model", "prager", {{"hardening_modulus", 1e9}});
  EXPECT_FALSE(is_missing_feature(k));
  k.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
  EXPECT_FALSE(is_missing_feature(k));  // ... and with a porous yield (test_plasticity_porous_kinematic)
  auto st = linear_parameters(0);
  st.add_block("stability_check", "no_such_check");
  EXPECT_THROW(create_constitutive_model("elastic_plastic", st), std::invalid_argument);
  auto me = linear_parameters(0);  // implemented (test_model_metal_modified_eos_thermal)
  me.values["useModifiedEOS"] = 1.0;
  EXPECT_FALSE(is_missing_feature(me));
  auto nf = linear_parameters(0);
  nf.blocks.erase("flow_model");
  EXPECT_THROW(create_constitutive_model("elastic_plastic", nf), std::invalid_argument);
  auto bad = linear_parameters(0);
  bad.add_block("flow_model", "no_such_law");
  EXPECT_THROW(create_constitutive_model("elastic_plastic", bad), std::invalid_argument);
  auto by = linear_parameters(0);
  by.add_block("yield_condition", "no_such_yield");
  EXPECT_THROW(create_constitutive_model("elastic_plastic", by), std::invalid_argument);
  auto nocp = linear_parameters(0);
  nocp.values["isothermal"] = 0.0;
  nocp.enclosing.erase("specific_heat");
  EXPECT_THROW(create_constitutive_model("elastic_plastic", nocp), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
