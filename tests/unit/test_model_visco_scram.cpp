// visco_scram (models/solid/ViscoScram.h) against closed forms: the Maxwell
// elements at a constant deviatoric strain rate, the volumetric part p = K ln J
// (with thermal strain), the crack-growth law of Bennett et al. (1998) at
// hand-computed states, the work identity (stress work = stored + dissipated),
// the stability of the sub-stepped RK4 at dt >> tau, and the deck checks.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "models/solid/ViscoScram.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
using test::MapModelParameters;
using test::PointState;
using test::step_point;

constexpr double kRho0 = 1830.0;  // PBX 9501 [kg/m^3]

// PBX 9501 of the stock burn decks (guni2dRT.ups), with the given element moduli and rates.
MapModelParameters scram_params(std::array<double, 5> G, std::array<double, 5> RTau) {
  MapModelParameters p({{"PR", 0.3}, {"CrackParameterA", 1e-3}, {"CrackPowerValue", 10.0},
                        {"CrackMaxGrowthRate", 300.0}, {"StressIntensityF", 500.0}, {"CrackFriction", 0.35},
                        {"InitialCrackRadius", 3e-5}, {"CrackGrowthRate", 12.0}, {"Beta", 1.5e-4},
                        {"Gamma", 1.0}, {"DCp_DTemperature", 3.30773}});
  for (int i = 0; i < 5; ++i) {
    p.values["G" + std::to_string(i + 1)] = G[i];
    p.values["RTau" + std::to_string(i + 1)] = RTau[i];
  }
  p.enclosing = {{"specific_heat", 996.0}};
  return p;
}

// Cracks off: no growth (v_res capped at 0) from a 1 pm crack, (c/a)^3 = 1e-27.
MapModelParameters no_crack_params(std::array<double, 5> G, std::array<double, 5> RTau) {
  MapModelParameters p = scram_params(G, RTau);
  p.values["CrackMaxGrowthRate"] = 0.0;
  p.values["InitialCrackRadius"] = 1e-12;
  return p;
}

const std::array<double, 5> kG = {1.0e9, 2.0e9, 1.5e9, 1.0e9, 0.5e9};
const std::array<double, 5> kRTau = {0.0, 0.25, 0.5, 1.0, 2.0};  // [1/s]

// s_i(t) = 2 G_i eps_dot tau_i (1 - exp(-t/tau_i)), tau_i = 1/RTau_i (2 G_i eps_dot t for RTau_i = 0):
// the solution of s_i_dot = 2 G_i eps_dot - s_i/tau_i, s_i(0) = 0.
double maxwell_ramp(double G, double R, double eps_dot, double t) {
  return R == 0.0 ? 2 * G * eps_dot * t : 2 * G * eps_dot / R * (1 - std::exp(-R * t));
}

// Pure shear F = diag(e^{e t}, e^{-e t}, 1) over t in [0, 1] in n steps: d' = diag(e, -e, 0)
// exactly (R = I, U = F); returns the largest error of the xx element stresses
// over all elements and steps, relative to 2 G_i eps_dot (1 s).
double pure_shear_error(const ConstitutiveModel& m, int n, double T, const std::array<double, 5>& R_eff) {
  const double e = 1e-4;
  PointState s(m);
  s.temperature = T;
  EXPECT_EQ(step_point(m, kRho0, s, M3::Identity(), 0.0), -1);
  double worst = 0;
  for (int k = 1; k <= n; ++k) {
    const double t = double(k) / n;
    const M3 F = Eigen::Vector3d(std::exp(e * t), std::exp(-e * t), 1.0).asDiagonal();
    EXPECT_EQ(step_point(m, kRho0, s, F, 1.0 / n), -1);
    double sum = 0;
    for (int i = 0; i < 5; ++i) {
      const double exact = maxwell_ramp(kG[i], R_eff[i], e, t);
      worst = std::max(worst, std::abs(s.history[i][0] - exact) / (2 * kG[i] * e));
      // yy = -xx, to the round-off of the stretch increments (~1e-6 of 1: 1e-10 relative).
      EXPECT_NEAR(s.history[i][4], -s.history[i][0], 1e-9 * std::abs(s.history[i][0]));
      sum += s.history[i][0];
    }
    EXPECT_NEAR(s.stress(0, 0), sum, 1e-9 * sum);                   // sigma = p I + sum s_i, p = K ln J = 0
    EXPECT_NEAR(s.stress(2, 2), 0.0, 1e-9 * std::abs(sum));
  }
  return worst;
}

