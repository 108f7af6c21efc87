// Damage models (VT ch. 15) and the Gaussian initial fields (ch. 12, 15):
// the Johnson-Cook fracture strain of 4340 steel against the inventory's
// table, the Hancock-MacKenzie h_D values, the damage accumulated along a
// constant-triaxiality path of the composed models, and the sample mean and
// standard deviation of the seeded initial porosity/damage.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "models/plasticity/YieldCondition.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/MetalFailure.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

// A stress of triaxiality sigma* = tr(sigma)/(3 sigma_eff): uniaxial tension (1/3),
// compression (-1/3), pure shear (0); equal triaxial tension plus shear for sigma* = 1.
Eigen::Matrix3d stress_with_triaxiality(double sstar) {
  if (sstar == 0.0) {
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    s(0, 1) = s(1, 0) = 1e8;
    return s;
  }
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  if (std::abs(std::abs(sstar) - 1.0 / 3.0) < 1e-15) {
    s(0, 0) = sstar > 0 ? 1e8 : -1e8;
    return s;
  }
  // sigma = m I + diag(2, -1, -1) t: sigma_eff = 3 t, tr = 3 m -> sigma* = m/(3 t).
  const double t = 1e8;
  s = (3.0 * sstar * t) * Eigen::Matrix3d::Identity();
  s(0, 0) += 2 * t;
  s(1, 1) -= t;
  s(2, 2) -= t;
  return s;
}

// Inventory ch. 15 [DERIVED] eps_f for 4340 (Table 26.1: D1 0.05, D2 3.44, D3 -2.12,
// D4 0.002, D5 0.61; T_0 = 294 K, T_m = 1793 K, eps_dot_0 = 1/s):
//   eps_f = [D1 + D2 exp(D3 sigma*)][1 + D4 ln eps_dot*][1 + D5 T*]   (VT eq. 15.3-15.6).
// D_dot = eps_dot_p/eps_f, so eps_f = eps_dot_p / D_dot.
TEST(Damage, JohnsonCookFractureStrainOf4340AgainstTheInventoryTable) {
  MapModelParameters p({{"D1", 0.05}, {"D2", 3.44}, {"D3", -2.12}, {"D4", 0.002}, {"D5", 0.61}});
  SubModelContext ctx;
  ctx.room_temperature = 294.0;
  ctx.melt_temperature = 1793.0;
  const auto jc = create_damage_model("johnson_cook", p, ctx);
  ASSERT_TRUE(jc);
  struct Row {
    double sstar, rate, T, eps_f;
  };
  const Row rows[] = {{0.0, 1.0, 294.0, 3.490000},
                      {1.0 / 3.0, 1.0, 294.0, 1.746903},
                      {-1.0 / 3.0, 1.0, 294.0, 7.023646},
                      {1.0 / 3.0, 1e3, 294.0, 1.771037},
                      {1.0 / 3.0, 1.0, 600.0, 1.964433}};
  for (const Row& r : rows) {
    PlasticState s;
    s.eps_p_rate = r.rate;
    s.temperature = r.T;
    const double Ddot = jc->damage_rate(stress_with_triaxiality(r.sstar), s);
    EXPECT_NEAR(r.rate / Ddot, r.eps_f, 5e-7) << "sigma* " << r.sstar << " rate " << r.rate << " T " << r.T;
  }
  EXPECT_EQ(jc->critical_damage(), 1.0);
}

// Inventory ch. 15 [DERIVED]: h_D = D_dot/eps_dot_p = exp(3 sigma*/2)/1.65 (VT eq. 15.1-15.2)
// = 0.606061 (sigma* = 0), 0.999225 (1/3), 2.716175 (1).
TEST(Damage, HancockMacKenzieRateAgainstTheInventoryValues) {
  MapModelParameters p({{"D0", 0.05}, {"Dc", 3.44}});
  const auto hm = create_damage_model("hancock_mackenzie", p);
  ASSERT_TRUE(hm);
  EXPECT_EQ(hm->initial_damage(), 0.05);
  EXPECT_EQ(hm->critical_damage(), 3.44);
  PlasticState s;
  s.eps_p_rate = 2.0;
  const double rows[3][2] = {{0.0, 0.606061}, {1.0 / 3.0, 0.999225}, {1.0, 2.716175}};
  for (const auto& r : rows) {
    const Eigen::Matrix3d sig = stress_with_triaxiality(r[0]);
    EXPECT_NEAR(sig.trace() / (3.0 * von_mises_stress(sig)), r[0], 1e-14);
    EXPECT_NEAR(hm->damage_rate(sig, s) / 2.0, r[1], 5e-7) << "sigma* " << r[0];
  }
}

