// Cam-Clay (VT ch. 20) along soil-test paths, strain controlled through the
// one-point driver (tests/support/SolidModelDriver.h) and, for one path, the
// real MPM step (tests/support/PrescribedDriver.h, deck blocks as Vaango's).
// Tension positive: p = tr(sigma)/3 < 0, q = sqrt(3/2) |dev sigma|.
//
// Closed forms (kt, lt: kappa-, lambda-tilde; eps_v = sum tr(de) = ln J up to the
// O(dt^2) midpoint error of the strain increment):
//  - isotropic compression from a normally consolidated state (p = p_c): on the
//    surface p = p_c, and the step's exact p_c update with the elastic law gives the
//    normal compression line ln(p/p_i) = -ln J / lt; unloading follows the
//    elastic line ln(p/p_1) = -(ln J - ln J_1)/kt with p_c frozen.
//  - undrained (isochoric) triaxial compression, alpha = 0: eps_v^p = -eps_v^e, so
//    p = p0 exp(-eps_v^e/kt) and p_c = p_c0 exp(-eps_v^e/(kt - lt)); the critical
//    state p = p_c/2 gives p_cs = p0 (p_c0/(2 p0))^((lt - kt)/lt), q_cs = M |p_cs|.
//  - drained triaxial compression at constant lateral stress sigma_r = p_i: the
//    stress path is q = 3 (p_i - p) (slope 3), so the critical state q = M |p| is
//    p_cs = 3 p_i/(3 - M), q_cs = 3 M |p_i|/(3 - M), whatever the elasticity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/grid/Loop.h"
#include "models/geo/CamClay.h"
#include "tests/support/PrescribedDriver.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
using test::PointState;
using test::step_point;

const double kRho0 = 1800.0, kP0 = -1.0e5, kKappa = 0.03, kLambda = 0.15, kM = 1.2;

ConstitutiveModelP camclay(double alpha, double pc0) {
  test::MapModelParameters p;
  p.add_block("equation_of_state", "borja_pressure",
              {{"p0", kP0}, {"alpha", alpha}, {"kappatilde", kKappa}, {"epse_v0", 0.0}});
  p.add_block("shear_modulus_model", "borja_shear", {{"mu0", 5.0e6}});
  p.add_block("yield_condition", "camclay", {{"M", kM}});
  p.add_block("internal_variable_model", "borja_consolidation_pressure", {{"pc0", pc0}, {"lambdatilde", kLambda}});
  return create_constitutive_model("camclay", p);
}

double mean(const M3& s) { return s.trace() / 3.0; }
double shear(const M3& s) { return std::sqrt(1.5) * (s - mean(s) * M3::Identity()).norm(); }

TEST(CamClayPaths, IsotropicCompressionFollowsTheNormalCompressionLine) {
  const ConstitutiveModelP m = camclay(5.0, kP0);  // normally consolidated: p_c0 = p0
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const int n = 200;
  const double lnJ1 = std::log(0.85);
  double worst = 0;
  for (int k = 1; k <= n; ++k) {
    const double lnJ = lnJ1 * k / n;
    ASSERT_EQ(step_point(*m, kRho0, s, M3(std::exp(lnJ / 3) * M3::Identity()), 1e-3), -1);
    const double expected = kP0 * std::exp(-lnJ / kLambda);  // NCL
    worst = std::max(worst, std::abs(mean(s.stress) / expected - 1.0));
    EXPECT_NEAR(s.history[1][0], mean(s.stress), 1e-9 * std::abs(expected));  // p = p_c on the cap
    EXPECT_LE(shear(s.stress), 1e-9 * std::abs(expected));
    EXPECT_GE(s.plastic_work, 0.0);
  }
  EXPECT_LT(worst, 1e-8);
  const double p1 = mean(s.stress), pc1 = s.history[1][0];
  std::printf("NCL: p(J=0.85) = %.6e Pa (closed form %.6e), max rel. error %.2e\n", p1,
              kP0 * std::exp(-lnJ1 / kLambda), worst);
  // Unload to J = 0.9: elastic, ln(p/p1) = -(ln J - ln J1)/kt, p_c frozen.
  for (int k = 1; k <= 50; ++k) {
    const double lnJ = lnJ1 + (std::log(0.9) - lnJ1) * k / 50;
    ASSERT_EQ(step_point(*m, kRho0, s, M3(std::exp(lnJ / 3) * M3::Identity()), 1e-3), -1);
    EXPECT_NEAR(mean(s.stress), p1 * std::exp(-(lnJ - lnJ1) / kKappa), 1e-8 * std::abs(p1));
    EXPECT_EQ(s.history[1][0], pc1);
    EXPECT_EQ(s.plastic_work, 0.0);
  }
}

