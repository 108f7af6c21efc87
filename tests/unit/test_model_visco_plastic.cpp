// visco_plastic with suvic_i (models/solid/ViscoPlastic.h; VT eqs. 10.29-10.38):
// constant-rate isochoric extension F = diag(l, l^{-1/2}, l^{-1/2}), l = exp(e t),
// against an offline integration of the same ODEs written here in scalar form,
// and the steady state of eqs. 10.36-10.38 in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "models/solid/ViscoPlastic.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kG = 3.52e9, kK = 8.9e9, kRho0 = 917.0;  // the seed deck's ice (VT §10.8)
const double kCp = 2093.0;                            // ice c_p [J/(kg K)] (heating tests)
const SuvicParams kP;                                 // Vaango's defaults = the seed deck's values

test::MapModelParameters params(std::map<std::string, double> flow = {}) {
  test::MapModelParameters p({{"shear_modulus", kG}, {"bulk_modulus", kK}});
  p.enclosing = {{"specific_heat", kCp}};
  p.add_block("viscoplastic_flow_model", "suvic_i", std::move(flow));
  return p;
}

// Isochoric extension at true rate e: d = e diag(1, -1/2, -1/2) = (3/2) e m, m = diag(2/3, -1/3, -1/3)
// (sqrt(3/2 m:m) = 1). With s = S m, beta = b m the system reduces to scalars (x = S - b,
// X_ae = |x|, n = (3/2) sgn(x) m, eps_dot^i = eps_eq sgn(x) (3/2) m):
//   S_dot = 3G (e - sgn(x) eps_eq),   eps_eq = A exp(-Q/(R_g T)) <(|x| - R)/K>^N     (4.2, 10.29-10.32)
//   b_dot = A1 eps_eq (sgn(x) - b/beta_sat)                                           (10.33)
//   R_dot = A3 eps_eq (1 - R/R_sat) if R < R_sat;  K_dot = A5 eps_eq (1 - K/K_sat) if K < K_sat
// with the saturation values of eqs. 10.36-10.38 (10.38 with the 1/N power, see the header).
struct Scalar {
  double S = 0, b = 0, R = 0, K = 0;
};
Scalar rates(const Scalar& y, double e) {
  const double x = y.S - y.b, X = std::abs(x), sg = x > 0 ? 1 : -1;
  const double pre = kP.A * std::exp(-kP.Q / (kP.Rg * kP.T));
  const double over = (X - y.R) / y.K;
  Scalar r;
  const double eq = over > 0 ? pre * std::pow(over, kP.N) : 0.0;
  r.S = 3 * kG * (e - sg * eq);
  if (eq > 0) {
    const double q = eq / kP.eps0;
    const double ssat = kP.s0 * std::pow(q, 1 / kP.N), bsat = kP.b0 * std::pow(q, 1 / kP.n_b);
    const double Rsat = kP.r0 * std::pow(q, 1 / kP.n_R);
    const double Ksat = (ssat - bsat - Rsat) / std::pow(eq / pre, 1 / kP.N);
    r.b = kP.A1 * eq * (sg - y.b / bsat);
    if (y.R < Rsat) r.R = kP.A3 * eq * (1 - y.R / Rsat);
    if (y.K < Ksat) r.K = kP.A5 * eq * (1 - y.K / Ksat);
  }
  return r;
}
// Classical RK4 with a fixed step h (stable: h * stiffness <= ~0.1 here).
Scalar rk4(Scalar y, double e, double T, double h) {
  auto add = [](const Scalar& a, double c, const Scalar& r) {
    return Scalar{a.S + c * r.S, a.b + c * r.b, a.R + c * r.R, a.K + c * r.K};
  };
  const long n = std::lround(T / h);
  for (long k = 0; k < n; ++k) {
    const Scalar k1 = rates(y, e), k2 = rates(add(y, h / 2, k1), e), k3 = rates(add(y, h / 2, k2), e),
                 k4 = rates(add(y, h, k3), e);
    y.S += h / 6 * (k1.S + 2 * k2.S + 2 * k3.S + k4.S);
    y.b += h / 6 * (k1.b + 2 * k2.b + 2 * k3.b + k4.b);
    y.R += h / 6 * (k1.R + 2 * k2.R + 2 * k3.R + k4.R);
    y.K += h / 6 * (k1.K + 2 * k2.K + 2 * k3.K + k4.K);
  }
  return y;
}

