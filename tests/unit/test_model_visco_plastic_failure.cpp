// visco_plastic (SUVIC-I) failure, heating-free options, thermal strain and MPMICE hooks
// (models/solid/ViscoPlastic.h header; Vaango ViscoPlastic: updateFailedParticlesAndModifyStress,
// computePressEOSCM, computeRhoMicroCM). Each expected value is written here:
//  - hooks: p = K/2 (eta - 1/eta), eta = rho/rho0; dp/drho = K/2 (1/rho0 + rho0/rho^2); c^2 = K/rho;
//    rho(p) = rho0 (x + sqrt(x^2 + 1)), x = p/K;
//  - failure: the failed run equals the run without failure up to the first inelastic step whose
//    measure exceeds v_f; at that step sigma becomes 0 (zero_stress_upon_failure), 0 / p I
//    (allow_no_tension) or stays, and afterwards the point keeps that stress;
//  - measures: uniaxial stretch F = diag(l, 1, 1): Almansi e_11 = (1 - l^-2)/2;
//  - thermal strain: heating at fixed F (elastic, R_0 = 1 GPa): sigma = -3 K alpha (T - T_0) I.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

#include "models/solid/MetalFailure.h"
#include "models/solid/ModifiedEos.h"
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

double max_principal(const M3& s) {
  return Eigen::SelfAdjointEigenSolver<M3>(s, Eigen::EigenvaluesOnly).eigenvalues()(2);
}

// Uniaxial strain at true rate e (F = diag(exp(e t), 1, 1)), sign of e = tension/compression.
M3 uniaxial(double e, double t) {
  M3 F = M3::Identity();
  F(0, 0) = std::exp(e * t);
  return F;
}

TEST(ModelViscoPlasticHooks, PressureDensityAndInverseAreVaangosEos) {
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params());
  for (double eta : {0.9, 1.0, 1.1, 1.3}) {
    const double rho = eta * kRho0;
    const auto e = m->pressure_at_density(rho, kRho0, 269.15);
    ASSERT_TRUE(e);
    EXPECT_NEAR(e->pressure, 0.5 * kK * (eta - 1 / eta), 1e-12 * kK) << eta;
    EXPECT_NEAR(e->dp_drho, 0.5 * kK * (1 / kRho0 + kRho0 / (rho * rho)), 1e-12 * kK / kRho0) << eta;
    EXPECT_NEAR(e->c2, kK / rho, 1e-12 * kK / rho) << eta;
    const double h = 1e-5 * rho;  // central difference, error ~ h^2 p'''/6
    const double fd = (m->pressure_at_density(rho + h, kRho0, 0)->pressure -
                       m->pressure_at_density(rho - h, kRho0, 0)->pressure) / (2 * h);
    EXPECT_NEAR(fd, e->dp_drho, 1e-7 * e->dp_drho) << eta;
    const auto back = m->density_at_pressure(e->pressure, kRho0, 269.15);
    ASSERT_TRUE(back);
    EXPECT_NEAR(*back, rho, 1e-12 * rho) << eta;
  }
  EXPECT_FALSE(m->modified_eos());
  const ConstitutiveModelP mm = create_constitutive_model("visco_plastic", params({{"useModifiedEOS", 1.0}}));
  EXPECT_TRUE(mm->modified_eos());
  // Below rho0 MPMICE takes the shared expansion branch p_ref (rho/rho0)^(K0/p_ref) (ModifiedEos.h),
  // K0 = rho0 dp/drho(rho0) = K here, continuous with the hooks at rho0.
  const double p_ref = 101325.0;
  const auto lo = mpmice_absolute_pressure_at_density(*mm, 0.99999 * kRho0, kRho0, 269.15, p_ref);
  ASSERT_TRUE(lo);
  EXPECT_NEAR(lo->pressure, p_ref * std::pow(0.99999, kK / p_ref), 1e-9 * p_ref);  // 0.4155 p_ref
}

// Runs uniaxial strain at rate e for n steps of dt with `p`; returns the states after each step.
std::vector<test::PointState> run(const test::MapModelParameters& p, double e, double dt, int n) {
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", p);
  std::vector<test::PointState> out;
  test::PointState s(*m);
  EXPECT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= n; ++k) {
    EXPECT_EQ(test::step_point(*m, kRho0, s, uniaxial(e, k * dt), dt), -1);
    out.push_back(s);
  }
  return out;
}

