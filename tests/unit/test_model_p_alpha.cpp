// p_alpha (models/solid/PAlpha.h): hydrostatic compaction along the crush curve,
// unloading, full densification (Mie-Grueneisen), all in closed form of alpha = alpha_0 J.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "models/solid/PAlpha.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
// A porous solid: rho_0 = 1800, rho_S = 2400 -> alpha_0 = 4/3; elastic limit J_P = 1 - Pe/K0 = 0.99,
// alpha_P = alpha_0 J_P = 1.32; full density at J = 1/alpha_0 = 0.75.
const double kRho0 = 1800, kRhoS = 2400, kK0 = 2e9, kPe = 2e7, kPs = 5e8, kKs = 3e10, kC0 = 3500, kG0 = 1.2,
             kS = 1.4, kCv = 800;
const double kA0 = kRhoS / kRho0, kAP = kA0 * (1 - kPe / kK0);

test::MapModelParameters params() {
  test::MapModelParameters p({{"Ps", kPs}, {"Pe", kPe}, {"rhoS", kRhoS}, {"K0", kK0}, {"Ks", kKs}, {"T_0", 300.0},
                              {"C_0", kC0}, {"Gamma_0", kG0}, {"S_alpha", kS}});
  p.enclosing = {{"density", kRho0}, {"specific_heat", kCv}};
  return p;
}
M3 vol(double J) { return std::cbrt(J) * M3::Identity(); }
double pressure(const test::PointState& s) { return -s.stress.trace() / 3; }
double crush(double a) { return kPs - (kPs - kPe) * std::sqrt((a - 1) / (kAP - 1)); }

TEST(ModelPAlpha, HydrostaticCompactionFollowsElasticThenCrushCurveThenMieGruneisen) {
  const ConstitutiveModelP m = create_constitutive_model("p_alpha", params());
  ASSERT_TRUE(m);
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  EXPECT_EQ(pressure(s), 0.0);
  const int n = 2000;
  double work = 0;
  for (int k = 1; k <= n; ++k) {
    const double J = 1 - 0.27 * k / n, a = kA0 * J;
    ASSERT_EQ(test::step_point(*m, kRho0, s, vol(J), 1e-6), -1);
    double expect;
    if (J > 1 - kPe / kK0) {
      expect = kK0 * (1 - J);  // elastic: K0 (1 - rho0/rho)
    } else if (a > 1) {
      expect = crush(a);  // Ps - (Ps - Pe) sqrt((alpha - 1)/(alpha_P - 1))
      work += s.plastic_work;
    } else {
      // Mie-Grueneisen about rho_S at T = T_1 (E = 0): zeta = 1/alpha - 1,
      // p = Ps + rho_S C0^2 (1/zeta + 1 - Gamma0/2)/(1/zeta - (S - 1))^2.
      const double z = 1 / a - 1;
      expect = kPs + kRhoS * kC0 * kC0 * (1 / z + 1 - kG0 / 2) / std::pow(1 / z - (kS - 1), 2);
    }
    EXPECT_NEAR(pressure(s), expect, 1e-9 * kPs) << "J = " << J;
    EXPECT_NEAR(s.history[0][0], std::min(a, kA0), 1e-14);  // alpha_min
    EXPECT_EQ(s.stress, Eigen::Vector3d::Constant(s.stress(0, 0)).asDiagonal().toDenseMatrix());  // -p I exactly
  }
  // Crushing work from alpha_P to 1 (per reference volume), u = (alpha - 1)/(alpha_P - 1), dJ = (alpha_P - 1)/alpha_0 du:
  //   W = (alpha_P - 1)/alpha_0 int_0^1 (Ps - (Ps - Pe) sqrt(u)) du = (alpha_P - 1)/alpha_0 (Ps - 2/3 (Ps - Pe)).
  // The steps sum -p_{n+1} dJ (a right-endpoint rule on a decreasing p: error ~ (Ps - Pe)/N_crush).
  EXPECT_NEAR(work, (kAP - 1) / kA0 * (kPs - 2.0 / 3 * (kPs - kPe)), 2e-3 * work);
  // Continuity at the transitions: the crush curve starts at Pe and ends at Ps.
  EXPECT_DOUBLE_EQ(crush(kAP), kPe);
  EXPECT_DOUBLE_EQ(crush(1.0), kPs);
  PAlphaParams pp;
  pp.Ps = kPs, pp.Pe = kPe, pp.rhoS = kRhoS, pp.K0 = kK0, pp.rho0 = kRho0;
  EXPECT_DOUBLE_EQ(p_alpha_crush_curve(1.1, pp), crush(1.1));
}