TEST(ViscoScram, ConstantDeviatoricRateMatchesMaxwellClosedFormAtFourthOrder) {
  const ConstitutiveModelP m = ViscoScram::create(no_crack_params(kG, kRTau));
  // h RTau_max <= 1/4 at n = 8: no sub-steps, so the error is RK4's O(dt^4).
  const double e8 = pure_shear_error(*m, 8, 300, kRTau), e16 = pure_shear_error(*m, 16, 300, kRTau),
               e32 = pure_shear_error(*m, 32, 300, kRTau);
  std::printf("visco_scram constant rate: max rel error %.3g %.3g %.3g (n = 8, 16, 32), order %.2f %.2f\n", e8, e16,
              e32, std::log2(e8 / e16), std::log2(e16 / e32));
  EXPECT_LT(e32, 1e-7);
  EXPECT_NEAR(std::log2(e8 / e16), 4.0, 0.3);
  EXPECT_NEAR(std::log2(e16 / e32), 4.0, 0.3);
}

TEST(ViscoScram, TimeTemperatureShiftScalesTheRelaxationRates) {
  MapModelParameters p = no_crack_params(kG, kRTau);
  p.values["use_time_temperature_equation"] = 1;
  p.values["T0"] = 298.0;
  const ConstitutiveModelP m = ViscoScram::create(p);
  // WLF: a_T = exp(-C1 (T - T0)/(C2 + T - T0)), C1 = 6.5, C2 = 120; RTau_i -> RTau_i / a_T.
  const double T = 350.0, a_T = std::exp(-6.5 * (T - 298.0) / (120.0 + T - 298.0));
  std::array<double, 5> R = kRTau;
  for (double& r : R) r /= a_T;
  EXPECT_LT(pure_shear_error(*m, 64, T, R), 1e-6);
  // At T = T0 no shift.
  EXPECT_LT(pure_shear_error(*m, 64, 298.0, kRTau), 1e-8);
}

TEST(ViscoScram, VolumetricPartIsKLnJMinusThermalStrain) {
  MapModelParameters p = no_crack_params(kG, kRTau);
  p.values["CoeffThermalExpansion"] = 1e-4;
  const ConstitutiveModelP m = ViscoScram::create(p);
  const double K = 2 * 6e9 * 1.3 / (3 * 0.4);  // K = 2G(1+nu)/(3(1-2nu)), G = sum G_i
  EXPECT_NEAR(m->bulk_modulus(), K, 1e-6);
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  // Uniaxial strain to lambda = 0.8 in 7 uneven steps while T rises 300 -> 370 K:
  // p = K [ln J - 3 alpha (T - 300)] exactly (log volume increments).
  const double lam[7] = {0.99, 0.95, 0.93, 0.9, 0.87, 0.82, 0.8};
  for (int k = 0; k < 7; ++k) {
    s.temperature = 300.0 + 10.0 * (k + 1);
    ASSERT_EQ(step_point(*m, kRho0, s, Eigen::Vector3d(lam[k], 1, 1).asDiagonal().toDenseMatrix(), 1e-3), -1);
    const double p_exact = K * (std::log(lam[k]) - 3e-4 * (s.temperature - 300.0));
    EXPECT_NEAR(s.stress.trace() / 3, p_exact, 1e-12 * std::abs(p_exact));
  }
  // Volumetric heating -Gamma T tr(d), tr(d) = ln(0.8/0.82)/dt - 3 alpha dT/dt: the
  // only heating term besides the (here positive) viscous one.
  const double trd = (std::log(0.8 / 0.82) - 3e-4 * 10.0) / 1e-3;
  EXPECT_NEAR(s.history[ViscoScram::kVolHeat][0], 1.0 * 370.0 * trd, 1e-9 * 370 * std::abs(trd));
}

