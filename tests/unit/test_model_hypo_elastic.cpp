// hypo_elastic (models/solid/HypoElastic.h): VT eq. 4.2 with the Green-Naghdi
// rate, integrated with the midpoint rule on the right stretch U.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "models/solid/HypoElastic.h"
#include "models/solid/PolarNewton.h"
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

// The point function as written before session 23 (constants and det F_new
// formed per point): the reference for the bits.
SolidPointResult hypo_point_before_session23(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new,
                                             const Eigen::Matrix3d& stress_old, double density0,
                                             const HypoElasticParams& p) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const PolarDecomposition a = polar_decomposition_newton(F_old), b = polar_decomposition_newton(F_new);
  const Eigen::Matrix3d G = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
  const Eigen::Matrix3d de = 0.5 * (G + G.transpose()) - 0.0 * I;
  const Eigen::Matrix3d tau =
      a.R.transpose() * stress_old * a.R + ((p.K - 2.0 * p.G / 3.0) * de.trace()) * I + (2.0 * p.G) * de;
  SolidPointResult r;
  r.stress = b.R * tau * b.R.transpose();
  r.stress = 0.5 * (r.stress + r.stress.transpose());
  const double J = F_new.determinant();
  const double pr = r.stress.trace() / 3.0;
  const Eigen::Matrix3d s = r.stress - pr * I;
  r.energy_density = J * (pr * pr / (2.0 * p.K) + s.squaredNorm() / (4.0 * p.G));
  r.wave_speed = std::sqrt((p.K + 4.0 * p.G / 3.0) * J / density0);
  return r;
}

// Session 23 forms the material constants once per update() and passes the
// update's det F_new to the point function: stress, wave speed and energy of
// update() and of hypo_elastic_point bit for bit those of the earlier point
// function, for random F_n, F_{n+1} = (I + dt l) F_n and stresses.
TEST(ModelHypoElastic, UpdateHasTheBitsOfThePointFunctionBeforeSession23) {
  const HypoElasticParams par{375939.8496240601, 980392.1568627450, 0.0};
  const HypoElastic model(par);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 5000;  // > 4096: the threaded point loop
  std::vector<Eigen::Matrix3d> F_old(n), F_new(n), L(n), stress_old(n), stress(n);
  std::vector<double> T(n, 300.0), c(n), W(n), pw(n), heat(n);
  for (int i = 0; i < n; ++i) {
    const double size = std::pow(10.0, -6.0 + 5.0 * (i % 6) / 5.0);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        F_old[i](a, b) = (a == b) + size * u(rng);
        L[i](a, b) = size * u(rng);
        stress_old[i](a, b) = 1e5 * u(rng);
      }
    stress_old[i] = (0.5 * (stress_old[i] + stress_old[i].transpose())).eval();
    F_new[i] = (Eigen::Matrix3d::Identity() + L[i]) * F_old[i];
  }
  SolidUpdateInput in;
  in.dt = 1e-5;
  in.density0 = kRho0;
  in.F_old = F_old;
  in.F_new = F_new;
  in.L = L;
  in.temperature = T;
  in.stress_old = stress_old;
  const SolidUpdateOutput out{stress, c, W, pw, heat, {}};
  ASSERT_EQ(model.update(in, out), -1);
  for (int i = 0; i < n; ++i) {
    const SolidPointResult ref = hypo_point_before_session23(F_old[i], F_new[i], stress_old[i], kRho0, par);
    const SolidPointResult pt = hypo_elastic_point(F_old[i], F_new[i], stress_old[i], kRho0, par);
    ASSERT_EQ(stress[i], ref.stress) << i;
    ASSERT_EQ(c[i], ref.wave_speed) << i;
    ASSERT_EQ(W[i], ref.energy_density) << i;
    ASSERT_EQ(pt.stress, ref.stress) << i;
    ASSERT_EQ(pt.wave_speed, ref.wave_speed) << i;
    ASSERT_EQ(pt.energy_density, ref.energy_density) << i;
  }
}

}  // namespace
}  // namespace tephra
