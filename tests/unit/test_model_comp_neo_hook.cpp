// comp_neo_hook (models/solid/CompNeoHookean.h):
//   sigma = K/2 (J - 1/J) I + G J^{-5/3} dev(F F^T),
//   W = K/2 [(J^2 - 1)/2 - ln J] + G/2 (J^{-2/3} tr(F F^T) - 3).
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <map>
#include <random>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "core/base/Types.h"
#include "models/ModelParameters.h"
#include "models/solid/CompNeoHookean.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

const CompNeoHookeanParams kParams{833.3, 384.6};  // the disks deck (E = 1000, nu = 0.3)
const double kRho0 = 1000.0;

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

Mat3 random_F(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Mat3 F = Mat3::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F(i, j) += u(rng);
  return F;
}

TEST(ModelCompNeoHook, ZeroStressAndEnergyAtIdentity) {
  const SolidPointResult r = comp_neo_hookean_point(Mat3::Identity(), kRho0, kParams);
  EXPECT_EQ(r.stress.norm(), 0.0);
  EXPECT_EQ(r.energy_density, 0.0);
  // c = sqrt((K + 4G/3)/rho0) at J = 1.
  EXPECT_NEAR(r.wave_speed, std::sqrt((833.3 + 4.0 * 384.6 / 3.0) / kRho0), 1e-14);
}

TEST(ModelCompNeoHook, UniaxialStretchClosedForm) {
  // F = diag(l, 1, 1): J = l, dev(B) = (l^2 - 1)/3 diag(2, -1, -1), so
  //   sigma_xx = K/2 (l - 1/l) + 2G/3 l^{-5/3} (l^2 - 1)
  //   sigma_yy = sigma_zz = K/2 (l - 1/l) - G/3 l^{-5/3} (l^2 - 1)
  //   W = K/2 [(l^2 - 1)/2 - ln l] + G/2 [l^{-2/3}(l^2 + 2) - 3]
  //   c = sqrt((K_t + 4G/3) l / rho0),  K_t = K/2 (1 + 1/l^2)  (Vaango UCNH + HyperElasticEOS)
  const double K = kParams.bulk_modulus, G = kParams.shear_modulus;
  for (double l : {0.5, 0.9, 1.1, 2.0}) {
    Mat3 F = Mat3::Identity();
    F(0, 0) = l;
    const SolidPointResult r = comp_neo_hookean_point(F, kRho0, kParams);
    const double p = 0.5 * K * (l - 1 / l), d = std::pow(l, -5.0 / 3.0) * (l * l - 1);
    const double scale = K + G;
    EXPECT_NEAR(r.stress(0, 0), p + 2 * G / 3 * d, 1e-14 * scale);
    EXPECT_NEAR(r.stress(1, 1), p - G / 3 * d, 1e-14 * scale);
    EXPECT_NEAR(r.stress(2, 2), p - G / 3 * d, 1e-14 * scale);
    EXPECT_NEAR(r.stress(0, 1), 0.0, 1e-14 * scale);
    EXPECT_NEAR(r.energy_density,
                0.5 * K * (0.5 * (l * l - 1) - std::log(l)) + 0.5 * G * (std::pow(l, -2.0 / 3.0) * (l * l + 2) - 3),
                1e-14 * scale);
    EXPECT_NEAR(r.wave_speed, std::sqrt((0.5 * K * (1 + 1 / (l * l)) + 4 * G / 3) * l / kRho0), 1e-14);
  }
}

TEST(ModelCompNeoHook, StressIsTheDerivativeOfTheEnergy) {
  // Hyperelasticity: P = dW/dF and sigma = P F^T / J. Central differences of W
  // have error O(e^2 W''') ~ 1e-12 relative for e = 1e-6.
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat3 F = random_F(rng);
    if (F.determinant() < 0.3) continue;
    Mat3 P;
    const double e = 1e-6;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Mat3 Fp = F, Fm = F;
        Fp(i, j) += e;
        Fm(i, j) -= e;
        P(i, j) = (comp_neo_hookean_point(Fp, kRho0, kParams).energy_density -
                   comp_neo_hookean_point(Fm, kRho0, kParams).energy_density) / (2 * e);
      }
    const Mat3 sigma_fd = P * F.transpose() / F.determinant();
    const Mat3 sigma = comp_neo_hookean_point(F, kRho0, kParams).stress;
    EXPECT_NEAR((sigma - sigma_fd).norm(), 0.0, 1e-6 * (1 + sigma.norm()));
  }
}

TEST(ModelCompNeoHook, Objectivity) {
  // sigma(R F) = R sigma(F) R^T and W(R F) = W(F) for any rotation R.
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Mat3 F = random_F(rng);
    if (F.determinant() < 0.2) continue;
    const Mat3 R = random_rotation(rng);
    const SolidPointResult a = comp_neo_hookean_point(R * F, kRho0, kParams);
    const SolidPointResult b = comp_neo_hookean_point(F, kRho0, kParams);
    EXPECT_NEAR((a.stress - R * b.stress * R.transpose()).norm(), 0.0, 1e-12 * (1 + b.stress.norm()));
    EXPECT_NEAR(a.energy_density, b.energy_density, 1e-12 * (1 + b.energy_density));
    EXPECT_NEAR((a.stress - a.stress.transpose()).norm(), 0.0, 1e-12 * (1 + a.stress.norm()));
  }
}