// <MPM><DoThermalExpansion>false</DoThermalExpansion> (Vaango ViscoScram zeroes
// CoeffThermalExpansion under it): the same heated uniaxial-strain path gives
// p = K ln J exactly, the thermal strain 3 alpha (T - 300) gone.
TEST(ViscoScram, DoThermalExpansionFalseRemovesTheThermalStrain) {
  MapModelParameters p = no_crack_params(kG, kRTau);
  p.values["CoeffThermalExpansion"] = 1e-4;
  p.mpm_flags["DoThermalExpansion"] = false;
  const ConstitutiveModelP m = ViscoScram::create(p);
  const double K = 2 * 6e9 * 1.3 / (3 * 0.4);
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double lam[3] = {0.99, 0.95, 0.9};
  for (int k = 0; k < 3; ++k) {
    s.temperature = 300.0 + 30.0 * (k + 1);
    ASSERT_EQ(step_point(*m, kRho0, s, Eigen::Vector3d(lam[k], 1, 1).asDiagonal().toDenseMatrix(), 1e-3), -1);
    const double p_exact = K * std::log(lam[k]);
    EXPECT_NEAR(s.stress.trace() / 3, p_exact, 1e-12 * std::abs(p_exact));
  }
}

TEST(ViscoScram, CrackGrowthLawAtHandComputedStates) {
  const ViscoScram m(*std::static_pointer_cast<const ViscoScram>(ViscoScram::create(scram_params(kG, kRTau))));
  const M3 s = Eigen::Vector3d(3e6, -1e6, -2e6).asDiagonal();   // s:s = 1.4e13 Pa^2
  const M3 d = Eigen::Vector3d(10.0, -5.0, -5.0).asDiagonal();  // |d'| = sqrt(150) 1/s
  // By hand (Bennett et al. 1998 [24-31], Vaango constants): eps_eff = sqrt(3/2) |d'| = 15,
  // v_res = exp(0.90564746 ln 15 - 2.90178468) = 0.638109172299441 m/s; compression p = -2 MPa:
  // sigma_e = sqrt(s:s) = 3741657.38677394 Pa; mu' = sqrt(45/(2(3 - 2 mu^2))) mu.
  struct Case { double p, c, K_0m, K_p, rate; };
  const Case cases[] = {
      {-2e6, 1e-12, 503.144986408002, 551.167717502586, 5.13750016281163e-20},  // slow: v (K_I/K_1)^m
      {-2e6, 1e-10, 531.676837915834, 582.422794859041, 2.9594154279885e-10},
      {-2e6, 1e-5, 11657.9399602858, 12770.6333805788, 0.506656491156604},   // fast: v (1 - (K_0m/K_I)^2)
      // tension p = +1 MPa: v_res x CrackGrowthRate = 7.65731006759329, sigma_e = sqrt(s:s + 3 p^2),
      // no friction (K_0m = K_0 = 500).
      {1e6, 1e-10, 500.0, 547.722557505166, 1.73288193781165e-08},
      {1e6, 1e-5, 500.0, 547.722557505166, 7.65492046220497}};
  for (const Case& k : cases) {
    const ViscoScramCrackLaw law = visco_scram_crack_law(m.params(), k.c, k.p, s, d);
    EXPECT_NEAR(law.K_0m, k.K_0m, 1e-12 * k.K_0m);
    EXPECT_NEAR(law.K_p, k.K_p, 1e-12 * k.K_p);
    EXPECT_NEAR(law.rate(k.c), k.rate, 1e-11 * k.rate) << "p = " << k.p << ", c = " << k.c;
  }
  // The two branches meet at K_I = K' with rate v_res / (1 + m/2).
  const ViscoScramCrackLaw law = visco_scram_crack_law(m.params(), 1e-5, -2e6, s, d);
  const double c_star = law.K_p * law.K_p / (1.5 * M_PI * law.sigma_e * law.sigma_e);
  EXPECT_NEAR(law.rate(c_star * (1 - 1e-12)), law.v_res / 6.0, 1e-9 * law.v_res);
  EXPECT_NEAR(law.rate(c_star * (1 + 1e-12)), law.v_res / 6.0, 1e-9 * law.v_res);
}

