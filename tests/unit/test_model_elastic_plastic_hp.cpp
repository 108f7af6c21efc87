// elastic_plastic_hp (VT ch. 17, Algorithm 1, von Mises): the radial return
// against closed forms, and the adiabatic Johnson-Cook point against an
// offline integration of the JC law with Taylor-Quinney heating.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "models/solid/ConstitutiveModel.h"
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

ConstitutiveModelP linear_model(double H) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", H}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}};
  return create_constitutive_model("elastic_plastic_hp", p);
}

// Uniaxial strain F = diag(lambda, 1, 1), small steps; eps = ln(lambda) (the
// hypoelastic log strain). J2 with linear isotropic hardening sigma_y = s0 + H ep:
//   elastic while 2G eps <= s0;  then  ep = (2G eps - s0)/(3G + H),
//   sigma_11 = K eps + 2/3 (s0 + H ep),  sigma_22 = K eps - 1/3 (s0 + H ep)
// (deviatoric strain 2/3 eps, s_11 = 2G(2/3 eps - ep), q = 3/2 s_11 = s0 + H ep;
// pressure from default_hypo: tr(sigma)/3 = K eps). Radial return is exact on
// this proportional path, so only round-off and the O(h^3) midpoint kinematics remain.
TEST(ElasticPlasticHP, UniaxialStrainLinearHardeningClosedForm) {
  for (const double H : {0.0, 1.0e9, 2.0e10}) {
    const auto m = linear_model(H);
    ASSERT_TRUE(m);
    test::PointState s(*m);
    const int n = 400;
    const double eps_end = 0.01;
    for (int k = 1; k <= n; ++k) {
      const double eps = eps_end * k / n;
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(0, 0) = std::exp(eps);
      ASSERT_EQ(test::step_point(*m, 8930.0, s, F, 1e-6), -1);
      const double ep = std::max(0.0, (2 * kG * eps - kS0) / (3 * kG + H));
      const double y = 2 * kG * eps <= kS0 ? 2 * kG * eps : kS0 + H * ep;
      EXPECT_NEAR(s.stress(0, 0), kK * eps + 2.0 / 3.0 * y, 1e-9 * 1.2e9) << "H " << H << " eps " << eps;
      EXPECT_NEAR(s.stress(1, 1), kK * eps - 1.0 / 3.0 * y, 1e-9 * 1.2e9) << "H " << H << " eps " << eps;
      EXPECT_NEAR(s.history[0][0], ep, 1e-12) << "H " << H << " eps " << eps;
    }
  }
}

// The inventory's printed oracle (elastic-perfectly-plastic, ch. 17): sigma_11 and
// sigma_22 at eps = 0.001, 0.002, 0.01 (7 significant digits printed).
TEST(ElasticPlasticHP, PerfectPlasticityInventoryOracle) {
  const auto m = linear_model(0.0);
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
    EXPECT_NEAR(von_mises(s.stress), kS0, 1e-9 * kS0);  // on the yield surface
  }
}

// A4 (decks README, adiCuJC4000s696K): OFHC Cu, Johnson-Cook flow, eps_dot = 4000/s,
// T0 = 696 K, chi = 0.9, rho = 8930, cp = 414; JC's T_r = 298, T_m = 1793 (Vaango
// defaults, the deck leaves them out). Isochoric stretch F = diag(l, l^-1/2, l^-1/2),
// l = exp(eps_dot t): equivalent rate eps_dot, p = 0, so q = sigma_y exactly after yield.
constexpr double kA = 90e6, kB = 292e6, kC = 0.025, kN = 0.31, kM = 1.09, kTr = 298, kTm = 1793;
constexpr double kRho = 8930, kCp = 414, kChi = 0.9, kT0 = 696, kRate = 4000;

double jc(double ep, double rate, double T) {  // VT eq. 10.2-10.3
  const double Ts = (T - kTr) / (kTm - kTr);
  return (kA + kB * std::pow(ep, kN)) * (1 + kC * std::log(rate)) * (1 - std::pow(Ts, kM));
}

