// elastic_plastic and elastic_plastic_hp: <useModifiedEOS> (the MPMICE hooks of
// models/solid/ModifiedEos.h) and thermal expansion (<coeff_thermal_expansion>,
// VT eq. 17.3-17.5, 18.12), each against its closed form; the steel blocks of the
// MPMICE decks guni2dRT / SteadyBurn_2dRT (useModifiedEOS, DoThermalExpansion) build.
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/deck/DeckLoader.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/ElasticPlastic.h"
#include "models/solid/ElasticPlasticHP.h"
#include "models/solid/ModifiedEos.h"
#include "mpm/DeckModelParameters.h"
#include "tests/support/SolidModelDriver.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kK = 117e9, kG = 43.8e9, kS0 = 70e6, kRho0 = 8930.0, kPref = 101325.0;
const char* const kModels[] = {"elastic_plastic", "elastic_plastic_hp"};

MapModelParameters metal(double alpha, bool modified) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"isothermal", 1.0},
                        {"coeff_thermal_expansion", alpha}, {"useModifiedEOS", modified ? 1.0 : 0.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", kS0}, {"K", 0.0}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}, {"density", kRho0}};
  return p;
}

// default_hypo (p = K ln J, mean stress) with useModifiedEOS, gauge pressure p - p_ref at rho:
//   rho >= rho0: -K ln J = K ln(rho/rho0),          dp/drho = K/rho;
//   rho <  rho0: p_ref (rho/rho0)^{K/p_ref} - p_ref, dp/drho = (K/rho)(rho/rho0)^{K/p_ref}
// (Vaango ElasticPlasticHP::computePressEOSCM's modified branch; K/p_ref = 1.155e6).
TEST(MetalModifiedEos, PressureBothSidesOfReferenceDensity) {
  for (const char* type : kModels) {
    const auto m = create_constitutive_model(type, metal(0.0, true));
    ASSERT_TRUE(m && m->modified_eos()) << type;
    EXPECT_FALSE(create_constitutive_model(type, metal(0.0, false))->modified_eos());
    const double n = kK / kPref;
    for (const double x : {1 + 1e-3, 1 + 1e-6, 1.0, 1 - 1e-7, 1 - 1e-6, 1 - 3e-6, 0.9}) {
      const double rho = x * kRho0;
      const SolidEosPoint e = *mpmice_pressure_at_density(*m, rho, kRho0, 300.0, kPref);
      const double p = x >= 1 ? kK * std::log(x) : kPref * std::pow(x, n) - kPref;
      const double dp = x >= 1 ? kK / rho : kK / rho * std::pow(x, n);
      EXPECT_NEAR(e.pressure, p, 1e-9 * std::abs(p) + 1e-6) << type << " x " << x;
      EXPECT_NEAR(e.dp_drho, dp, 1e-9 * dp + 1e-30) << type << " x " << x;
      EXPECT_GE(e.pressure + kPref, 0.0) << type << " x " << x;  // no tension in the absolute pressure
      // The inverse hook: rho(p(rho)) = rho wherever p is invertible (p + p_ref > 0).
      if (e.pressure + kPref > 1e-3 * kPref)
        EXPECT_NEAR(*mpmice_density_at_pressure(*m, e.pressure, kRho0, 300.0, kPref), rho, 1e-11 * rho)
            << type << " x " << x;
    }
    // And p(rho(p)) = p on a pressure grid through both branches.
    for (const double pg : {1e9, 1e5, 0.0, -1e3, -5e4, -0.9 * kPref}) {
      const double rho = *mpmice_density_at_pressure(*m, pg, kRho0, 300.0, kPref);
      EXPECT_NEAR(mpmice_pressure_at_density(*m, rho, kRho0, 300.0, kPref)->pressure, pg, 1e-6 * kPref + 1e-9 * std::abs(pg))
          << type << " p " << pg;
    }
    // C^0 and C^1 at rho0: both one-sided values and slopes meet (p = 0, dp/drho = K/rho0).
    const double h = 1e-12 * kRho0;
    const SolidEosPoint lo = *mpmice_pressure_at_density(*m, kRho0 - h, kRho0, 300.0, kPref);
    const SolidEosPoint hi = *mpmice_pressure_at_density(*m, kRho0 + h, kRho0, 300.0, kPref);
    EXPECT_NEAR(lo.pressure, 0.0, 2 * kK / kRho0 * h);
    EXPECT_NEAR(hi.pressure, 0.0, 2 * kK / kRho0 * h);
    EXPECT_NEAR(lo.dp_drho / (kK / kRho0), 1.0, 1e-5);
    EXPECT_NEAR(hi.dp_drho / (kK / kRho0), 1.0, 1e-5);
    // The stress update does not change (Vaango: the flag only selects the MPMICE branch).
    const auto plain = create_constitutive_model(type, metal(0.0, false));
    test::PointState a(*m), b(*plain);
    const Eigen::Matrix3d F = Eigen::Vector3d(1.002, 1.0, 1.0).asDiagonal();
    ASSERT_EQ(test::step_point(*m, kRho0, a, F, 1e-6), -1);
    ASSERT_EQ(test::step_point(*plain, kRho0, b, F, 1e-6), -1);
    EXPECT_EQ((a.stress - b.stress).norm(), 0.0) << type;
  }
}