// The first step (index) of `ref` with inelastic flow whose measure exceeds vf.
int first_failure(const std::vector<test::PointState>& ref, double vf, bool by_pressure = false) {
  for (size_t k = 0; k < ref.size(); ++k) {
    const double d_eq = ref[k].history[3][0] - (k ? ref[k - 1].history[3][0] : 0.0);
    const double m = by_pressure ? ref[k].stress.trace() / 3 : max_principal(ref[k].stress);
    if (d_eq > 0 && m > vf) return int(k);
  }
  return -1;
}

TEST(ModelViscoPlasticFailure, MaxPrincipalStressFailureZeroesTheStressFromThatStepOn) {
  // Uniaxial tension at 1e-3 /s, 0.05 s steps, 100 steps (the deck's ice: flow starts at once,
  // R_0 = 0). v_f = 3 MPa is crossed part way: before it the run equals the one without the check
  // bit for bit, at and after it sigma = 0 and localized = 1.
  const double e = 1e-3, dt = 0.05, vf = 3.0e6;
  const auto ref = run(params(), e, dt, 100);
  const int kf = first_failure(ref, vf);
  ASSERT_GT(kf, 0) << "the path never reaches v_f: choose a smaller v_f";
  ASSERT_LT(kf, 99);
  RecordProperty("failure_step", kf);
  const auto got = run(params({{"check_failure", 1}, {"failure_variable_mean", vf}}), e, dt, 100);
  for (int k = 0; k < kf; ++k) {
    EXPECT_EQ((got[k].stress - ref[k].stress).norm(), 0.0) << k;
    EXPECT_EQ(got[k].history[4][0], 0.0) << k;
  }
  for (int k = kf; k < 100; ++k) {
    EXPECT_EQ(got[k].stress.norm(), 0.0) << k;
    EXPECT_EQ(got[k].history[4][0], 1.0) << k;
    if (k > kf) EXPECT_EQ(got[k].heating, 0.0) << k;  // the failure step itself heats (Vaango: before the check)
  }
  // The step's changes of beta, R, K are discarded at failure (Vaango's updateElastic).
  EXPECT_EQ(got[kf].history[1][0], ref[kf - 1].history[1][0]);
  EXPECT_EQ(got[kf].history[2][0], ref[kf - 1].history[2][0]);
}

TEST(ModelViscoPlasticFailure, AllowNoTensionAndKeepStressOptions) {
  // Failure by the mean stress (failure_by_stress false, failure_by_pressure true), v_f = -1 GPa:
  // the first step is inelastic (R_0 = 0) and its mean stress is above v_f, so the point fails at
  // step 0 with the stress of the run without the check, ref[0], modified by the option:
  //  compression + allow_no_tension: sigma = p I, p = tr(ref[0])/3 < 0;
  //  tension + allow_no_tension:     sigma = 0 (p > 0);
  //  neither option:                 sigma = ref[0] unchanged;
  // and keeps that stress on every later step while F goes on changing.
  const double dt = 0.05, vf = -1e9;
  const std::map<std::string, double> opts = {{"check_failure", 1}, {"failure_variable_mean", vf},
                                              {"failure_by_stress", 0}, {"failure_by_pressure", 1},
                                              {"zero_stress_upon_failure", 0}};
  for (double e : {-1e-3, 1e-3}) {
    const auto ref = run(params(), e, dt, 20);
    ASSERT_GT(ref[0].history[3][0], 0.0) << "step 0 must be inelastic";
    auto o = opts;
    o["allow_no_tension"] = 1;
    const auto got = run(params(o), e, dt, 20);
    const double p = ref[0].stress.trace() / 3;
    const M3 expect = e < 0 ? M3(p * M3::Identity()) : M3::Zero();
    EXPECT_EQ(e < 0, p < 0);
    for (int k = 0; k < 20; ++k) {
      EXPECT_EQ((got[k].stress - expect).norm(), 0.0) << "rate " << e << " step " << k;
      EXPECT_EQ(got[k].history[4][0], 1.0);
    }
    const auto kept = run(params(opts), e, dt, 20);
    for (int k = 0; k < 20; ++k) EXPECT_EQ((kept[k].stress - ref[0].stress).norm(), 0.0) << e << " " << k;
    EXPECT_GT((ref[19].stress - ref[0].stress).norm(), 1e-3 * ref[0].stress.norm());  // it would have changed
  }
}

