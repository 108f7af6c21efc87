// Specific-heat sub-models, VT ch. 14. The constants the manual leaves out
// (copper_Cp, steel_Cp: inventory "gap") are Vaango's defaults (CopperCp.cc,
// SteelCp.cc), each overridable by its schema tag.
#include <cmath>

#include "models/plasticity/ThermalModels.h"

namespace tephra {
namespace {

// constant_Cp: the material's <specific_heat>.
class ConstantCp final : public SpecificHeatModel {
 public:
  explicit ConstantCp(double cp) : cp_(cp) {}
  std::string type() const override { return "constant_Cp"; }
  double specific_heat(const PlasticState&) const override { return cp_; }
  double cp_;
};

// copper_Cp, eq. 14.2: C_p = A_0 T³ - B_0 T² + C_0 T - D_0 for T < T_0, A_1 T + B_1 above.
class CopperCp final : public SpecificHeatModel {
 public:
  double T0, A0, B0, C0, D0, A1, B1;
  std::string type() const override { return "copper_Cp"; }
  double specific_heat(const PlasticState& s) const override {
    const double T = s.temperature;
    return T < T0 ? ((A0 * T - B0) * T + C0) * T - D0 : A1 * T + B1;
  }
};

// steel_Cp, eq. 14.3-14.4 (critical-exponent form about the Curie point T_c):
//   T < T_c: C_p = A_0 - B_0 t + C_0 t^{-n_0},  t = 1 - T/T_c
//   T > T_c: C_p = A_1 + B_1 t + C_1 t^{-n_1},  t = T/T_c - 1
// At T = T_c exactly (singular) the value at T_c - 1 K is used, as Vaango does.
class SteelCp final : public SpecificHeatModel {
 public:
  double Tc, A0, B0, C0, n0, A1, B1, C1, n1;
  std::string type() const override { return "steel_Cp"; }
  double specific_heat(const PlasticState& s) const override {
    double T = s.temperature;
    if (T == Tc) T -= 1.0;
    if (T < Tc) {
      const double t = 1.0 - T / Tc;
      return A0 - B0 * t + C0 / std::pow(t, n0);
    }
    const double t = T / Tc - 1.0;
    return A1 + B1 * t + C1 / std::pow(t, n1);
  }
};

// cubic_Cp (Sewell and Menikoff 2003, Vaango CubicCp): with the reduced
// temperature τ = T/θ_D(ρ), θ_D = η^a exp(b(η - 1)),
//   C_v = τ³/(c_0 + c_1 τ + c_2 τ² + c_3 τ³).
// The thermal-expansion correction β² T K_T/ρ (<beta> != 0) is not implemented.
class CubicCp final : public SpecificHeatModel {
 public:
  double a, b, c0, c1, c2, c3;
  std::string type() const override { return "cubic_Cp"; }
  double specific_heat(const PlasticState& s) const override {
    const double eta = s.eta();
    const double tau = s.temperature / (std::pow(eta, a) * std::exp(b * (eta - 1.0)));
    const double t3 = tau * tau * tau;
    return t3 / (c0 + tau * (c1 + tau * (c2 + tau * c3)));
  }
};

std::unique_ptr<SpecificHeatModel> make_constant(const ModelParameters& p, const SubModelContext& c) {
  if (!(c.specific_heat > 0))
    p.fail("type", "constant_Cp needs the material's positive <specific_heat>");
  return std::make_unique<ConstantCp>(c.specific_heat);
}
std::unique_ptr<SpecificHeatModel> make_copper(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<CopperCp>();
  m->T0 = p.get_double("T_transition", 270.0);
  m->A0 = p.get_double("A_LowT", 0.0000416);
  m->B0 = p.get_double("B_LowT", 0.027);
  m->C0 = p.get_double("C_LowT", 6.21);
  m->D0 = p.get_double("D_LowT", 142.6);
  m->A1 = p.get_double("A_HighT", 0.1009);
  m->B1 = p.get_double("B_HighT", 358.4);
  return m;
}
std::unique_ptr<SpecificHeatModel> make_steel(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<SteelCp>();
  m->Tc = p.get_double("T_transition", 1040.0);
  m->A0 = p.get_double("A_LowT", 190.14);
  m->B0 = p.get_double("B_LowT", 273.75);
  m->C0 = p.get_double("C_LowT", 418.30);
  m->n0 = p.get_double("n_LowT", 0.2);
  m->A1 = p.get_double("A_HighT", 465.21);
  m->B1 = p.get_double("B_HighT", 267.52);
  m->C1 = p.get_double("C_HighT", 58.16);
  m->n1 = p.get_double("n_HighT", 0.35);
  if (!(m->Tc > 0)) p.fail("T_transition", "must be positive");
  return m;
}
std::unique_ptr<SpecificHeatModel> make_cubic(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<CubicCp>();
  m->a = p.get_double("a", 1.0);
  m->b = p.get_double("b", 1.0);
  if (p.get_double("beta", 0.0) != 0.0)
    p.missing_feature("beta", "cubic_Cp thermal-expansion correction (beta != 0)");
  m->c0 = p.get_double("c0");
  m->c1 = p.get_double("c1");
  m->c2 = p.get_double("c2");
  m->c3 = p.get_double("c3");
  return m;
}
}  // namespace

const std::vector<SubModelEntry<SpecificHeatModel>>& specific_heat_models() {
  static const std::vector<SubModelEntry<SpecificHeatModel>> table = {
      {"constant_Cp", {}, &make_constant},
      {"cubic_Cp", {}, &make_cubic},
      {"copper_Cp", {}, &make_copper},
      {"steel_Cp", {}, &make_steel},
  };
  return table;
}

std::unique_ptr<SpecificHeatModel> create_specific_heat_model(const std::string& key, const ModelParameters& p,
                                                              const SubModelContext& ctx) {
  const auto* e = find_sub_model(specific_heat_models(), key);
  return e ? e->create(p, ctx) : nullptr;
}

}  // namespace tephra
