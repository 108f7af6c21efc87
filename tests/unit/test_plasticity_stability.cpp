// Stability checks (VT ch. 16; models/plasticity/StabilityCheck.h): the corrected
// Becker quadratic on an elastic tangent, the acoustic-tensor determinant of the
// J2 tangent against a hand computation, Drucker's (C : D) : D against its closed
// form, and the checks driving the failure flag
// of elastic_plastic and elastic_plastic_hp (softening flagged, hardening not).
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "models/plasticity/StabilityCheck.h"
#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kLambda = 50e9, kMu = 30e9;  // an isotropic tangent [Pa]
const double kK = kLambda + 2.0 * kMu / 3.0;

// Inventory oracle 14: for isotropic elasticity the corrected quadratic is
// mu (lambda + 2 mu) (beta + 1)^2: a1 = a3 = mu(lambda+2mu), a2 = 2 mu(lambda+2mu); beta = -1, stable.
TEST(StabilityCheck, BeckerQuadraticOfIsotropicElasticityIsAPerfectSquare) {
  const BeckerQuadratic q = becker_quadratic(isotropic_tangent(kLambda, kMu));
  const double m = kMu * (kLambda + 2 * kMu);
  EXPECT_NEAR(q.a1 / m, 1.0, 1e-14);
  EXPECT_NEAR(q.a2 / m, 2.0, 1e-14);
  EXPECT_NEAR(q.a3 / m, 1.0, 1e-14);
  EXPECT_FALSE(becker_unstable(q));
  // Root placement: (beta-1)(beta-4) has two positive roots (four real n3/n1): unstable;
  // (beta+1)(beta-4) one negative root: two real n3/n1, stable by (16.41).
  EXPECT_TRUE(becker_unstable({1.0, -5.0, 4.0}));
  EXPECT_FALSE(becker_unstable({1.0, -3.0, -4.0}));
  EXPECT_FALSE(becker_unstable({1.0, 1.0, 1.0}));  // complex roots
}

// Elastic acoustic tensor A(n) = mu I + (lambda + mu) n n: det = mu^2 (lambda + 2 mu) for every unit n.
TEST(StabilityCheck, AcousticDeterminantOfIsotropicElasticity) {
  const Tangent4 C = isotropic_tangent(kLambda, kMu);
  const double expect = kMu * kMu * (kLambda + 2 * kMu);
  const Eigen::Vector3d n = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  EXPECT_NEAR(acoustic_tensor(C, n).determinant() / expect, 1.0, 1e-13);
  EXPECT_NEAR(min_acoustic_determinant(C) / expect, 1.0, 1e-12);
  // Rotation leaves an isotropic tensor unchanged.
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Tangent4 R = C.rotated(Q);
  for (int k = 0; k < 81; ++k) EXPECT_NEAR(R.c[k], C.c[k], 1e-4);  // |C| ~ 1e11: 1e-15 relative
}