// With mie_gruneisen (guni2dRT's steel: C_0 = 3574 m/s, rho0 = 7830) the compression branch is
// the EOS sub-model's, K0 = rho0 dp/drho(rho0) = rho0 C_0^2, and the expansion branch uses K0:
// C^1 at rho0 with dp/drho = C_0^2 from both sides.
TEST(MetalModifiedEos, MieGruneisenBranchIsC1AtReferenceDensity) {
  const double rho0 = 7830.0, c0 = 3574.0;
  for (const char* type : kModels) {
    MapModelParameters p = metal(0.0, true);
    p.enclosing["density"] = rho0;
    p.add_block("equation_of_state", "mie_gruneisen", {{"C_0", c0}, {"Gamma_0", 1.69}, {"S_alpha", 1.92}});
    const auto m = create_constitutive_model(type, p);
    ASSERT_TRUE(m) << type;
    // One-sided at rho0 -+ h: the expansion slope is (K0/rho)(rho/rho0)^n, n = K0/p_ref = 9.9e5,
    // so h = 1e-12 rho0 leaves a 1e-6 offset from the limit C_0^2.
    const double h = 1e-12 * rho0;
    const SolidEosPoint lo = *mpmice_pressure_at_density(*m, rho0 - h, rho0, 300.0, kPref);
    const SolidEosPoint hi = *mpmice_pressure_at_density(*m, rho0 + h, rho0, 300.0, kPref);
    EXPECT_NEAR(lo.dp_drho / (c0 * c0), 1.0, 1e-5) << type;
    EXPECT_NEAR(hi.dp_drho / (c0 * c0), 1.0, 1e-5) << type;
    EXPECT_NEAR(lo.pressure, -c0 * c0 * h, 1e-4 * c0 * c0 * h) << type;
    // Expansion: p = p_ref (rho/rho0)^{rho0 C_0^2/p_ref} - p_ref.
    const double x = 1 - 2e-7;
    EXPECT_NEAR(mpmice_pressure_at_density(*m, x * rho0, rho0, 300.0, kPref)->pressure,
                kPref * std::pow(x, rho0 * c0 * c0 / kPref) - kPref, 1e-9 * kPref)
        << type;
  }
}