TEST(ViscoScram, CrackRadiusFollowsItsGrowthLawThroughTheUpdate) {
  // One small step from a stressed state: (c_{n+1} - c_n)/dt = c_dot(c_n + dt c_dot/2) + O(dt^2)
  // (midpoint rule for dc/dt = c_dot(c) with the stress frozen at t_n).
  const ConstitutiveModelP m = ViscoScram::create(scram_params(kG, kRTau));
  const auto& vs = static_cast<const ViscoScram&>(*m);
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const M3 F1 = Eigen::Vector3d(0.995, 1.002, 1.002).asDiagonal();  // compression + shear
  ASSERT_EQ(step_point(*m, kRho0, s, F1, 1e-6), -1);
  const double c_n = s.history[ViscoScram::kCrackRadius][0];
  const M3 F2 = Eigen::Vector3d(0.995 - 1e-6, 1.002 + 5e-7, 1.002 + 5e-7).asDiagonal();
  const double dt = 1e-7;
  // The law at t_n: the deviatoric stress (unrotated = spatial, R = I), mean stress, d'.
  M3 S = M3::Zero();
  for (int i = 0; i < 5; ++i) S += Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(s.history[i].data());
  const M3 g = (F2 - F1) * (0.5 * (F1 + F2)).inverse();
  const M3 d = g / dt;
  const ViscoScramCrackLaw law =
      visco_scram_crack_law(vs.params(), c_n, s.stress.trace() / 3, S, d - d.trace() / 3 * M3::Identity());
  const double rate = law.rate(c_n);
  ASSERT_GT(rate, 0.0);
  ASSERT_EQ(step_point(*m, kRho0, s, F2, dt), -1);
  const double c_new = s.history[ViscoScram::kCrackRadius][0];
  std::printf("visco_scram crack: c = %.6g m, c_dot = %.6g m/s, (c_new - c)/dt = %.6g\n", c_n, rate,
              (c_new - c_n) / dt);
  const double rate_mid = law.rate(c_n + 0.5 * dt * rate);
  EXPECT_GT(std::abs(rate_mid - rate), 1e-6 * rate);  // the step is long enough to see c_dot(c) vary
  EXPECT_NEAR((c_new - c_n) / dt, rate_mid, 1e-8 * rate);
}

TEST(ViscoScram, StressWorkEqualsStoredPlusDissipatedEnergy) {
  // Cracks off, shear ramp then hold: int sigma:d dt = W(t) + int W_ve dt. The
  // work is summed by the trapezoidal rule and the dissipation by the
  // end-of-step rate the model reports (first order), so the residual falls like dt.
  const ConstitutiveModelP m = ViscoScram::create(no_crack_params(kG, kRTau));
  auto residual = [&](int n) {
    PointState s(*m);
    EXPECT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    double work = 0, dissipated = 0, e_prev = 0;
    for (int k = 1; k <= n; ++k) {
      const double t = 2.0 * k / n;
      const double eps = 1e-4 * std::min(t, 1.0);
      const M3 sig_old = s.stress;
      EXPECT_EQ(step_point(*m, kRho0, s, Eigen::Vector3d(std::exp(eps), std::exp(-eps), 1).asDiagonal().toDenseMatrix(), 2.0 / n), -1);
      const double de = eps - e_prev;
      e_prev = eps;
      work += 0.5 * ((sig_old(0, 0) + s.stress(0, 0)) - (sig_old(1, 1) + s.stress(1, 1))) * de;
      EXPECT_GE(s.plastic_work, 0.0);
      EXPECT_GE(s.heating, 0.0);  // no volume change: viscous heating only
      dissipated += s.plastic_work;
    }
    return std::abs(work - s.energy_density - dissipated) / work;
  };
  const double r1 = residual(200), r2 = residual(400);
  std::printf("visco_scram work identity: residual %.3g, %.3g (order %.2f)\n", r1, r2, std::log2(r1 / r2));
  EXPECT_LT(r2, 1e-2);
  EXPECT_NEAR(std::log2(r1 / r2), 1.0, 0.2);
}

