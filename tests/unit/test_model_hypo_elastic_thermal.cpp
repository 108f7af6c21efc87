// hypo_elastic with thermal expansion <alpha> (Vaango HypoElastic: D = sym(l) - alpha T_dot I;
// models/solid/HypoElastic.h). Closed forms of one material point, alpha = 1.2e-5 /K,
// K = 8 GPa, G = 3 GPa, heated from T_0 = 300 K by 200 K in 20 steps:
//   free expansion in the model's convention: the midpoint increment of U = lambda I is
//     2 (lambda_k - lambda_{k-1})/(lambda_k + lambda_{k-1}); with lambda_k = lambda_{k-1} (2 + x)/(2 - x),
//     x = alpha (T_k - T_{k-1}), it equals the thermal increment x: sigma = 0 to round-off (1e-11);
//   free expansion F = Q(t) exp(alpha (T - T_0)) I (log strain = thermal strain, plus a rotation):
//     sigma = 0 up to the midpoint rule's x - 2 tanh(x/2) = x^3/12 per step (x = 1.2e-4: 1.44e-13),
//     |sigma| <= 3K sum |x^3/12| = 3K 40 x 1.44e-13 = 0.14 Pa (2.4e-8 of 3 K alpha 200 K);
//   constrained (F = I): sigma = -3 K alpha (T - T_0) I, exactly (sum of exact increments),
//     and 0 again after cooling back to T_0;
//   a superposed rotation F = Q(t) exp(alpha (T - T_0)) I stays stress-free;
//   <DoThermalExpansion> false in <MPM>: alpha = 0, no history, no thermal stress.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/deck/DeckLoader.h"
#include "models/solid/ConstitutiveModel.h"
#include "mpm/DeckModelParameters.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
constexpr double kK = 8e9, kG = 3e9, kAlpha = 1.2e-5, kT0 = 300.0, kRho0 = 7800.0;

ConstitutiveModelP thermal_model() {
  test::MapModelParameters p({{"G", kG}, {"K", kK}, {"alpha", kAlpha}});
  return create_constitutive_model("hypo_elastic", p);
}

TEST(HypoElasticThermal, FreeExpansionIsStressFreeConstrainedGivesThreeKAlphaDeltaT) {
  const ConstitutiveModelP m = thermal_model();
  ASSERT_EQ(m->history().size(), 1u);
  EXPECT_EQ(m->history()[0].name, "lastTemperature");
  const double scale = 3 * kK * kAlpha * 200.0;  // the constrained pressure at Delta T = 200 K
  test::PointState free(*m), fixed(*m), spun(*m);
  free.temperature = fixed.temperature = spun.temperature = kT0;
  ASSERT_EQ(test::step_point(*m, kRho0, free, M3::Identity(), 0.0), -1);  // initialization: T_0
  ASSERT_EQ(test::step_point(*m, kRho0, fixed, M3::Identity(), 0.0), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, spun, M3::Identity(), 0.0), -1);
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  double max_free = 0, max_spun = 0, max_fixed = 0, lambda = 1.0, T_prev = kT0;
  for (int k = 1; k <= 40; ++k) {
    const double T = k <= 20 ? kT0 + 10.0 * k : kT0 + 10.0 * (40 - k);  // heat, then cool back
    free.temperature = fixed.temperature = spun.temperature = T;
    const double x = kAlpha * (T - T_prev);
    T_prev = T;
    lambda *= (2 + x) / (2 - x);
    const double l = std::exp(kAlpha * (T - kT0));
    ASSERT_EQ(test::step_point(*m, kRho0, free, M3(lambda * M3::Identity()), 1e-6), -1);
    ASSERT_EQ(test::step_point(*m, kRho0, fixed, M3::Identity(), 1e-6), -1);
    const M3 Q = Eigen::AngleAxisd(0.05 * k, axis).toRotationMatrix();
    ASSERT_EQ(test::step_point(*m, kRho0, spun, M3(Q * l), 1e-6), -1);
    max_free = std::max(max_free, free.stress.norm());
    max_spun = std::max(max_spun, spun.stress.norm());
    const M3 exact = -3 * kK * kAlpha * (T - kT0) * M3::Identity();
    max_fixed = std::max(max_fixed, (fixed.stress - exact).norm());
    EXPECT_EQ(fixed.history[0][0], T);
  }
  std::printf("free |sigma| max %.3e Pa, rotated %.3e Pa, constrained |sigma + 3 K alpha dT I| max %.3e Pa "
              "(3 K alpha 200 K = %.4e Pa)\n", max_free, max_spun, max_fixed, scale);
  EXPECT_LT(max_free, 1e-11 * scale);  // round-off of 40 increments of ~3e10 x 1e-4
  EXPECT_LT(max_spun, 3 * kK * 40 * std::pow(kAlpha * 10, 3) / 12 * 1.01 + 1e-12 * scale);
  EXPECT_LT(max_fixed, 1e-12 * scale);
  EXPECT_LT(fixed.stress.norm(), 1e-12 * scale);  // cooled back to T_0
}

TEST(HypoElasticThermal, DoThermalExpansionFalseTurnsItOff) {
  auto deck = load_deck_from_string(
      "<Uintah_specification><MPM><DoThermalExpansion>false</DoThermalExpansion></MPM>\n"
      "<constitutive_model type=\"hypo_elastic\"><G>3e9</G><K>8e9</K><alpha>1.2e-5</alpha></constitutive_model>"
      "</Uintah_specification>",
      "thermal.ups", ".");
  DeckModelParameters params(*deck->root.child("constitutive_model"));
  const ConstitutiveModelP m = create_constitutive_model("hypo_elastic", params);
  params.check_all_used("hypo_elastic");
  EXPECT_TRUE(m->history().empty());
  test::PointState s(*m);
  s.temperature = kT0;
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  s.temperature = kT0 + 100;
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 1e-6), -1);
  EXPECT_EQ(s.stress.norm(), 0.0);
}

}  // namespace
}  // namespace tephra