// Thermal expansion, the linear form of VT eq. 18.12 with default_hypo (kappa = K):
// sigma = [K ln J - 3 K alpha (T - T_0)] I + s, T_0 the point's first temperature.
//   constrained (F = I):            sigma = -3 K alpha dT I;
//   free (F = exp(alpha dT) I):     sigma = 0, the log strain alpha dT in every direction
//                                   (eq. 17.3-17.5: the mechanical strain rate d - alpha T_dot I = 0).
TEST(MetalThermalExpansion, ConstrainedAndFreeHeatingClosedForms) {
  const double alpha = 2e-5, T0 = 300.0, dT = 50.0;
  for (const char* type : kModels) {
    const auto m = create_constitutive_model(type, metal(alpha, false));
    ASSERT_TRUE(m) << type;
    test::PointState c(*m), f(*m);
    c.temperature = f.temperature = T0;
    ASSERT_EQ(test::step_point(*m, kRho0, c, Eigen::Matrix3d::Identity(), 0.0), -1);
    ASSERT_EQ(test::step_point(*m, kRho0, f, Eigen::Matrix3d::Identity(), 0.0), -1);
    EXPECT_EQ(c.stress.norm(), 0.0) << type;
    const int n = 50;
    for (int k = 1; k <= n; ++k) {
      const double T = T0 + dT * k / n;
      c.temperature = f.temperature = T;
      ASSERT_EQ(test::step_point(*m, kRho0, c, Eigen::Matrix3d::Identity(), 1e-6), -1);
      const Eigen::Matrix3d F = std::exp(alpha * (T - T0)) * Eigen::Matrix3d::Identity();
      ASSERT_EQ(test::step_point(*m, kRho0, f, F, 1e-6), -1);
      const double sig = -3 * kK * alpha * (T - T0);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(c.stress(i, i), sig, 1e-9 * std::abs(sig)) << type << " k " << k;
      EXPECT_NEAR((c.stress - c.stress(0, 0) * Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-6) << type;
      // Free: the midpoint strain increment differs from the log increment by O(h^3) per step
      // (h = alpha dT/n = 2e-5): |sigma| <= 3K n h^3 ~ 1e-3 Pa, against 3 K alpha dT = 3.5e8 Pa.
      EXPECT_LT(f.stress.norm(), 1e-8 * 3 * kK * alpha * dT) << type << " k " << k;
    }
    // Cooling back to T_0 at F = I returns to zero stress.
    c.temperature = T0;
    ASSERT_EQ(test::step_point(*m, kRho0, c, Eigen::Matrix3d::Identity(), 1e-6), -1);
    EXPECT_LT(c.stress.norm(), 1e-6) << type;
  }
}

// Heating at fixed F after yielding in uniaxial strain: the thermal pressure shifts the mean
// stress only; the deviator (on the yield surface, q = sigma_y) is unchanged.
TEST(MetalThermalExpansion, ThermalPressureLeavesTheDeviatorUnchanged) {
  const double alpha = 1e-5;
  for (const char* type : kModels) {
    const auto m = create_constitutive_model(type, metal(alpha, false));
    test::PointState s(*m);
    s.temperature = 300.0;
    for (int k = 1; k <= 20; ++k)
      ASSERT_EQ(test::step_point(*m, kRho0, s, Eigen::Vector3d(std::exp(0.004 * k / 20), 1, 1).asDiagonal().toDenseMatrix(), 1e-6), -1);
    const Eigen::Matrix3d before = s.stress;
    s.temperature = 340.0;
    ASSERT_EQ(test::step_point(*m, kRho0, s, Eigen::Vector3d(std::exp(0.004), 1, 1).asDiagonal().toDenseMatrix(), 1e-6), -1);
    const Eigen::Matrix3d d = s.stress - before;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(d(i, i), -3 * kK * alpha * 40.0, 1e-6 * 3 * kK * alpha * 40.0) << type;
  }
}

std::vector<const DeckNode*> metal_blocks(const DeckNode& n, const std::string& type) {
  std::vector<const DeckNode*> out;
  std::function<void(const DeckNode&)> walk = [&](const DeckNode& d) {
    if (d.name == "constitutive_model" && d.attribute("type").value_or("") == type) out.push_back(&d);
    for (const DeckNode& c : d.children) walk(c);
  };
  walk(n);
  return out;
}

// guni2dRT.ups (line 167, elastic_plastic_hp) and SteadyBurn_2dRT.ups (line 217, elastic_plastic):
// steel with <useModifiedEOS> true; SteadyBurn_2dRT also has <coeff_thermal_expansion> 2.5e-5
// with <MPM><DoThermalExpansion> false, so alpha = 0 (Vaango MPMFlags) and no thermal history.
TEST(MetalModifiedEos, SteelBlocksOfTheMpmiceDecksBuild) {
  const std::pair<const char*, const char*> decks[] = {{"guni2dRT.ups", "elastic_plastic_hp"},
                                                       {"SteadyBurn_2dRT.ups", "elastic_plastic"}};
  for (const auto& [name, type] : decks) {
    auto deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/" + name);
    const auto blocks = metal_blocks(deck->root, type);
    ASSERT_EQ(blocks.size(), 1u) << name;
    DeckModelParameters params(*blocks[0]);
    const ConstitutiveModelP m = create_constitutive_model(type, params);
    params.check_all_used(type);
    ASSERT_TRUE(m && m->modified_eos()) << name;
    const double alpha = std::string(type) == "elastic_plastic" ? static_cast<const ElasticPlastic&>(*m).p_.alpha
                                                                : static_cast<const ElasticPlasticHP&>(*m).p_.alpha;
    EXPECT_EQ(alpha, 0.0) << name;
    for (const HistoryVariable& h : m->history()) EXPECT_NE(h.name, "thermalReferenceTemperature") << name;
  }
}

}  // namespace
}  // namespace tephra