TEST(ViscoScram, ViscousHeatingIsTheElementDissipationOverRhoCv) {
  const ConstitutiveModelP m = ViscoScram::create(no_crack_params(kG, kRTau));
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  ASSERT_EQ(step_point(*m, kRho0, s, Eigen::Vector3d(std::exp(1e-3), std::exp(-1e-3), 1).asDiagonal().toDenseMatrix(), 0.5), -1);
  double w = 0;  // W_ve = sum_i s_i:s_i RTau_i / (2 G_i)
  for (int i = 0; i < 5; ++i)
    w += Eigen::Map<const Eigen::VectorXd>(s.history[i].data(), 9).squaredNorm() * kRTau[i] / (2 * kG[i]);
  EXPECT_GT(w, 0.0);
  EXPECT_NEAR(s.history[ViscoScram::kVeHeat][0], w / (kRho0 * 996.0), 1e-12 * w / (kRho0 * 996.0));
  EXPECT_NEAR(s.plastic_work, w * 0.5, 1e-12 * w);
}

TEST(ViscoScram, DissipationIsNonNegativeWithGrowingCracks) {
  // PBX 9501 of guni2dRT.ups (tau_5 = 0.5 us), compression with shear at 1e3 1/s.
  const ConstitutiveModelP m =
      ViscoScram::create(scram_params({3.5e8, 1.739e8, 5.212e8, 9.085e8, 6.875e8}, {0.0, 7.32e3, 7.32e4, 7.32e5, 2e6}));
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double c0 = s.history[ViscoScram::kCrackRadius][0];
  double c_prev = c0;
  for (int k = 1; k <= 100; ++k) {
    const double e = 1e-3 * k;  // 1e-3 per step of 1e-5 s (100 1/s), up to 0.1
    ASSERT_EQ(step_point(*m, kRho0, s, Eigen::Vector3d(1 - e, 1 + 0.3 * e, 1 + 0.3 * e).asDiagonal().toDenseMatrix(), 1e-5), -1);
    EXPECT_GE(s.plastic_work, 0.0) << k;
    EXPECT_GE(s.history[ViscoScram::kCrHeat][0], 0.0) << k;
    EXPECT_GE(s.history[ViscoScram::kCrackRadius][0], c_prev);  // cracks never heal
    c_prev = s.history[ViscoScram::kCrackRadius][0];
  }
  std::printf("visco_scram PBX compression: c %.3g -> %.3g m, sigma_xx = %.4g Pa\n", c0, c_prev, s.stress(0, 0));
  EXPECT_GT(c_prev, c0);
}

