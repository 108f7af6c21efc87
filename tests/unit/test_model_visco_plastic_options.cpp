// visco_plastic (SUVIC-I) model options <tolerance>, <initial_material_temperature> and
// <use_polar_decomposition_RMB> (models/solid/ViscoPlastic.h header; Vaango ViscoPlastic
// constructor and explicit computeStressTensor). Expected values, each written here:
//  - tolerance: components of the laboratory rate of deformation below tol are zero; when all
//    are, the point is not updated (stress, beta, R, K, plastic strain unchanged; no heating, no
//    plastic work); with tolerance 0 the same step relaxes the overstress (SUVIC-I, eq. 10.29:
//    eps_dot_eq > 0 whenever X_ae > R, whatever the strain rate);
//  - elastic coaxial stretching (R_0 = 1 GPa) with a lateral stretch rate g: the stress change
//    from g is (K + 4G/3) g t along it and (K - 2G/3) g t across (hypoelastic, VT eq. 4.2);
//  - initial_material_temperature and use_polar_decomposition_RMB have no effect (Vaango never
//    reads them in this model): results bit-identical to the defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/solid/ViscoPlastic.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kG = 3.52e9, kK = 8.9e9, kRho0 = 917.0, kCp = 2093.0;  // ice (VT §10.8)

test::MapModelParameters params(std::map<std::string, double> model = {}, std::map<std::string, double> flow = {}) {
  model.emplace("shear_modulus", kG);
  model.emplace("bulk_modulus", kK);
  test::MapModelParameters p(model);
  p.enclosing = {{"specific_heat", kCp}, {"melt_temp", 273.15}};
  p.add_block("viscoplastic_flow_model", "suvic_i", std::move(flow));
  return p;
}

// F(t) of uniaxial extension at true rate e plus simple shear at rate g: F = [[exp(e t), g t, 0], [0, 1, 0], [0, 0, 1]].
M3 path(double e, double g, double t) {
  M3 F = M3::Identity();
  F(0, 0) = std::exp(e * t);
  F(0, 1) = g * t;
  return F;
}

std::vector<test::PointState> run(const test::MapModelParameters& p, double e, double g, double dt, int n) {
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", p);
  std::vector<test::PointState> out;
  test::PointState s(*m);
  EXPECT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= n; ++k) {
    EXPECT_EQ(test::step_point(*m, kRho0, s, path(e, g, k * dt), dt), -1);
    out.push_back(s);
  }
  return out;
}

TEST(ModelViscoPlasticOptions, TruncateRateZeroesComponentsBelowTheTolerance) {
  M3 d;
  d << 1e-3, 5e-11, 0, 5e-11, -2e-10, 1e-10, 0, 1e-10, -1e-11;
  M3 expect;  // |d_ij| < 1e-10 -> 0; 1e-10 itself is kept (strict <, as Vaango)
  expect << 1e-3, 0, 0, 0, -2e-10, 1e-10, 0, 1e-10, 0;
  EXPECT_FALSE(suvic_truncate_rate(d, 1e-10));
  EXPECT_EQ((d - expect).norm(), 0.0);
  M3 small = M3::Constant(9e-11);
  EXPECT_TRUE(suvic_truncate_rate(small, 1e-10));
  EXPECT_EQ(small.norm(), 0.0);
  M3 zero = M3::Zero();
  EXPECT_TRUE(suvic_truncate_rate(zero, 1e-10));
}