// J2 tangent C^ep = C^e - c Nh Nh, c = 6 mu^2/(3 mu + H), with Nh = diag(1, 0, -1)/sqrt(2)
// (deviator of plane-strain shear in the sigma1-sigma3 plane). Hand computation for
// n = (1, 0, 1)/sqrt(2): a = Nh n = (1, 0, -1)/2, |a|^2 = 1/2, n.a = 0, so by the
// matrix determinant lemma with A^e^{-1} = (I - (lambda+mu)/(lambda+2mu) n n)/mu,
//   det A = mu^2 (lambda + 2 mu) (1 - c |a|^2/mu) = mu^2 (lambda + 2 mu) H/(3 mu + H).
TEST(StabilityCheck, AcousticDeterminantOfTheJ2TangentAgainstTheHandComputation) {
  Eigen::Matrix3d Nh = Eigen::Matrix3d::Zero();
  Nh(0, 0) = 1.0 / std::sqrt(2.0);
  Nh(2, 2) = -1.0 / std::sqrt(2.0);
  const Eigen::Vector3d n = Eigen::Vector3d(1, 0, 1).normalized();
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
  stress(0, 0) = 1e8;
  stress(2, 2) = -1e8;
  for (const double H : {-0.2 * kMu, -0.01 * kMu, 0.01 * kMu, 0.5 * kMu}) {
    const Tangent4 C = j2_elastoplastic_tangent(kK, kMu, H, Nh);
    const double hand = kMu * kMu * (kLambda + 2 * kMu) * H / (3 * kMu + H);
    EXPECT_NEAR(acoustic_tensor(C, n).determinant() / hand, 1.0, 1e-10) << "H " << H;
    const double dmin = min_acoustic_determinant(C);
    EXPECT_LE(dmin, hand * (1 + 1e-12) + 1e-6 * std::abs(hand)) << "H " << H;  // the search finds <= the sample
    StabilityInput in;
    in.stress = stress;
    in.tangent = C;
    in.deformation_rate = Nh;  // D along the flow direction
    // (C^ep : D) : D = 2 mu H/(3 mu + H) (Nh:Nh = 1): the sign of H.
    EXPECT_NEAR(drucker_product(C, Nh), 2 * kMu * H / (3 * kMu + H), 1e-6 * kMu);
    const bool soft = H < 0;
    for (const char* key : {"drucker", "acoustic", "becker", "drucker_becker"}) {
      const auto chk = create_stability_check(key, MapModelParameters{});
      ASSERT_TRUE(chk);
      EXPECT_EQ(chk->unstable(in), soft) << key << " H " << H;
    }
    EXPECT_FALSE(create_stability_check("none", MapModelParameters{})->unstable(in));
  }
  EXPECT_EQ(create_stability_check("no_such_check", MapModelParameters{}), nullptr);
}

// Drucker's check in Vaango's form, (C^ep : D) : D <= 0 (StabilityCheck.h, DruckerCheck.cc),
// on the J2 tangent C^ep = K I⊗I + 2mu I_dev - (2mu)^2/(2mu + 2H/3) N⊗N (|N| = 1, tr N = 0;
// (2mu)^2/(2mu + 2H/3) = 6 mu^2/(3 mu + H)). With D = a N + b M + (e/3) I (|M| = 1, M:N = 0,
// tr M = 0):  C^ep:D = K e I + 2mu (a N + b M) - 6 mu^2 a/(3 mu + H) N, so
//   (C^ep : D) : D = K e^2 + 2 mu b^2 + 2 mu a^2 H/(3 mu + H).
// Hardening (H > 0) is positive for every D != 0; softening (-3 mu < H < 0) is <= 0 exactly
// when K e^2 + 2 mu b^2 <= 2 mu a^2 |H|/(3 mu + H): for e = 0, (b/a)^2 <= -H/(3 mu + H).
Eigen::Matrix3d flow_direction() {  // N = dev(diag(2, -1, -1))/|.| = diag(2, -1, -1)/sqrt(6)
  return Eigen::Vector3d(2.0, -1.0, -1.0).asDiagonal() * (1.0 / std::sqrt(6.0));
}
Eigen::Matrix3d orthogonal_direction() {  // M = (e1 e2 + e2 e1)/sqrt(2): M:N = 0, tr M = 0
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  M(0, 1) = M(1, 0) = 1.0 / std::sqrt(2.0);
  return M;
}

StabilityInput drucker_input(double H, const Eigen::Matrix3d& D) {
  StabilityInput in;
  in.stress = 3e8 * flow_direction();  // deviatoric stress along N
  in.deformation_rate = D;
  in.tangent = j2_elastoplastic_tangent(kK, kMu, H, flow_direction());
  return in;
}

TEST(StabilityCheck, DruckerProductOfTheJ2TangentMatchesTheClosedForm) {
  const Eigen::Matrix3d N = flow_direction(), M = orthogonal_direction(), I = Eigen::Matrix3d::Identity();
  for (const double H : {-0.3 * kMu, -1e-3 * kMu, 0.0, 2e-3 * kMu, 0.4 * kMu})
    for (const double a : {1.0, -0.7})
      for (const double b : {0.0, 0.05, -0.3})
        for (const double e : {0.0, 0.02}) {
          const Eigen::Matrix3d D = a * N + b * M + (e / 3.0) * I;
          const double closed = kK * e * e + 2 * kMu * b * b + 2 * kMu * a * a * H / (3 * kMu + H);
          EXPECT_NEAR(drucker_product(j2_elastoplastic_tangent(kK, kMu, H, N), D), closed, 1e-12 * kK)
              << "H " << H << " a " << a << " b " << b << " e " << e;
        }
}