TEST(ModelCompNeoHook, SmallStrainLimitIsLinearElasticity) {
  // F = I + eps H: sigma = K tr(e) I + 2G dev(e) + O(eps^2), e = sym(eps H).
  // The relative error must fall like eps (checked at two amplitudes).
  std::mt19937 rng(3);
  const Mat3 H = random_F(rng) - Mat3::Identity();
  const double K = kParams.bulk_modulus, G = kParams.shear_modulus;
  double err[2];
  const double eps[2] = {1e-4, 1e-5};
  for (int k = 0; k < 2; ++k) {
    const Mat3 e = 0.5 * eps[k] * (H + H.transpose());
    const Mat3 lin = K * e.trace() * Mat3::Identity() + 2 * G * (e - e.trace() / 3 * Mat3::Identity());
    const Mat3 sigma = comp_neo_hookean_point(Mat3::Identity() + eps[k] * H, kRho0, kParams).stress;
    err[k] = (sigma - lin).norm() / lin.norm();
  }
  EXPECT_LT(err[0], 10 * eps[0]);
  EXPECT_LT(err[1], 10 * eps[1]);
  EXPECT_NEAR(err[0] / err[1], 10.0, 1.0);  // first order in eps
}

// ---- registry
TEST(ModelCompNeoHook, RegistryCreatesAndValidates) {
  test::MapModelParameters p;
  p.values = {{"bulk_modulus", 833.3}, {"shear_modulus", 384.6}};
  ConstitutiveModelP m = create_constitutive_model("comp_neo_hook", p);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->type(), "comp_neo_hook");
  EXPECT_EQ(m->bulk_modulus(), 833.3);
  EXPECT_EQ(m->shear_modulus(), 384.6);
  EXPECT_EQ(create_constitutive_model("no_such_model", p), nullptr);
  // Sorted, and holding (at least) these types; each new model adds itself.
  const std::vector<std::string> types = constitutive_model_types();
  const std::vector<std::string> expected{"UCNH", "cnh_mms", "comp_mooney_rivlin", "comp_neo_hook", "comp_neo_hook_plastic",
                                          "elastic_plastic", "elastic_plastic_hp", "hypo_elastic", "ideal_gas",
                                          "jwlpp_mpm", "murnaghanMPM", "mw_visco_elastic", "rigid", "trans_iso_hyper",
                                          "visco_scram", "water"};
  EXPECT_TRUE(std::is_sorted(types.begin(), types.end()));
  EXPECT_TRUE(std::includes(types.begin(), types.end(), expected.begin(), expected.end()));
  p.values["shear_modulus"] = -1;
  EXPECT_THROW(create_constitutive_model("comp_neo_hook", p), std::invalid_argument);
  p.values["shear_modulus"] = 384.6;
  p.values["useModifiedEOS"] = 1;
  EXPECT_THROW(create_constitutive_model("comp_neo_hook", p), std::logic_error);
}

TEST(ModelCompNeoHook, SpanUpdateReportsInvertedPoint) {
  CompNeoHookean m(kParams);
  std::vector<Mat3> F = {Mat3::Identity(), Mat3::Identity()};
  F[1](2, 2) = -0.5;  // J < 0
  const std::vector<Mat3> F0(2, Mat3::Identity()), L(2, Mat3::Zero());
  std::vector<Mat3> s(2, Mat3::Zero());
  std::vector<double> c(2), w(2), wp(2), h(2), T(2, 300.0);
  SolidUpdateInput in;
  in.density0 = kRho0;
  in.F_old = F0;
  in.F_new = F;
  in.L = L;
  in.temperature = T;
  in.stress_old = s;
  const SolidUpdateOutput out{s, c, w, wp, h, {}};
  EXPECT_EQ(m.update(in, out), 1);
  F[1](2, 2) = 1.2;
  EXPECT_EQ(m.update(in, out), -1);
  EXPECT_EQ(s[1], comp_neo_hookean_point(F[1], kRho0, kParams).stress);
}

TEST(ModelCompNeoHook, PressureHooksAreInverseAndDifferentiable) {
  // p(rho) = K/2 (rho/rho0 - rho0/rho) = -(trace sigma)/3 at F = (rho0/rho)^{1/3} I,
  // dp/drho by central differences, rho(p(rho)) = rho.
  CompNeoHookean m(kParams);
  for (double rho : {800.0, 1000.0, 1300.0}) {
    const SolidEosPoint e = *m.pressure_at_density(rho, kRho0, 300.0);
    const Mat3 F = std::cbrt(kRho0 / rho) * Mat3::Identity();
    EXPECT_NEAR(e.pressure, -comp_neo_hookean_point(F, kRho0, kParams).stress.trace() / 3, 1e-12 * 833.3);
    const double h = 1e-3;
    const double fd = (m.pressure_at_density(rho + h, kRho0, 300.0)->pressure -
                       m.pressure_at_density(rho - h, kRho0, 300.0)->pressure) / (2 * h);
    EXPECT_NEAR(e.dp_drho, fd, 1e-8 * e.dp_drho);
    EXPECT_NEAR(*m.density_at_pressure(e.pressure, kRho0, 300.0), rho, 1e-12 * rho);
  }
}

}  // namespace
}  // namespace tephra
