#pragma once
// Sample constants of every registered flow-stress model (VT ch. 10), shared by
// tests/unit/test_plasticity_flow_composition.cpp (each law composed into both metal models)
// and tests/bench/bench_stress_update.cpp (the cost of each law's return).
#include <map>
#include <string>

namespace tephra::test {

// Copper constants of the decks (A4 and its Vaango sisters adiCu{MTS,PTW,SCG,ZA}4000s696K.ups;
// ZA polymer: the oracle set of test_submodel_oracles).
inline const std::map<std::string, std::map<std::string, double>>& flow_constants() {
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

}  // namespace tephra::test