TEST(StabilityCheck, DruckerHardeningJ2TangentIsStableForEveryD) {
  const auto chk = create_stability_check("drucker", MapModelParameters{});
  ASSERT_TRUE(chk);
  // Random directions, and the worst one (D = N: product 2 mu H/(3 mu + H) > 0).
  for (const double H : {1e-4 * kMu, 0.1 * kMu, 2.0 * kMu}) {
    EXPECT_FALSE(chk->unstable(drucker_input(H, flow_direction()))) << "H " << H;
    for (int k = 0; k < 200; ++k) {
      const Eigen::Matrix3d R = Eigen::Matrix3d::Random();
      EXPECT_FALSE(chk->unstable(drucker_input(H, R + R.transpose()))) << "H " << H << " sample " << k;
    }
  }
}

TEST(StabilityCheck, DruckerSofteningJ2TangentThresholdAlongTheFlowDirection) {
  const auto drucker = create_stability_check("drucker", MapModelParameters{});
  const auto both = create_stability_check("drucker_becker", MapModelParameters{});
  const Eigen::Matrix3d N = flow_direction(), M = orthogonal_direction();
  for (const double H : {-0.05 * kMu, -0.5 * kMu}) {
    // Threshold (b/a)^2 = -H/(3 mu + H) with a = 1, e = 0 (closed form above).
    const double b_star = std::sqrt(-H / (3 * kMu + H));
    EXPECT_TRUE(drucker->unstable(drucker_input(H, N))) << "H " << H;
    EXPECT_TRUE(drucker->unstable(drucker_input(H, N + 0.99 * b_star * M))) << "H " << H;
    EXPECT_FALSE(drucker->unstable(drucker_input(H, N + 1.01 * b_star * M))) << "H " << H;
    EXPECT_TRUE(both->unstable(drucker_input(H, N + 0.99 * b_star * M))) << "H " << H;
    // A volumetric part stabilises: K e^2 > 2 mu |H|/(3 mu + H) with a = 1, b = 0.
    const double e_star = std::sqrt(2 * kMu * -H / ((3 * kMu + H) * kK));
    EXPECT_TRUE(drucker->unstable(drucker_input(H, N + (0.99 * e_star / 3.0) * Eigen::Matrix3d::Identity())));
    EXPECT_FALSE(drucker->unstable(drucker_input(H, N + (1.01 * e_star / 3.0) * Eigen::Matrix3d::Identity())));
  }
}

// The elastic tangent: (C^e : D) : D = K (tr D)^2 + 2 mu |dev D|^2 > 0 for D != 0: stable.
TEST(StabilityCheck, DruckerElasticStateIsStable) {
  const auto chk = create_stability_check("drucker", MapModelParameters{});
  const Tangent4 Ce = isotropic_tangent(kLambda, kMu);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Matrix3d R = Eigen::Matrix3d::Random();
    StabilityInput in;
    in.deformation_rate = R + R.transpose();
    in.tangent = Ce;
    const Eigen::Matrix3d dev = in.deformation_rate - (in.deformation_rate.trace() / 3.0) * Eigen::Matrix3d::Identity();
    EXPECT_NEAR(drucker_product(Ce, in.deformation_rate),
                kK * std::pow(in.deformation_rate.trace(), 2) + 2 * kMu * dev.squaredNorm(), 1e-12 * kK);
    EXPECT_FALSE(chk->unstable(in)) << "sample " << k;
  }
}