TEST(ModelViscoPlasticOptions, PointBelowTheToleranceIsNotUpdated) {
  // 20 steps of uniaxial extension at 1e-3 /s (dt 0.05 s; R_0 = 0: flowing with an overstress),
  // then 10 steps at 1e-12 /s (every component of D below Vaango's default 1e-10): the point
  // keeps its state exactly. With <tolerance> 0 the same steps relax the overstress: the
  // equivalent inelastic strain grows and the axial stress falls (eq. 10.29).
  const double dt = 0.05;
  for (double tol : {1e-10, 0.0}) {
    const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params({{"tolerance", tol}}));
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    for (int k = 1; k <= 20; ++k) ASSERT_EQ(test::step_point(*m, kRho0, s, path(1e-3, 0, k * dt), dt), -1);
    const test::PointState loaded = s;
    ASSERT_GT(loaded.history[3][0], 0.0);  // flowing
    double heat = 0, work = 0;
    for (int k = 1; k <= 10; ++k) {
      M3 F = loaded.F;
      F(0, 0) *= std::exp(1e-12 * k * dt);
      ASSERT_EQ(test::step_point(*m, kRho0, s, F, dt), -1);
      heat += std::abs(s.heating);
      work += std::abs(s.plastic_work);
    }
    if (tol > 0) {
      EXPECT_LE((s.stress - loaded.stress).norm(), 1e-14 * loaded.stress.norm());  // R_n = R_{n+1} = I
      for (size_t c = 0; c < 4; ++c)  // backstress, R, K, plastic strain: exactly the step-start values
        for (size_t j = 0; j < s.history[c].size(); ++j) EXPECT_EQ(s.history[c][j], loaded.history[c][j]) << c;
      EXPECT_EQ(heat, 0.0);
      EXPECT_EQ(work, 0.0);
    } else {
      EXPECT_GT(s.history[3][0], loaded.history[3][0]);
      EXPECT_LT(s.stress(0, 0), loaded.stress(0, 0));
      EXPECT_GT(heat, 0.0);
    }
    std::printf("tolerance %g: sigma_11 %.6e -> %.6e Pa, eps_eq %.6e -> %.6e\n", tol, loaded.stress(0, 0),
                s.stress(0, 0), loaded.history[3][0], s.history[3][0]);
  }
}

TEST(ModelViscoPlasticOptions, StretchRateBelowTheToleranceIsIgnored) {
  // Elastic (R_0 = 1 GPa), 10 steps of 0.05 s, F = diag(exp(e t), exp(g t), 1): extension at
  // e = 1e-3 /s plus a lateral stretch at g = 1e-11 /s (D_22 = g < 1e-10; F diagonal, so R = I and
  // the laboratory D is the unrotated one). With the default tolerance D_22 is dropped and the
  // result is the pure extension's (g = 0) to round-off. With <tolerance> 0 the lateral stretch
  // adds, by hypoelasticity (VT eq. 4.2, coaxial stretching), sigma_22 - sigma_22(g = 0) =
  // (K + 4G/3) g t and sigma_11 - sigma_11(g = 0) = (K - 2G/3) g t (0.07 and 0.03 Pa against
  // ~5e5 Pa: checked to 1e-4 of the increment, far above the round-off 5e5 * 1e-16).
  const double e = 1e-3, g = 1e-11, dt = 0.05;
  const std::map<std::string, double> flow{{"initial_yield", 1e9}};
  const auto run_diag = [&](const test::MapModelParameters& p, double g_rate) {
    const ConstitutiveModelP m = create_constitutive_model("visco_plastic", p);
    std::vector<test::PointState> out;
    test::PointState s(*m);
    EXPECT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    for (int k = 1; k <= 10; ++k) {
      EXPECT_EQ(test::step_point(*m, kRho0, s, Eigen::Vector3d(std::exp(e * k * dt), std::exp(g_rate * k * dt), 1.0)
                                                   .asDiagonal().toDenseMatrix(), dt), -1);
      out.push_back(s);
    }
    return out;
  };
  const auto pure = run_diag(params({}, flow), 0.0);
  const auto cut = run_diag(params({}, flow), g);
  const auto pure0 = run_diag(params({{"tolerance", 0.0}}, flow), 0.0);
  const auto kept = run_diag(params({{"tolerance", 0.0}}, flow), g);
  for (int k = 0; k < 10; ++k) {
    EXPECT_LE((cut[k].stress - pure[k].stress).norm(), 1e-13 * pure[k].stress.norm()) << k;
    const double gt = g * (k + 1) * dt;
    EXPECT_NEAR(kept[k].stress(1, 1) - pure0[k].stress(1, 1), (kK + 4 * kG / 3) * gt, 1e-4 * (kK + 4 * kG / 3) * gt) << k;
    EXPECT_NEAR(kept[k].stress(0, 0) - pure0[k].stress(0, 0), (kK - 2 * kG / 3) * gt, 1e-4 * (kK - 2 * kG / 3) * gt) << k;
  }
  // Only the stretch below the tolerance: the point is not updated at all (stress stays 0).
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params({}, flow));
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= 10; ++k)
    ASSERT_EQ(test::step_point(*m, kRho0, s, Eigen::Vector3d(1.0, std::exp(g * k * dt), 1.0).asDiagonal().toDenseMatrix(), dt), -1);
  EXPECT_EQ(s.stress.norm(), 0.0);
}

