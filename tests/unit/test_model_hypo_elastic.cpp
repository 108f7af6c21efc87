// hypo_elastic (models/solid/HypoElastic.h): VT eq. 4.2 with the Green-Naghdi
// rate, integrated with the midpoint rule on the right stretch U.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "models/solid/HypoElastic.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const HypoElasticParams kP{3.0e9, 8.0e9};  // G, K
const double kRho0 = 7800.0;

M3 diag(double a, double b, double c) { return Eigen::Vector3d(a, b, c).asDiagonal(); }

TEST(ModelHypoElastic, OneStepUniaxialStrainClosedForm) {
  // F: I -> diag(l, 1, 1) in one step. U = F, R = I, the increment is
  // de = diag(2 (l - 1)/(l + 1), 0, 0) (midpoint rule), so
  //   sigma_11 = (K + 4G/3) de_11,  sigma_22 = sigma_33 = (K - 2G/3) de_11.
  for (double l : {0.8, 0.99, 1.01, 1.3}) {
    const SolidPointResult r = hypo_elastic_point(M3::Identity(), diag(l, 1, 1), M3::Zero(), kRho0, kP);
    const double de = 2 * (l - 1) / (l + 1);
    const double scale = 1e-15 * (kP.K + kP.G);
    EXPECT_NEAR(r.stress(0, 0), (kP.K + 4 * kP.G / 3) * de, scale);
    EXPECT_NEAR(r.stress(1, 1), (kP.K - 2 * kP.G / 3) * de, scale);
    EXPECT_NEAR(r.stress(2, 2), (kP.K - 2 * kP.G / 3) * de, scale);
    EXPECT_NEAR(r.stress(0, 1), 0.0, scale);
    // c = sqrt((K + 4G/3) J / rho0) (Vaango HypoElastic, rho = rho0/J).
    EXPECT_NEAR(r.wave_speed, std::sqrt((kP.K + 4 * kP.G / 3) * l / kRho0), 1e-12);
    // W = J [p^2/(2K) + s:s/(4G)].
    const double p = r.stress.trace() / 3;
    const M3 s = r.stress - p * M3::Identity();
    EXPECT_NEAR(r.energy_density, l * (p * p / (2 * kP.K) + s.squaredNorm() / (4 * kP.G)), 1e-15 * r.energy_density);
  }
}

TEST(ModelHypoElastic, UniaxialStrainConvergesToHenckyStrainAtSecondOrder) {
  // Stretching without rotation, d = diag(l_dot/l, 0, 0): the exact solution of
  // eq. 4.2 is sigma_11 = (K + 4G/3) ln l, sigma_22 = (K - 2G/3) ln l.
  // The midpoint increment 2(l1-l0)/(l1+l0) = ln(l1/l0) + O(dl^3): error O(1/N^2).
  HypoElastic m(kP);
  const double l = 1.5;
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const int n = 10 << k;
    const test::PointState s = test::drive_path(m, kRho0, [&](double a) { return diag(1 + a * (l - 1), 1, 1); }, n);
    err[k] = std::abs(s.stress(0, 0) - (kP.K + 4 * kP.G / 3) * std::log(l));
    EXPECT_NEAR(s.stress(1, 1) / s.stress(0, 0), (kP.K - 2 * kP.G / 3) / (kP.K + 4 * kP.G / 3), 1e-12);
  }
  EXPECT_NEAR(std::log2(err[0] / err[1]), 2.0, 0.05);
  EXPECT_NEAR(std::log2(err[1] / err[2]), 2.0, 0.05);
}