// Through the composed models: isochoric plane strain F = diag(e^e, 1, e^-e) with
// linear hardening sigma_y = s0 + H eps_p; softening (H < 0) is flagged once plastic,
// hardening is not (the max-stress and TEPLA tests are switched off).
MapModelParameters metal(const std::string& type, double H, const std::string& check) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kMu}, {"isothermal", 1.0},
                        {"check_max_stress_failure", 0.0}, {"check_TEPLA_failure_criterion", 0.0}});
  if (type == "elastic_plastic") p.values["coeff_thermal_expansion"] = 0.0;
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", 2e8}, {"K", H}});
  p.add_block("stability_check", check);
  p.enclosing = {{"melt_temp", 1800.0}, {"specific_heat", 450.0}, {"density", 7830.0}};
  return p;
}

TEST(StabilityCheck, SofteningFlagsThePointHardeningDoesNot) {
  for (const char* type : {"elastic_plastic", "elastic_plastic_hp"})
    for (const char* check : {"none", "drucker", "acoustic", "becker", "drucker_becker"})
      for (const double H : {-0.1 * kMu, 0.1 * kMu}) {
        const auto m = create_constitutive_model(type, metal(type, H, check));
        ASSERT_TRUE(m) << type;
        int localized = 0;
        while (localized < int(m->history().size()) && m->history()[localized].name != "localized") ++localized;
        ASSERT_LT(localized, int(m->history().size()));
        test::PointState s(*m);
        // Yield at 2 mu e sqrt(3) = s0 -> e ~ 1.9e-3; drive to e = 4e-3.
        int first_flag = -1;
        for (int k = 1; k <= 40; ++k) {
          Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
          F(0, 0) = std::exp(1e-4 * k);
          F(2, 2) = std::exp(-1e-4 * k);
          ASSERT_EQ(test::step_point(*m, 7830.0, s, F, 1e-6), -1);
          if (first_flag < 0 && s.history[localized][0] == 1.0) first_flag = k;
        }
        const bool expect = H < 0 && std::string(check) != "none";
        EXPECT_EQ(first_flag >= 0, expect) << type << " " << check << " H " << H;
        if (expect) EXPECT_GE(first_flag, 20) << "flagged before yield";  // elastic while 2 sqrt(3) mu e < s0 (k <= 19)
      }
}

// Porous yields (Gurson, Rousselier) take the J2-I1 continuum tangent (VT §18.6.2,
// ContinuumTangent.h; its finite-difference check: test_plasticity_tangent): the acoustic
// check flags a softening matrix (dsigma_y/deps_p = -0.1 mu) after yield and never a
// hardening one, in both models. Same plane-strain shear path as above.
TEST(StabilityCheck, PorousYieldSofteningFlagsThePointHardeningDoesNot) {
  for (const char* type : {"elastic_plastic", "elastic_plastic_hp"})
    for (const char* yield : {"gurson", "rousselier"})
      for (const double H : {-0.1 * kMu, 0.1 * kMu}) {
        auto p = metal(type, H, "acoustic");
        if (std::string(yield) == "gurson")
          p.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
        else
          p.add_block("yield_condition", "rousselier", {{"D", 2.0}, {"sigma_1", 300e6}});
        p.values["initial_mean_porosity"] = 0.01;
        p.values["evolve_porosity"] = 0.0;
        const auto m = create_constitutive_model(type, p);
        ASSERT_TRUE(m) << type;
        int localized = -1;
        for (std::size_t k = 0; k < m->history().size(); ++k)
          if (m->history()[k].name == "localized") localized = static_cast<int>(k);
        ASSERT_GE(localized, 0);
        test::PointState s(*m);
        int first_flag = -1, first_plastic = -1;
        for (int k = 1; k <= 40; ++k) {
          Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
          F(0, 0) = std::exp(1e-4 * k);
          F(2, 2) = std::exp(-1e-4 * k);
          ASSERT_EQ(test::step_point(*m, 7830.0, s, F, 1e-6), -1);
          if (first_plastic < 0 && s.history[0][0] > 0.0) first_plastic = k;
          if (first_flag < 0 && s.history[localized][0] == 1.0) first_flag = k;
        }
        ASSERT_GT(first_plastic, 0) << type << " " << yield;
        EXPECT_EQ(first_flag >= 0, H < 0) << type << " " << yield << " H " << H;
        if (H < 0) EXPECT_GE(first_flag, first_plastic) << "flagged before yield";
      }
}

}  // namespace
}  // namespace tephra