// Isochoric axial compression F = diag(l^-1/2, l^-1/2, l), ln l from 0 to ln_end in n steps.
PointState undrained(const ConstitutiveModel& m, double ln_end, int n) {
  PointState s(m);
  EXPECT_EQ(step_point(m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= n; ++k) {
    const double l = std::exp(ln_end * k / n);
    EXPECT_EQ(step_point(m, kRho0, s, M3(Eigen::Vector3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal()), 1e-3),
              -1);
  }
  return s;
}

TEST(CamClayPaths, UndrainedTriaxialReachesTheClosedFormCriticalState) {
  for (double ocr : {1.0, 4.0}) {  // normally and heavily over-consolidated (contractive / dilative)
    const double pc0 = ocr * kP0;
    const ConstitutiveModelP m = camclay(0.0, pc0);
    const PointState s = undrained(*m, -0.8, 1600);
    const double p_cs = kP0 * std::pow(pc0 / (2 * kP0), (kLambda - kKappa) / kLambda);
    const double p = mean(s.stress), q = shear(s.stress);
    std::printf("undrained OCR %.0f: p = %.6e (closed form %.6e), q/(M|p|) = %.8f, p_c/(2p) = %.8f\n", ocr, p, p_cs,
                q / (kM * std::abs(p)), s.history[1][0] / (2 * p));
    EXPECT_NEAR(p / p_cs, 1.0, 1e-6);
    EXPECT_NEAR(q / (kM * std::abs(p_cs)), 1.0, 1e-6);
    EXPECT_NEAR(s.history[1][0] / (2 * p), 1.0, 1e-6);  // on the critical-state point of the ellipse
  }
}

TEST(CamClayPaths, DrainedTriaxialReachesTheCriticalStateOnTheSlopeThreePath) {
  const ConstitutiveModelP m = camclay(5.0, kP0);  // normally consolidated, coupled elasticity
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double p_i = mean(s.stress);  // = p0
  const int n = 5000;
  const double ln_end = -2.5;
  double lr = 0.0, worst_lateral = 0.0;  // lateral log stretch, solved each step for sigma_r = p_i
  for (int k = 1; k <= n; ++k) {
    const double la = ln_end * k / n;
    auto trial = [&](double x, PointState& t) {
      t = s;
      EXPECT_EQ(step_point(*m, kRho0, t, M3(Eigen::Vector3d(std::exp(x), std::exp(x), std::exp(la)).asDiagonal()), 1e-3),
                -1);
      return t.stress(0, 0) - p_i;
    };
    PointState t0 = s, t1 = s;
    double x0 = lr, x1 = lr + 1e-6;
    double r0 = trial(x0, t0), r1 = trial(x1, t1);
    for (int it = 0; it < 30 && std::abs(r1) > 1e-10 * std::abs(p_i); ++it) {  // secant
      const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
      x0 = x1, r0 = r1;
      x1 = x2;
      r1 = trial(x1, t1);
    }
    worst_lateral = std::max(worst_lateral, std::abs(r1 / p_i));
    lr = x1;
    s = t1;
    EXPECT_NEAR(s.stress(1, 1), p_i, 1e-9 * std::abs(p_i));
    // The drained stress path q = 3 (p_i - p) (slope 3 in p-q).
    EXPECT_NEAR(shear(s.stress), 3 * (p_i - mean(s.stress)), 1e-8 * std::abs(p_i));
  }
  const double p_cs = 3 * p_i / (3 - kM), q_cs = 3 * kM * std::abs(p_i) / (3 - kM);
  const double p = mean(s.stress), q = shear(s.stress);
  std::printf("drained: p = %.6e (closed form %.6e), q = %.6e (closed form %.6e), q/(M|p|) = %.8f\n", p, p_cs, q,
              q_cs, q / (kM * std::abs(p)));
  EXPECT_LT(worst_lateral, 1e-10);
  EXPECT_NEAR(p / p_cs, 1.0, 1e-5);  // asymptotic: 2e-7 short at ln(l_axial) = -2.5
  EXPECT_NEAR(q / q_cs, 1.0, 1e-5);
}

TEST(CamClayPaths, DeckThroughTheMpmStepEqualsThePointDriver) {
  set_thread_count(1);
  const std::string xml =
      "<constitutive_model type=\"camclay\">"
      "<equation_of_state type=\"borja_pressure\"><p0>-1.0e5</p0><alpha>5.0</alpha>"
      "<kappatilde>0.03</kappatilde><epse_v0>0.0</epse_v0></equation_of_state>"
      "<shear_modulus_model type=\"borja_shear\"><mu0>5.0e6</mu0></shear_modulus_model>"
      "<yield_condition type=\"camclay\"><M>1.2</M></yield_condition>"
      "<internal_variable_model type=\"borja_consolidation_pressure\"><pc0>-1.0e5</pc0>"
      "<lambdatilde>0.15</lambdatilde></internal_variable_model>"
      "</constitutive_model>";
  const double l = 0.8;
  const M3 F1 = Eigen::Vector3d(1 / std::sqrt(l), 1 / std::sqrt(l), l).asDiagonal();
  const int n = 200;
  const auto h = test::drive_prescribed(
      xml, {PrescribedRow{0.0, M3::Identity(), 0.0, Vec3::UnitZ()}, PrescribedRow{1e-3, F1, 0.0, Vec3::UnitZ()}},
      {.steps = n, .density = kRho0});
  const ConstitutiveModelP m = camclay(5.0, kP0);
  const PointState s = test::drive_path(*m, kRho0, [&](double a) { return M3(M3::Identity() + a * (F1 - M3::Identity())); }, n);
  const M3 sigma = h.stress.back();
  EXPECT_LE((h.F.back() - F1).norm(), 1e-12);
  EXPECT_LE((sigma - s.stress).norm(), 1e-9 * s.stress.norm());
  // history columns: elasticStrain (9), p_c, deltaGamma
  ASSERT_EQ(h.history.back().size(), 11u);
  EXPECT_NEAR(h.history.back()[9], s.history[1][0], 1e-9 * std::abs(s.history[1][0]));
  EXPECT_LT(h.history.back()[9], kP0);  // p_c hardened (contractive NC clay in shear)
  std::printf("deck: p = %.6e, q = %.6e, p_c = %.6e\n", mean(sigma), shear(sigma), h.history.back()[9]);
}

}  // namespace
}  // namespace tephra