TEST(ModelViscoPlasticOptions, HeatingAtFixedDeformationIsSkippedWithTheDefaultTolerance) {
  // F = I held, T from 260 K to 270 K (ModelViscoPlasticThermal with <tolerance> 0 gives
  // sigma = -3 K alpha dT I): with the default tolerance D = 0 and the point is not updated
  // (Vaango: "just sitting there"), so no thermal stress develops.
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params({}, {{"initial_yield", 1e9}}));
  test::PointState s(*m);
  s.temperature = 260.0;
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= 10; ++k) {
    s.temperature = 260.0 + k;
    ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.1), -1);
  }
  EXPECT_EQ(s.stress.norm(), 0.0);
}

TEST(ModelViscoPlasticOptions, InitialTemperatureAndPolarDecompositionFlagHaveNoEffect) {
  // 40 steps of extension with shear (both above the tolerance): the options change nothing.
  const double e = 1e-3, g = 4e-4, dt = 0.05;
  const auto ref = run(params(), e, g, dt, 40);
  for (const auto& opt : std::vector<std::map<std::string, double>>{
           {{"initial_material_temperature", 100.0}},
           {{"use_polar_decomposition_RMB", 0.0}},
           {{"use_polar_decomposition_RMB", 1.0}, {"initial_material_temperature", 300.0}}}) {
    const auto got = run(params(opt), e, g, dt, 40);
    for (int k = 0; k < 40; ++k) {
      EXPECT_EQ((got[k].stress - ref[k].stress).norm(), 0.0) << k;
      EXPECT_EQ(got[k].history, ref[k].history) << k;
    }
  }
  EXPECT_GT(ref.back().history[3][0], 0.0);  // the path flows
}

TEST(ModelViscoPlasticOptions, InitialDragFromVaangosMisspeltTag) {
  // Vaango's schema and ViscoPlastic read the initial drag K_0 from <intial_drag>: the drag
  // history starts at that value; <initial_drag> is the same; both at once is an error.
  for (const char* tag : {"intial_drag", "initial_drag"}) {
    const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params({}, {{tag, 0.07e6}}));
    EXPECT_EQ(m->history()[2].name, "drag");
    EXPECT_EQ(m->history()[2].initial[0], 0.07e6) << tag;
  }
  EXPECT_THROW(create_constitutive_model("visco_plastic", params({}, {{"intial_drag", 0.07e6}, {"initial_drag", 0.07e6}})),
               std::invalid_argument);
  EXPECT_THROW(create_constitutive_model("visco_plastic", params({}, {{"intial_drag", 0.0}})), std::invalid_argument);
}

TEST(ModelViscoPlasticOptions, BadValuesAreDeckErrors) {
  EXPECT_THROW(create_constitutive_model("visco_plastic", params({{"tolerance", -1e-10}})), std::invalid_argument);
  EXPECT_THROW(create_constitutive_model("visco_plastic", params({{"initial_material_temperature", 0.0}})),
               std::invalid_argument);
  EXPECT_THROW(create_constitutive_model("visco_plastic", params({{"initial_material_temperature", -5.0}})),
               std::invalid_argument);
  EXPECT_NO_THROW(create_constitutive_model("visco_plastic", params({{"tolerance", 0.0}})));
}

}  // namespace
}  // namespace tephra
