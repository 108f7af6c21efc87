// hypo_elastic_mms (HypoElastic::create_mms in models/solid/HypoElastic.h): hypo_elastic's law (VT eq. 4.2,
// Green-Naghdi rate) under Vaango's MMS type name, created through the registry.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kG = 3.0e9, kK = 8.0e9, kRho0 = 7800.0;

ConstitutiveModelP make() {
  test::MapModelParameters p({{"G", kG}, {"K", kK}});
  ConstitutiveModelP m = create_constitutive_model("hypo_elastic_mms", p);
  if (!m) throw std::runtime_error("hypo_elastic_mms not registered");
  return m;
}

TEST(ModelHypoElasticMms, UniaxialStrainReachesHenckyAtOrderTwo) {
  // F = diag(l(a), 1, 1), l = 1 + a (lam - 1), no rotation: d_hat = d = diag(l'/l, 0, 0),
  // so the exact integral of eq. 4.2 is the Hencky form
  //   sigma_11 = (K + 4G/3) ln lam,  sigma_22 = sigma_33 = (K - 2G/3) ln lam.
  // The midpoint rule on U errs by O(1/N^2).
  const ConstitutiveModelP m = make();
  const double lam = 1.3, e = std::log(lam);
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const int n = 10 << k;
    const test::PointState s = test::drive_path(*m, kRho0, [&](double a) {
      M3 F = M3::Identity();
      F(0, 0) = 1 + a * (lam - 1);
      return F;
    }, n);
    err[k] = std::hypot(s.stress(0, 0) - (kK + 4 * kG / 3) * e, s.stress(1, 1) - (kK - 2 * kG / 3) * e) / kK;
    EXPECT_NEAR(s.stress(1, 1), s.stress(2, 2), 1e-12 * kK);
    EXPECT_NEAR(s.stress(0, 1), 0.0, 1e-12 * kK);
    // c = sqrt((K + 4G/3) J / rho0).
    EXPECT_NEAR(s.wave_speed, std::sqrt((kK + 4 * kG / 3) * lam / kRho0), 1e-9);
  }
  EXPECT_LT(err[2], 1e-4);
  EXPECT_NEAR(std::log2(err[0] / err[1]), 2.0, 0.1);
  EXPECT_NEAR(std::log2(err[1] / err[2]), 2.0, 0.1);
}

TEST(ModelHypoElasticMms, SimpleShearMatchesDienesGreenNaghdiSolution) {
  // F = I + gamma e1 (x) e2; Dienes (Acta Mech. 32, 1979), tan(b) = gamma/2:
  //   sigma_11 = -sigma_22 = 4G [cos 2b ln cos b + b sin 2b - sin^2 b]
  //   sigma_12 = 2G cos 2b [2b - 2 tan 2b ln cos b - tan b].
  const ConstitutiveModelP m = make();
  const double gamma = 1.0, b = std::atan(gamma / 2);
  const double s11 = 4 * kG * (std::cos(2 * b) * std::log(std::cos(b)) + b * std::sin(2 * b) - std::sin(b) * std::sin(b));
  const double s12 = 2 * kG * std::cos(2 * b) * (2 * b - 2 * std::tan(2 * b) * std::log(std::cos(b)) - std::tan(b));
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const int n = 20 << k;
    const test::PointState s = test::drive_path(*m, kRho0, [&](double a) {
      M3 F = M3::Identity();
      F(0, 1) = a * gamma;
      return F;
    }, n);
    err[k] = std::hypot(s.stress(0, 0) - s11, s.stress(0, 1) - s12) / kG;
    EXPECT_NEAR(s.stress(1, 1), -s.stress(0, 0), 1e-9 * kG);  // isochoric: tr sigma = 0
    EXPECT_NEAR(s.stress(2, 2), 0.0, 1e-9 * kG);
  }
  EXPECT_LT(err[2], 1e-4);
  EXPECT_NEAR(std::log2(err[0] / err[1]), 2.0, 0.15);
  EXPECT_NEAR(std::log2(err[1] / err[2]), 2.0, 0.15);
}

TEST(ModelHypoElasticMms, ParametersAndHooks) {
  const ConstitutiveModelP m = make();
  EXPECT_EQ(m->type(), "hypo_elastic_mms");
  EXPECT_EQ(m->bulk_modulus(), kK);
  EXPECT_EQ(m->shear_modulus(), kG);
  // p = K (1 - rho0/rho) as hypo_elastic (Vaango computePressEOSCM).
  EXPECT_NEAR(m->pressure_at_density(2 * kRho0, kRho0, 300)->pressure, kK / 2, 1e-6);
  EXPECT_NEAR(*m->density_at_pressure(kK / 2, kRho0, 300), 2 * kRho0, 1e-9);
  test::MapModelParameters p({{"G", kG}, {"K", kK}, {"alpha", 1e-5}});
  EXPECT_THROW(create_constitutive_model("hypo_elastic_mms", p), std::logic_error);  // MissingFeature
  p.values.erase("alpha");
  p.values["K"] = -1;
  EXPECT_THROW(create_constitutive_model("hypo_elastic_mms", p), std::exception);  // DeckError
}

}  // namespace
}  // namespace tephra