TEST(ModelViscoPlasticFailure, GaussianFailureVariableIsDrawnOncePerPoint) {
  // failure_variable_distrib gauss: v_f = |mean + std N|, N = seeded_normal(0, point index)
  // (MetalFailure.h), drawn at the first update and kept.
  test::MapModelParameters p = params({{"check_failure", 1}, {"failure_variable_mean", 2e6},
                                       {"failure_variable_std", 5e5}});
  p.strings["failure_variable_distrib"] = "gauss";
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", p);
  test::PointState s(*m);
  EXPECT_EQ(s.history[5][0], -1.0);  // not drawn yet
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double vf = std::abs(2e6 + 5e5 * seeded_normal(0, 0));
  EXPECT_EQ(s.history[5][0], vf);
  ASSERT_EQ(test::step_point(*m, kRho0, s, uniaxial(1e-3, 0.05), 0.05), -1);
  EXPECT_EQ(s.history[5][0], vf);
}

TEST(ModelViscoPlasticThermal, ConstrainedHeatingGivesMinusThreeKAlphaDeltaT) {
  // Elastic (R_0 = 1 GPa), F = I held, T from 260 to 270 K in 10 steps: the mechanical strain
  // rate is -alpha dT/dt I, so sigma = -3 K alpha (T - T_0) I exactly (alpha = 1e-5, Vaango's
  // default); with coeff_thermal_expansion 0 no stress. <tolerance> 0: with Vaango's default 1e-10
  // a point at fixed F is not updated at all (test_model_visco_plastic_options.cpp).
  for (double alpha : {1e-5, 0.0}) {
    std::map<std::string, double> mp{{"tolerance", 0.0}};
    if (alpha == 0.0) mp["coeff_thermal_expansion"] = 0.0;
    const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params(mp, {{"initial_yield", 1e9}}));
    test::PointState s(*m);
    s.temperature = 260.0;
    ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    for (int k = 1; k <= 10; ++k) {
      s.temperature = 260.0 + k;
      ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.1), -1);
      const M3 expect = -3 * kK * alpha * k * M3::Identity();
      EXPECT_LE((s.stress - expect).norm(), 1e-9 * 3 * kK * 1e-5 * k) << alpha << " " << k;
    }
  }
}

TEST(ModelViscoPlasticFailure, RemoveParticlesMeltCheckOnlyDiscardsTheInternalVariableStep) {
  // <remove_particles> with <check_failure>: Vaango's melt check (T + dT > the material's
  // <melt_temp> = 273.15 K here; the point is at 300 K) marks the step "localized" only locally:
  // beta, R, K keep their step-start values (updateElastic), the stress is the same as without
  // the check and the point is not flagged (v_f = 1e30 is never reached).
  const double e = 1e-3, dt = 0.05;
  const auto ref = run(params(), e, dt, 5);
  const auto got = run(params({{"check_failure", 1}, {"remove_particles", 1}}), e, dt, 5);
  ASSERT_GT(ref[0].history[1][0], 0.0);  // R grows without the check (R_0 = 0)
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(got[k].history[1][0], 0.0) << k;       // R stays R_0
    EXPECT_EQ(got[k].history[2][0], 0.05e6) << k;    // K stays K_0
    EXPECT_EQ(got[k].history[4][0], 0.0) << k;       // not flagged
  }
  EXPECT_EQ((got[0].stress - ref[0].stress).norm(), 0.0);  // the first step's stress is unchanged
  test::MapModelParameters no_tm = params({{"remove_particles", 1}});
  no_tm.enclosing.erase("melt_temp");
  EXPECT_THROW(create_constitutive_model("visco_plastic", no_tm), std::invalid_argument);
}

TEST(ModelViscoPlasticFailure, MeasuresAndOptions) {
  SuvicFailure f;
  const M3 s = Eigen::Vector3d(3e6, -1e6, 2e6).asDiagonal();
  M3 F = M3::Identity();
  F(0, 0) = 1.2;
  EXPECT_DOUBLE_EQ(suvic_failure_measure(f, s, F), 3e6);  // largest principal stress (default)
  f.by_stress = false;
  f.by_pressure = true;
  EXPECT_DOUBLE_EQ(suvic_failure_measure(f, s, F), 4e6 / 3);  // tr(sigma)/3
  f.by_pressure = false;
  EXPECT_NEAR(suvic_failure_measure(f, s, F), 0.5 * (1 - 1 / (1.2 * 1.2)), 1e-15);  // Almansi e_11
}

}  // namespace
}  // namespace tephra
