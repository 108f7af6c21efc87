// Every registered flow-stress model (VT ch. 10) composed into both metal models,
// elastic_plastic (VT ch. 18) and elastic_plastic_hp (VT ch. 17).
//
// Path: an isochoric stretch F = diag(l, l^-1/2, l^-1/2), l = exp(eps_dot t), eps_dot =
// 4000 /s, from T = 296 K, isothermal, constant shear modulus mu = 46 GPa, constant T_m.
// The deviator stays along diag(1, -1/2, -1/2) and J = 1 (rho = rho_0, p = 0 up to
// round-off; ~100 Pa from the midpoint kinematics), so after yield every step is a J2 return and the identity to check is the
// consistency condition of the return (VT 18.56 / 17.79 at convergence):
//   q = sqrt(3/2)|s| = sigma_y(eps_p, eps_p_dot = Delta eps_p/dt, T, mu, rho, T_m[, sigma_e])
// with the flow law evaluated at the point's own returned state (the laws themselves are
// checked against closed forms in test_submodel_oracles), and the flow rule
//   Delta eps_p = (q_trial - q)/(3 mu),  q_trial = q_n + 3 mu Delta e  (Delta e = eps_dot dt, uniaxial
//   isochoric: the equivalent strain increment), so eps_p -> eps - q/(3 mu) after yield.
// MTS carries its structure stress sigma_e as history in both models (it grows with eps_p).
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "models/plasticity/FlowStressModel.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/ElasticPlastic.h"
#include "models/solid/ElasticPlasticHP.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kRho = 8930.0, kMu = 46e9, kK = 129e9, kT = 296.0, kTm = 1356.0, kRate = 4000.0;

// Copper constants of the decks (A4 and its Vaango sisters adiCu{MTS,PTW,SCG,ZA}4000s696K.ups;
// ZA polymer: the oracle set of test_submodel_oracles).
const std::map<std::string, std::map<std::string, double>>& flow_constants() {
  static const std::map<std::string, std::map<std::string, double>> t = {
      {"linear", {{"sigma_0", 70e6}, {"K", 2e8}}},
      {"johnson_cook", {{"A", 90e6}, {"B", 292e6}, {"C", 0.025}, {"n", 0.31}, {"m", 1.09}}},
      {"mechanical_threshold_stress",
       {{"sigma_a", 40e6}, {"mu_0", 47.7e9}, {"D", 3.0e9}, {"T_0", 180}, {"koverbcubed", 0.823e6}, {"g_0i", 0},
        {"g_0e", 1.6}, {"edot_0i", 0}, {"edot_0e", 1e7}, {"p_i", 0}, {"q_i", 0}, {"p_e", 0.667}, {"q_e", 1},
        {"sigma_i", 0}, {"a_0", 2390e6}, {"a_1", 12e6}, {"a_2", 1.696e6}, {"a_3", 0}, {"theta_IV", 0}, {"alpha", 2},
        {"edot_es0", 1e7}, {"g_0es", 0.2625}, {"sigma_es0", 770e6}}},
      {"preston_tonks_wallace",
       {{"theta", 0.025}, {"p", 2.0}, {"s0", 0.0085}, {"sinf", 0.00055}, {"kappa", 0.11}, {"gamma", 1e-5},
        {"y0", 1e-4}, {"yinf", 1e-4}, {"y1", 0.094}, {"y2", 0.575}, {"beta", 0.25}, {"M", 63.54}}},
      {"steinberg_cochran_guinan",
       {{"mu_0", 47.7e9}, {"sigma_0", 0.125e9}, {"Y_max", 0.64e9}, {"beta", 36}, {"n", 0.45}, {"A", 28.0e-12},
        {"B", 0.92e-3}, {"T_m0", 1790.0}, {"Gamma_0", 1.99}, {"a", 1.5}, {"epsilon_p0", 0.0}, {"C1", 0.71e6},
        {"C2", 0.012e6}, {"energy_to_form_kink_pair", 0.31}, {"Boltzmann_constant", 8.617385e-5},
        {"Peierls_stress", 0.5e8}}},
      {"zerilli_armstrong",
       {{"sigma_g", 46.5e6}, {"k_H", 5.0e6}, {"sqrt_l_inv", 3.7}, {"B", 0.0}, {"beta_0", 0.0}, {"beta_1", 0.0},
        {"B_0", 890.0e6}, {"alpha_0", 0.0028}, {"alpha_1", 0.000115}, {"K", 0.0}, {"n", 0.0}}},
      {"zerilli_armstrong_polymer",
       {{"sigma_g", 46.5e6}, {"B_pa", 5e6}, {"B_pb", 1e-3}, {"B_pn", 1}, {"beta_0", 0.5}, {"beta_1", 0.01},
        {"T_0", 300}, {"B_0pa", 890e6}, {"B_0pb", 1e-3}, {"B_0pn", 1}, {"omega_a", 1}, {"omega_b", 0.05},
        {"omega_p", 1e-4}}},
  };
  return t;
}