// The composed models along isochoric plane strain F = diag(e^e, 1, e^-e): J = 1, so the
// mean stress is 0 (default_hypo) and sigma* = 0 at every step; isothermal at T = T_0 and
// eps_dot_p < eps_dot_0 = 1/s. The explicit update D += dt D_dot = Delta eps_p h_D then gives
// exactly D = D0 + eps_p/eps_f with eps_f = D1 + D2 = 3.49 (JC) and h_D = 1/1.65 (HM).
TEST(Damage, ComposedModelsAccumulateDamageAlongAConstantTriaxialityPath) {
  for (const char* type : {"elastic_plastic", "elastic_plastic_hp"})
    for (const char* law : {"johnson_cook", "hancock_mackenzie"}) {
      MapModelParameters p({{"bulk_modulus", 173.3e9}, {"shear_modulus", 80e9}, {"isothermal", 1.0},
                            {"coeff_thermal_expansion", 0.0}, {"check_max_stress_failure", 0.0},
                            {"check_TEPLA_failure_criterion", 0.0}, {"evolve_porosity", 0.0}});
      if (std::string(type) == "elastic_plastic_hp") p.values.erase("coeff_thermal_expansion");
      p.add_block("yield_condition", "von_mises");
      p.add_block("flow_model", "linear", {{"sigma_0", 792e6}, {"K", 510e6}});
      const bool jc = std::string(law) == "johnson_cook";
      if (jc) p.add_block("damage_model", law, {{"D1", 0.05}, {"D2", 3.44}, {"D3", -2.12}, {"D4", 0.002}, {"D5", 0.61}});
      else p.add_block("damage_model", law, {{"D0", 0.05}, {"Dc", 3.44}});
      p.enclosing = {{"melt_temp", 1793.0}, {"room_temp", 294.0}, {"specific_heat", 477.0}, {"density", 7830.0}};
      const auto m = create_constitutive_model(type, p);
      ASSERT_TRUE(m) << type;
      test::PointState s(*m);
      s.temperature = 294.0;
      int kD = -1, kEp = -1;
      for (int k = 0; k < int(m->history().size()); ++k) {
        if (m->history()[k].name == "damage") kD = k;
        if (k == 0) kEp = k;
      }
      ASSERT_GE(kD, 0);
      for (int k = 1; k <= 100; ++k) {
        Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
        F(0, 0) = std::exp(1e-3 * k);
        F(2, 2) = std::exp(-1e-3 * k);
        ASSERT_EQ(test::step_point(*m, 7830.0, s, F, 1.0), -1);  // dt = 1 s: eps_dot_p < 1/s
      }
      const double ep = s.history[kEp][0];
      EXPECT_GT(ep, 0.1);  // well into the plastic range (yield at e ~ 2.9e-3)
      const double expect = jc ? ep / 3.49 : 0.05 + ep / 1.65;
      EXPECT_NEAR(s.history[kD][0], expect, 1e-12) << type << " " << law;
    }
}

// Gaussian initial fields: sample mean and standard deviation of N draws are within
// 4 standard errors of the requested values (se(mean) = std/sqrt(N), se(std) ~ std/sqrt(2N));
// the draws are a pure function of (seed, index).
TEST(Damage, GaussianInitialFieldsHaveTheRequestedMeanAndStd) {
  MetalFailureParams f;
  f.gauss_porosity = f.gauss_damage = true;
  f.initial_porosity = 0.005;  // inventory ch. 12 tags: mean 0.005, std 0.001
  f.std_porosity = 0.001;
  f.mean_damage = 0.005;       // inventory ch. 15 tags
  f.std_damage = 0.001;
  f.porosity_seed = 7;
  f.damage_seed = 11;
  const int N = 40000;
  double sp = 0, sp2 = 0, sd = 0, sd2 = 0, cross = 0;
  for (int i = 0; i < N; ++i) {
    double phi = -1, D = -1;
    draw_initial_fields(f, i, phi, D);
    double phi2 = -1, D2 = -1;
    draw_initial_fields(f, i, phi2, D2);
    ASSERT_EQ(phi, phi2);  // deterministic
    sp += phi, sp2 += phi * phi, sd += D, sd2 += D * D, cross += (phi - 0.005) * (D - 0.005);
  }
  const double mp = sp / N, md = sd / N;
  const double vp = sp2 / N - mp * mp, vd = sd2 / N - md * md;
  EXPECT_NEAR(mp, 0.005, 4 * 0.001 / std::sqrt(N));
  EXPECT_NEAR(md, 0.005, 4 * 0.001 / std::sqrt(N));
  EXPECT_NEAR(std::sqrt(vp), 0.001, 4 * 0.001 / std::sqrt(2.0 * N));
  EXPECT_NEAR(std::sqrt(vd), 0.001, 4 * 0.001 / std::sqrt(2.0 * N));
  // Independent streams for porosity and damage: correlation within 4/sqrt(N).
  EXPECT_NEAR(cross / N / 1e-6, 0.0, 4.0 / std::sqrt(N));
  // Different seed: different values.
  MetalFailureParams g = f;
  g.porosity_seed = 8;
  double a = 0, b = 0, D = 0;
  draw_initial_fields(f, 3, a, D);
  draw_initial_fields(g, 3, b, D);
  EXPECT_NE(a, b);
  // Constant distributions leave the values alone.
  MetalFailureParams c;
  double phi = 0.25, dmg = 0.5;
  draw_initial_fields(c, 5, phi, dmg);
  EXPECT_EQ(phi, 0.25);
  EXPECT_EQ(dmg, 0.5);
}

}  // namespace
}  // namespace tephra