// Offline: dT/d ep = chi sigma(ep, eps_dot, T)/(rho cp), RK4 in ep from (0, T0).
double offline_temperature(double ep_end) {
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
JcRun run_jc(int n, bool isothermal) {
  MapModelParameters p({{"bulk_modulus", 129e9}, {"shear_modulus", 46e9}, {"taylor_quinney_coeff", kChi},
                        {"isothermal", isothermal ? 1.0 : 0.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "johnson_cook", {{"A", kA}, {"B", kB}, {"C", kC}, {"n", kN}, {"m", kM}});
  p.add_block("equation_of_state", "mie_gruneisen", {{"C_0", 3940}, {"Gamma_0", 2.02}, {"S_alpha", 1.489}, {"rho_0", kRho}});
  p.add_block("shear_modulus_model", "constant_shear", {{"shear_modulus", 46e9}});
  p.add_block("melting_temp_model", "constant_Tm");
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", kCp}, {"density", kRho}};
  const auto m = create_constitutive_model("elastic_plastic_hp", p);
  test::PointState s(*m);
  s.temperature = kT0;
  const double t_end = 0.3 / kRate, dt = t_end / n;
  for (int k = 1; k <= n; ++k) {
    const double l = std::exp(kRate * dt * k);
    const Eigen::Matrix3d F = Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal();
    if (test::step_point(*m, kRho, s, F, dt) != -1) throw std::runtime_error("step failed");
    s.temperature += s.heating * dt;  // the driver's explicit temperature update
  }
  return {von_mises(s.stress), s.history[0][0], s.temperature};
}

TEST(ElasticPlasticHP, JohnsonCookAdiabaticMatchesOfflineIntegration) {
  // Errors of the point run against the offline curve: the heating lags one step
  // (T of step n+1 uses the rate of step n: O(dt)), and eps_p_dot differs from
  // eps_dot by the elastic rate q_dot/(3G) (~1e-3 relative, C ln -> ~3e-5 in sigma).
  double prev_err = 0;
  for (const int n : {1000, 2000}) {
    const JcRun r = run_jc(n, false);
    const double T_off = offline_temperature(r.ep);
    const double err_T = std::abs(r.T - T_off);
    std::printf("n %d: ep %.6f  T %.5f (offline %.5f)  q %.6e (JC %.6e)\n", n, r.ep, r.T, T_off, r.q,
                jc(r.ep, kRate, T_off));
    EXPECT_GT(r.T - kT0, 5.0);  // the heating is real: ~ chi int sigma d ep/(rho cp) ~ 10 K
    EXPECT_NEAR(r.q / jc(r.ep, kRate, T_off), 1.0, 5e-5);  // observed 1.4e-5, 2.0e-5
    EXPECT_LT(err_T, 0.01);  // observed 5.0e-3 K (n 1000), 2.0e-3 K (n 2000)
    if (prev_err > 0) EXPECT_LT(err_T, 0.6 * prev_err);  // first order in dt: halves
    prev_err = err_T;
  }
  // Stress at the same strain is lower with the temperature rise (README A4).
  const JcRun iso = run_jc(1000, true), adi = run_jc(1000, false);
  EXPECT_DOUBLE_EQ(iso.T, kT0);
  EXPECT_NEAR(iso.q / jc(iso.ep, kRate, kT0), 1.0, 1e-4);
  EXPECT_LT(adi.q, iso.q);
}

// MapModelParameters: fail() throws invalid_argument, missing_feature() logic_error
// (invalid_argument derives from logic_error, so it is caught first).
bool is_missing_feature(const MapModelParameters& p) {
  try {
    create_constitutive_model("elastic_plastic_hp", p);
  } catch (const std::invalid_argument&) {
    return false;
  } catch (const std::logic_error&) {
    return true;
  }
  return false;
}

TEST(ElasticPlasticHP, UnimplementedOptionsAreMissingFeatures) {
  auto base = [] {
    MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}});
    p.add_block("yield_condition", "von_mises");
    p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", 0.0}});
    p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}};
    return p;
  };
  auto g = base();  // a porous yield with a stability check: the J2-I1 tangent (test_plasticity_stability)
  g.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
  g.add_block("stability_check", "acoustic");
  EXPECT_FALSE(is_missing_feature(g));
  g.add_block("kinematic_hardening_model", "prager", {{"hardening_modulus", 1e9}});
  EXPECT_FALSE(is_missing_feature(g));  // the shifted two-invariant return (test_plasticity_porous_kinematic)
  // Porosity, damage and failure flags are implemented (models/solid/MetalFailure.h).
  for (const char* flag : {"evolve_porosity", "evolve_damage", "check_TEPLA_failure_criterion"}) {
    auto p = base();
    p.values[flag] = 1.0;
    EXPECT_FALSE(is_missing_feature(p)) << flag;
    EXPECT_TRUE(create_constitutive_model("elastic_plastic_hp", p)) << flag;
  }
  auto k = base();
  k.add_block("kinematic_hardening_model", "prager", {{"hardening_modulus", 1e9}});
  EXPECT_FALSE(is_missing_feature(k));  // implemented (test_model_elastic_plastic_hp_kinematic)
  auto nf = base();
  nf.blocks.erase("flow_model");
  EXPECT_THROW(create_constitutive_model("elastic_plastic_hp", nf), std::invalid_argument);
  EXPECT_FALSE(is_missing_feature(nf));
  auto bad = base();
  bad.add_block("flow_model", "no_such_law");
  EXPECT_THROW(create_constitutive_model("elastic_plastic_hp", bad), std::invalid_argument);
  auto me = base();  // implemented (test_model_metal_modified_eos_thermal)
  me.values["useModifiedEOS"] = 1.0;
  EXPECT_FALSE(is_missing_feature(me));
  for (const char* algo : {"radialReturn", "biswajit"}) {  // both take Tephra's returns
    auto a = base();
    a.strings["plastic_convergence_algo"] = algo;
    EXPECT_TRUE(create_constitutive_model("elastic_plastic_hp", a)) << algo;
  }
  auto ba = base();
  ba.strings["plastic_convergence_algo"] = "newton";
  EXPECT_THROW(create_constitutive_model("elastic_plastic_hp", ba), std::invalid_argument);
}