TEST(ViscoScram, StableAndExactForStepsFarAboveTheRelaxationTime) {
  // Vaango caps dt at 1 us because its single RK4 step diverges for dt RTau > 2.8;
  // the sub-stepped update relaxes the fast element to its steady value
  // s_5 = 2 G_5 eps_dot / RTau_5 (1 - e^{-RTau_5 dt}), e^{-200} = 0 at dt = 1e-4 s.
  const std::array<double, 5> G = {3.5e8, 1.739e8, 5.212e8, 9.085e8, 6.875e8}, R = {0.0, 7.32e3, 7.32e4, 7.32e5, 2e6};
  const ConstitutiveModelP m = ViscoScram::create(no_crack_params(G, R));
  PointState s(*m);
  ASSERT_EQ(step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  const double e = 1.0, dt = 1e-4;  // eps_dot = 1 1/s
  ASSERT_EQ(step_point(*m, kRho0, s, Eigen::Vector3d(std::exp(e * dt), std::exp(-e * dt), 1).asDiagonal().toDenseMatrix(), dt), -1);
  for (int i = 0; i < 5; ++i) {
    const double exact = maxwell_ramp(G[i], R[i], e, dt);
    EXPECT_NEAR(s.history[i][0], exact, 2e-5 * std::abs(exact)) << "element " << i + 1;
  }
}

TEST(ViscoScram, DeckChecks) {
  // Vaango's visco_scram: PR in (-1, 0.5); randomized moduli, JWLC and the
  // Murnaghan volumetric options are MissingFeature (std::logic_error here);
  // useJWLEOS needs its JWL constants (test_model_visco_scram_jwl).
  MapModelParameters p = scram_params(kG, kRTau);
  p.values["PR"] = 0.5;
  EXPECT_THROW(ViscoScram::create(p), std::invalid_argument);
  for (const char* flag : {"randomize_parameters", "useJWLCEOS", "useMurnahanEOS", "useBirchMurnaghanEOS"}) {
    MapModelParameters q = scram_params(kG, kRTau);
    q.values[flag] = 1;
    EXPECT_THROW(ViscoScram::create(q), std::logic_error) << flag;
  }
  MapModelParameters q = scram_params(kG, kRTau);
  q.enclosing.clear();  // heating needs <specific_heat>
  EXPECT_THROW(ViscoScram::create(q), std::invalid_argument);
  q = scram_params(kG, kRTau);
  q.values.erase("G3");
  EXPECT_THROW(ViscoScram::create(q), std::invalid_argument);
}

TEST(ViscoScram, ModifiedEosBelowReferenceDensity) {
  MapModelParameters p = scram_params(kG, kRTau);
  p.values["useModifiedEOS"] = 1;
  const auto m = std::static_pointer_cast<const ViscoScram>(ViscoScram::create(p));
  EXPECT_TRUE(m->modified_eos());  // MPMICE adds the expansion branch with its p_ref (ModifiedEos.h)
  const double K = m->bulk_modulus(), p_ref = 101325.0;
  for (double x : {1 - 1e-5, 1 - 1e-6, 1.0, 1.001}) {  // K/p_ref = 64150: steep below rho0
    const double rho = x * kRho0;
    const SolidEosPoint e = m->modified_eos_pressure(rho, kRho0, p_ref);
    // rho < rho0: p = p_ref (rho/rho0)^(K/p_ref) > 0 (absolute); else the standard EOS.
    const double expect = x < 1 ? p_ref * std::pow(x, K / p_ref) - p_ref : 0.5 * K * (x - 1 / x);
    EXPECT_NEAR(e.pressure, expect, 1e-9 * K * std::abs(1 - x) + 1e-9 * p_ref);
    EXPECT_GT(e.pressure + p_ref, 0.0);
    const double h = 1e-9 * rho;  // (K/p_ref h/rho)^2/6 ~ 1e-9: truncation below the tolerance
    const double fd = (m->modified_eos_pressure(rho + h, kRho0, p_ref).pressure -
                       m->modified_eos_pressure(rho - h, kRho0, p_ref).pressure) / (2 * h);
    if (x != 1.0) EXPECT_NEAR(e.dp_drho, fd, 1e-6 * e.dp_drho);
    EXPECT_NEAR(m->modified_eos_density(e.pressure, kRho0, p_ref), rho, 1e-11 * rho);
  }
  // dp/drho is continuous at rho0: K/rho0 from both sides.
  EXPECT_NEAR(m->modified_eos_pressure(kRho0 * (1 - 1e-12), kRho0, p_ref).dp_drho, K / kRho0, 1e-6 * K / kRho0);
}

}  // namespace
}  // namespace tephra