TEST(ModelHypoElastic, RigidSpinRotatesThePrestress) {
  // Inventory [ORACLE]: a rigid rotation with zero stretch leaves the principal
  // stresses unchanged. Stretch to F_s, then spin F(t) = Q(t) F_s through 3 rad
  // in 50 steps: U is constant, so the increment vanishes and
  // sigma = Q sigma_s Q^T to round-off (no drift, unlike a first-order Jaumann update).
  HypoElastic m(kP);
  test::PointState s(m);
  const M3 Fs = diag(1.05, 0.98, 1.0) + 0.02 * (M3() << 0, 1, 0, 1, 0, 0, 0, 0, 0).finished();
  ASSERT_EQ(test::step_point(m, kRho0, s, M3::Identity(), 0.0), -1);
  ASSERT_EQ(test::step_point(m, kRho0, s, Fs, 1e-3), -1);
  const M3 sigma_s = s.stress;
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  for (int k = 1; k <= 50; ++k)
    ASSERT_EQ(test::step_point(m, kRho0, s, Eigen::AngleAxisd(3.0 * k / 50, axis).toRotationMatrix() * Fs, 1e-3), -1);
  const M3 Q = Eigen::AngleAxisd(3.0, axis).toRotationMatrix();
  EXPECT_LE((s.stress - Q * sigma_s * Q.transpose()).norm(), 1e-12 * sigma_s.norm());
  const Eigen::Vector3d a = Eigen::SelfAdjointEigenSolver<M3>(s.stress).eigenvalues();
  const Eigen::Vector3d b = Eigen::SelfAdjointEigenSolver<M3>(sigma_s).eigenvalues();
  EXPECT_LE((a - b).norm(), 1e-12 * b.norm());
}

TEST(ModelHypoElastic, SimpleShearMatchesDienesGreenNaghdiSolution) {
  // Simple shear F = I + gamma e1 (x) e2. For the Green-Naghdi rate, Dienes
  // (Acta Mech. 32, 1979, eq. 5.x) gives with tan(beta) = gamma/2:
  //   sigma_11 = -sigma_22 = 4G [cos 2b ln cos b + b sin 2b - sin^2 b]
  //   sigma_12 = 2G cos 2b [2b - 2 tan 2b ln cos b - tan b]
  // (no oscillation, unlike the Jaumann rate). Midpoint rule: error O(1/N^2).
  HypoElastic m(kP);
  const double gamma = 2.0, b = std::atan(gamma / 2), G = kP.G;
  const double s11 = 4 * G * (std::cos(2 * b) * std::log(std::cos(b)) + b * std::sin(2 * b) - std::sin(b) * std::sin(b));
  const double s12 = 2 * G * std::cos(2 * b) * (2 * b - 2 * std::tan(2 * b) * std::log(std::cos(b)) - std::tan(b));
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const int n = 20 << k;
    const test::PointState s = test::drive_path(m, kRho0, [&](double a) {
      M3 F = M3::Identity();
      F(0, 1) = a * gamma;
      return F;
    }, n);
    err[k] = std::hypot(s.stress(0, 0) - s11, s.stress(0, 1) - s12) / G;
    EXPECT_NEAR(s.stress(1, 1), -s.stress(0, 0), 1e-9 * G);  // isochoric: tr sigma = 0
    EXPECT_NEAR(s.stress(2, 2), 0.0, 1e-9 * G);
  }
  EXPECT_LT(err[2], 1e-4);
  EXPECT_NEAR(std::log2(err[0] / err[1]), 2.0, 0.1);
  EXPECT_NEAR(std::log2(err[1] / err[2]), 2.0, 0.1);
}

TEST(ModelHypoElastic, ParametersAndHooks) {
  test::MapModelParameters p({{"G", 3e9}, {"K", 8e9}});
  ConstitutiveModelP m = create_constitutive_model("hypo_elastic", p);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->bulk_modulus(), 8e9);
  EXPECT_EQ(m->shear_modulus(), 3e9);
  EXPECT_FALSE(m->hyperelastic());
  // Vaango computePressEOSCM: p = K (1 - rho0/rho); computeRhoMicroCM: rho = rho0/(1 - p/K).
  EXPECT_NEAR(m->pressure_at_density(2 * kRho0, kRho0, 300)->pressure, 4e9, 1e-6);
  EXPECT_NEAR(*m->density_at_pressure(4e9, kRho0, 300), 2 * kRho0, 1e-9);
  EXPECT_TRUE(std::isinf(*m->density_at_pressure(8e9, kRho0, 300)));
  p.values["alpha"] = 1e-5;  // thermal strain: test_model_hypo_elastic_thermal
  EXPECT_EQ(create_constitutive_model("hypo_elastic", p)->history().size(), 1u);
  EXPECT_TRUE(m->history().empty());
  p.values.erase("alpha");
  p.values["G"] = 0;
  EXPECT_THROW(create_constitutive_model("hypo_elastic", p), std::invalid_argument);
  p.values.erase("G");
  EXPECT_THROW(create_constitutive_model("hypo_elastic", p), std::invalid_argument);  // required
}

}  // namespace
}  // namespace tephra