TEST(ModelPAlpha, UnloadingFromTheCrushCurveAndReloading) {
  // Crushed to alpha_m = 1.1, unloaded: p = p_crush(alpha) + (alpha - alpha_m)/a',
  //   a' = min((alpha^2/K_s)(1 - 1/h^2), -1/K_s), h = 1 + (c_e - c_s)(alpha - 1)/(c_s (alpha_0 - 1)),
  //   c_s = sqrt(K_s/rho_S), c_e = sqrt(K_0/rho_0); back at alpha_m it is on the crush curve again.
  // Where that is negative: p = K_u (1 - rho_max/rho), rho_max = rho_S/alpha_m, K_u = 0.1 K_0.
  const ConstitutiveModelP m = create_constitutive_model("p_alpha", params());
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double am = 1.1;
  for (int k = 1; k <= 50; ++k) ASSERT_EQ(test::step_point(*m, kRho0, s, vol(1 + (am / kA0 - 1) * k / 50), 1e-6), -1);
  EXPECT_NEAR(pressure(s), crush(am), 1e-9 * kPs);
  const double cs = std::sqrt(kKs / kRhoS), ce = std::sqrt(kK0 / kRho0);
  for (double a : {1.1005, 1.101, 1.102}) {
    ASSERT_EQ(test::step_point(*m, kRho0, s, vol(a / kA0), 1e-6), -1);
    const double h = 1 + (ce - cs) * (a - 1) / (cs * (kA0 - 1));
    const double ap = std::min(a * a / kKs * (1 - 1 / (h * h)), -1 / kKs);
    double expect = crush(a) + (a - am) / ap;
    if (expect < 0) expect = 0.1 * kK0 * (1 - a / am);
    EXPECT_NEAR(pressure(s), expect, 1e-9 * kPs) << "alpha = " << a;
    EXPECT_EQ(s.history[0][0], am);  // alpha_min kept
    EXPECT_EQ(s.plastic_work, 0.0);
  }
  ASSERT_EQ(test::step_point(*m, kRho0, s, vol(am / kA0), 1e-6), -1);
  EXPECT_NEAR(pressure(s), crush(am), 1e-9 * kPs);
  // Far from alpha_m the unloading law reaches p < 0: the K_u branch (tension allowed with K_u).
  ASSERT_EQ(test::step_point(*m, kRho0, s, vol(1.2 / kA0), 1e-6), -1);
  EXPECT_NEAR(pressure(s), 0.1 * kK0 * (1 - 1.2 / am), 1e-9 * kPs);
}

TEST(ModelPAlpha, ElasticUnloadingBeforeCrushAndCrushHeating) {
  const ConstitutiveModelP m = create_constitutive_model("p_alpha", params());
  test::PointState s(*m);
  s.temperature = 300;
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, s, vol(0.995), 1e-6), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, s, vol(0.998), 1e-6), -1);
  EXPECT_NEAR(pressure(s), kK0 * 0.002, 1e-9 * kPs);  // K0 (1 - J), reversible
  EXPECT_NEAR(s.energy_density, 0.5 * kK0 * 0.002 * 0.002, 1e-9 * kK0 * 0.002 * 0.002);
  // One crushing step J 0.98 -> 0.97 (dt = 1e-6): dT/dt = -p (J_{n+1}/J_n - 1)/(rho c_v dt), rho = rho_0/J.
  ASSERT_EQ(test::step_point(*m, kRho0, s, vol(0.98), 1e-6), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, s, vol(0.97), 1e-6), -1);
  const double p = crush(kA0 * 0.97);
  EXPECT_NEAR(s.heating, -p * (0.97 / 0.98 - 1) / (kRho0 / 0.97 * kCv * 1e-6), 1e-9 * s.heating);
  EXPECT_NEAR(s.plastic_work, p * 0.01, 1e-9 * p * 0.01);
}

TEST(ModelPAlpha, Parameters) {
  test::MapModelParameters p = params();
  ASSERT_TRUE(create_constitutive_model("p_alpha", p));
  EXPECT_EQ(create_constitutive_model("p_alpha", p)->history()[0].initial[0], kA0);
  p.values["alpha0"] = 1.5;  // not rhoS/density
  EXPECT_THROW(create_constitutive_model("p_alpha", p), std::invalid_argument);
  p.values["alpha0"] = kA0;
  ASSERT_TRUE(create_constitutive_model("p_alpha", p));
  p.values["Ps"] = 1e7;  // < Pe
  EXPECT_THROW(create_constitutive_model("p_alpha", p), std::invalid_argument);
  test::MapModelParameters q = params();
  q.enclosing.erase("density");
  EXPECT_THROW(create_constitutive_model("p_alpha", q), std::invalid_argument);
  test::MapModelParameters r = params();
  r.values.erase("K0");
  EXPECT_THROW(create_constitutive_model("p_alpha", r), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