MapModelParameters parameters(const std::string& flow) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kMu}, {"isothermal", 1.0},
                        {"coeff_thermal_expansion", 0.0}, {"tolerance", 1e-12}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", flow, flow_constants().at(flow));
  p.enclosing = {{"melt_temp", kTm}, {"specific_heat", 414.0}, {"density", kRho}};
  return p;
}

double von_mises(const Eigen::Matrix3d& s) {
  const Eigen::Matrix3d d = s - (s.trace() / 3.0) * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * d.squaredNorm());
}

TEST(FlowComposition, EveryRegisteredFlowModelReturnsOntoItsLawInBothMetalModels) {
  ASSERT_EQ(flow_stress_models().size(), flow_constants().size());  // a new flow model must add a row
  for (const auto& entry : flow_stress_models()) {
    for (const std::string type : {"elastic_plastic", "elastic_plastic_hp"}) {
      SCOPED_TRACE(entry.name + " in " + type);
      const auto m = create_constitutive_model(type, parameters(entry.name));
      ASSERT_TRUE(m);
      const FlowStressModel& flow = type == "elastic_plastic" ? *static_cast<const ElasticPlastic&>(*m).flow_
                                                              : *static_cast<const ElasticPlasticHP&>(*m).flow_;
      const bool mts = entry.name == "mechanical_threshold_stress";
      int k_se = -1;
      const auto h = m->history();
      for (std::size_t k = 0; k < h.size(); ++k)
        if (h[k].name == "mtsStructureStress") k_se = static_cast<int>(k);
      EXPECT_EQ(k_se >= 0, mts);
      test::PointState s(*m);
      s.temperature = kT;
      const int n = 200;
      const double dt = 0.2 / kRate / n;
      double worst_law = 0, worst_flow = 0, q_prev = 0, ep_prev = 0, se_prev = 0, p_prev = 0;
      int plastic = 0;
      for (int k = 1; k <= n; ++k) {
        const double l = std::exp(kRate * dt * k);
        const Eigen::Matrix3d F = Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal();
        ASSERT_EQ(test::step_point(*m, kRho, s, F, dt), -1) << "step " << k;
        const double q = von_mises(s.stress), ep = s.history[0][0], rate = s.history[1][0];
        const double dg = ep - ep_prev;
        if (dg > 0) {
          ++plastic;
          PlasticState st;
          st.eps_p = ep;
          st.eps_p_rate = rate;
          st.temperature = kT;
          st.melt_temperature = kTm;
          st.density = st.density0 = kRho;
          // p̄ (ZA polymer reads it): elastic_plastic takes the moduli state at t_n (VT §18.2),
          // elastic_plastic_hp the EOS pressure of the step (VT ch. 17).
          st.pressure = type == "elastic_plastic" ? -p_prev : -s.stress.trace() / 3.0;
          st.shear_modulus = kMu;
          if (mts) {
            st.sigma_e = s.history[k_se][0];
            EXPECT_GE(st.sigma_e, se_prev);
            se_prev = st.sigma_e;
          }
          worst_law = std::max(worst_law, std::abs(q / flow.evaluate(st).sigma_y - 1.0));
          // Flow rule: q_trial = q_n + 3 mu Delta e with Delta e the equivalent (= axial) log-strain increment.
          const double q_trial = q_prev + 3.0 * kMu * kRate * dt;
          worst_flow = std::max(worst_flow, std::abs(dg - (q_trial - q) / (3.0 * kMu)) / (kRate * dt));
        }
        q_prev = q;
        ep_prev = ep;
        p_prev = s.stress.trace() / 3.0;
      }
      std::printf("%-28s %-19s plastic steps %3d, max |q/sigma_y - 1| %.2e, max flow-rule error %.2e (of the "
                  "step's strain), eps_p %.4f, q %.4e%s\n",
                  entry.name.c_str(), type.c_str(), plastic, worst_law, worst_flow, ep_prev, q_prev,
                  mts ? (", sigma_e " + std::to_string(se_prev)).c_str() : "");
      EXPECT_GT(plastic, 150);
      EXPECT_LT(worst_law, 1e-9);   // the return tolerance is 1e-12 of q_trial
      EXPECT_LT(worst_flow, 1e-6);  // midpoint kinematics: O(Delta e^2) of the step's log strain
      if (mts) EXPECT_GT(se_prev, 1e8);
    }
  }
}

}  // namespace
}  // namespace tephra