M3 extension(double e, double t) {
  const double l = std::exp(e * t);
  return Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal();
}

TEST(ModelViscoPlasticSuvic, ConstantRateExtensionMatchesOfflineOdeAndIsRateDependent) {
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params());
  ASSERT_TRUE(m);
  double final_S[2];
  const double erates[2] = {1e-4, 1e-3};
  for (int c = 0; c < 2; ++c) {
    const double e = erates[c], T = 1e-2 / e, dt = T / 400;  // 1% strain in 400 steps
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    Scalar ref{0, 0, kP.R0, kP.K0};
    double max_err = 0, scale = 0;
    for (int k = 1; k <= 400; ++k) {
      ASSERT_EQ(test::step_point(*m, kRho0, s, extension(e, k * dt), dt), -1);
      if (k % 40) continue;
      ref = rk4(ref, e, 40 * dt, 40 * dt / 20000);
      const double S = s.stress(0, 0) - s.stress(1, 1);  // = S (m11 - m22 = 1)
      max_err = std::max(max_err, std::abs(S - ref.S));
      scale = std::max(scale, std::abs(ref.S));
      EXPECT_NEAR(s.history[1][0], ref.R, 1e-6 * std::abs(ref.R) + 1e-3) << "R at t = " << k * dt;
      EXPECT_NEAR(s.history[2][0], ref.K, 1e-6 * ref.K) << "K at t = " << k * dt;
      EXPECT_NEAR(s.history[0][0], ref.b * 2 / 3, 1e-6 * std::abs(ref.b) + 1e-3) << "beta_11 at t = " << k * dt;
    }
    EXPECT_LT(max_err / scale, 1e-7) << "rate " << e << ": " << max_err / scale;
    RecordProperty(c == 0 ? "rel_err_1e-4" : "rel_err_1e-3", testing::PrintToString(max_err / scale));
    EXPECT_GT(s.plastic_work, 0.0);
    final_S[c] = s.stress(0, 0) - s.stress(1, 1);
    // Pressure stays the hypoelastic one: the flow is deviatoric and the path isochoric.
    EXPECT_NEAR(s.stress.trace(), 0.0, 1e-6 * scale);
  }
  // Ten times the rate: a higher flow stress (saturation ~ rate^{1/4}, eq. 10.36).
  EXPECT_GT(final_S[1], 1.3 * final_S[0]);
}

TEST(ModelViscoPlasticSuvic, SteadyStateIsTheSaturationStress) {
  // At a constant inelastic rate e all internal variables saturate (10.33-10.35 = 0):
  // beta_eff = beta_sat, R = R_sat, K = K_sat, so X_ae = R_sat + K_sat (e/pre)^{1/N}
  // = sigma_sat - beta_sat and the effective stress sqrt(3/2 s:s) = X_ae + beta_sat
  //   = sigma_sat = s0 (e/eps0)^{1/N}                                      (eq. 10.36).
  // Rate 1e-3/s: relaxation times ~ K_sat/(A5 e) = 9 s, R_sat/(A3 e) = 5 s; run 100 s.
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params());
  const double e = 1e-3, dt = 0.05;
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int k = 1; k <= 2000; ++k) ASSERT_EQ(test::step_point(*m, kRho0, s, extension(e, k * dt), dt), -1);
  const M3 sd = s.stress - s.stress.trace() / 3 * M3::Identity();
  const double q = e / kP.eps0, pre = kP.A * std::exp(-kP.Q / (kP.Rg * kP.T));
  const double ssat = kP.s0 * std::pow(q, 0.25), bsat = kP.b0 * std::pow(q, 0.25), Rsat = kP.r0 * std::pow(q, 0.25);
  EXPECT_NEAR(std::sqrt(1.5 * sd.squaredNorm()), ssat, 1e-3 * ssat);
  RecordProperty("sigma_eff_over_sigma_sat", testing::PrintToString(std::sqrt(1.5 * sd.squaredNorm()) / ssat));
  EXPECT_NEAR(s.history[1][0], Rsat, 1e-3 * Rsat);
  EXPECT_NEAR(s.history[2][0], (ssat - bsat - Rsat) / std::pow(e / pre, 0.25), 1e-3 * ssat);
  M3 beta;
  for (int i = 0; i < 9; ++i) beta(i / 3, i % 3) = s.history[0][i];
  EXPECT_NEAR(std::sqrt(1.5 * beta.squaredNorm()), bsat, 1e-3 * bsat);
  // Heating (Vaango's): dT/dt = 0.9 sigma_eq eps_dot_eq/(rho c_p); at steady state the whole
  // imposed rate is inelastic (eps_dot_eq = e) and sigma_eq = sigma_sat, rho = rho0 (isochoric).
  const double heat = 0.9 * ssat * e / (kRho0 * kCp);
  EXPECT_NEAR(s.heating, heat, 2e-3 * heat);
  RecordProperty("heating_over_closed_form", testing::PrintToString(s.heating / heat));
}