namespace tephra {
namespace {

// MTS flow with a porous yield (PorousReturn.h: sigma_e = sigma_e,n + theta Delta eps_p inside
// the two-invariant return). Identity: Gurson with phi = 0 (and no nucleation) is von Mises
// (VT eq. 8.9 with f = 0: Phi = q^2/sigma_y^2 - 1), so the porous return must reproduce the
// von Mises MTS return (test_model_elastic_plastic's MTS tests) along a uniaxial-strain path:
// stress, eps_p and the structure stress sigma_e agree to the returns' tolerances.
TEST(PorousYieldMts, GursonAtZeroPorosityEqualsVonMisesWithMts) {
  for (const char* type : kModels) {
    auto base = [&] {
      MapModelParameters p({{"bulk_modulus", 129e9}, {"shear_modulus", 46e9}, {"isothermal", 1.0},
                            {"coeff_thermal_expansion", 0.0}, {"tolerance", 1e-12}, {"evolve_porosity", 0.0},
                            {"evolve_damage", 0.0}, {"initial_mean_porosity", 0.0}});
      // ETP copper MTS constants (decks MaterialData/MTSPlasticETPCu.xml).
      p.add_block("flow_model", "mts_model",
                  {{"sigma_a", 40e6}, {"mu_0", 47.7e9}, {"D", 3.0e9}, {"T_0", 180}, {"koverbcubed", 0.823e6},
                   {"g_0i", 0}, {"g_0e", 1.6}, {"edot_0i", 0}, {"edot_0e", 1e7}, {"p_i", 0}, {"q_i", 0},
                   {"p_e", 0.667}, {"q_e", 1}, {"sigma_i", 0}, {"a_0", 2390e6}, {"a_1", 12e6}, {"a_2", 1.696e6},
                   {"a_3", 0}, {"theta_IV", 0}, {"alpha", 2}, {"edot_es0", 1e7}, {"g_0es", 0.2625}, {"sigma_es0", 770e6}});
      p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}, {"density", kRho0}};
      return p;
    };
    auto vm = base(), gu = base();
    vm.add_block("yield_condition", "von_mises");
    gu.add_block("yield_condition", "gurson", {{"q1", 1.5}, {"q2", 1.0}, {"q3", 2.25}, {"k", 4.0}, {"f_c", 0.05}});
    const auto a = create_constitutive_model(type, vm), b = create_constitutive_model(type, gu);
    ASSERT_TRUE(a && b) << type;
    auto column = [](const ConstitutiveModel& m, const char* name) {
      const auto h = m.history();
      for (std::size_t k = 0; k < h.size(); ++k)
        if (h[k].name == name) return int(k);
      return -1;
    };
    const int ka = column(*a, "mtsStructureStress"), kb = column(*b, "mtsStructureStress");
    ASSERT_GE(ka, 0);
    ASSERT_GE(kb, 0);
    test::PointState sa(*a), sb(*b);
    sa.temperature = sb.temperature = 300.0;
    const int n = 100;
    for (int k = 1; k <= n; ++k) {
      const Eigen::Matrix3d F = Eigen::Vector3d(std::exp(-0.05 * k / n), 1, 1).asDiagonal();
      ASSERT_EQ(test::step_point(*a, kRho0, sa, F, 1e-5), -1) << type;
      ASSERT_EQ(test::step_point(*b, kRho0, sb, F, 1e-5), -1) << type;
      EXPECT_NEAR((sa.stress - sb.stress).norm(), 0.0, 1e-8 * sa.stress.norm()) << type << " k " << k;
      EXPECT_NEAR(sa.history[0][0], sb.history[0][0], 1e-9) << type << " k " << k;
      EXPECT_NEAR(sa.history[ka][0], sb.history[kb][0], 1e-7 * std::abs(sa.history[ka][0]) + 1.0) << type << " k " << k;
    }
    EXPECT_GT(sb.history[kb][0], 1e7) << type;  // sigma_e evolved (tens of MPa at 4 % plastic strain)
  }
}

}  // namespace
}  // namespace tephra