// p.strainRate (Vaango's ElasticPlasticHP label, saved by MPMICE/guni2dRT.ups):
// sqrt(2/3) |D| with D = de/dt, de = sym((U1 - U0)((U0 + U1)/2)^{-1}). Uniaxial
// stretch U = diag(l, 1, 1) from l0 to l1: de_11 = 2 (l1 - l0)/(l0 + l1), the
// other entries 0, so the rate is sqrt(2/3) 2 |l1 - l0| / ((l0 + l1) dt) in the
// elastic and in the plastic range. A rigid rotation R of both F_n and F_{n+1}
// leaves U, hence the rate, unchanged.
TEST(ElasticPlasticHP, StrainRateIsTheTotalEquivalentRate) {
  const auto m = linear_model(1e9);
  ASSERT_TRUE(m);
  int k_rate = 0;
  while (k_rate < int(m->history().size()) && m->history()[k_rate].name != "strainRate") ++k_rate;
  ASSERT_LT(k_rate, int(m->history().size()));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (const bool rotated : {false, true}) {
    test::PointState s(*m);
    const Eigen::Matrix3d Q = rotated ? R : Eigen::Matrix3d::Identity();
    s.F = Q;
    const double dt = 1e-6;
    double l0 = 1.0;
    for (int k = 1; k <= 40; ++k) {  // to 1 % stretch: 2G eps passes s0 near eps = 8e-4 (plastic after step 4)
      const double l1 = 1.0 + 2.5e-4 * k;
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(0, 0) = l1;
      ASSERT_EQ(test::step_point(*m, 8930.0, s, Eigen::Matrix3d(Q * F), dt), -1);
      const double expected = std::sqrt(2.0 / 3.0) * 2.0 * (l1 - l0) / ((l0 + l1) * dt);
      EXPECT_NEAR(s.history[k_rate][0], expected, 1e-9 * expected) << "step " << k << " rotated " << rotated;
      l0 = l1;
    }
    EXPECT_GT(s.history[0][0], 0.0);  // the path went plastic
  }
}

}  // namespace
}  // namespace tephra
