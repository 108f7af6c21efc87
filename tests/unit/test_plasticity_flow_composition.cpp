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
#include "tests/support/FlowSamples.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kRho = 8930.0, kMu = 46e9, kK = 129e9, kT = 296.0, kTm = 1356.0, kRate = 4000.0;

using test::flow_constants;  // tests/support/FlowSamples.h

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