TEST(ModelViscoPlasticSuvic, BelowTheYieldStressItIsHypoElastic) {
  // R_0 = 1 GPa: X_ae < R on the whole path, eps_eq = 0 (eq. 10.29), so the stress is
  // hypo_elastic's (the same unrotated-frame update, VT eq. 4.2) and nothing evolves.
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", params({{"initial_yield", 1e9}}));
  test::MapModelParameters he({{"G", kG}, {"K", kK}});
  const ConstitutiveModelP h = create_constitutive_model("hypo_elastic", he);
  auto path = [](double a) { M3 F = M3::Identity(); F(0, 1) = 0.01 * a; F(2, 2) = 1 - 0.005 * a; return F; };
  const test::PointState sm = test::drive_path(*m, kRho0, path, 10), sh = test::drive_path(*h, kRho0, path, 10);
  EXPECT_LE((sm.stress - sh.stress).norm(), 1e-12 * sh.stress.norm());
  EXPECT_EQ(sm.history[1][0], 1e9);
  EXPECT_EQ(sm.history[2][0], kP.K0);
  EXPECT_EQ(sm.plastic_work, 0.0);
}

TEST(ModelViscoPlasticSuvic, Parameters) {
  test::MapModelParameters p({{"shear_modulus", kG}, {"bulk_modulus", kK}});
  EXPECT_THROW(create_constitutive_model("visco_plastic", p), std::invalid_argument);  // no <specific_heat>
  p.enclosing = {{"specific_heat", kCp}};
  EXPECT_THROW(create_constitutive_model("visco_plastic", p), std::invalid_argument);  // no flow block
  p.add_block("viscoplastic_flow_model", "suvic_ii");
  EXPECT_THROW(create_constitutive_model("visco_plastic", p), std::logic_error);  // MissingFeature
  test::MapModelParameters q = params({{"initial_drag", 0.0}});
  EXPECT_THROW(create_constitutive_model("visco_plastic", q), std::invalid_argument);
  test::MapModelParameters r = params();
  r.add_block("equation_of_state", "mie_gruneisen");
  EXPECT_THROW(create_constitutive_model("visco_plastic", r), std::logic_error);
  test::MapModelParameters ok = params();
  ok.add_block("equation_of_state", "default_hypo", {{"bulk_modulus", kK}});
  const ConstitutiveModelP m = create_constitutive_model("visco_plastic", ok);
  ASSERT_TRUE(m);
  // backstress, yield, drag, plasticStrain, localized, varf, lastTemperature (alpha = 1e-5 by default)
  ASSERT_EQ(m->history().size(), 7u);
  EXPECT_EQ(m->history()[4].name, "localized");
  EXPECT_EQ(m->history()[2].name, "drag");
  EXPECT_EQ(m->history()[2].initial[0], 0.05e6);
}

}  // namespace
}  // namespace tephra
