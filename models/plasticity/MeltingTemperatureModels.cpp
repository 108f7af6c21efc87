// Melting-temperature sub-models, VT ch. 13. η = ρ/ρ_0, p̄ = PlasticState::pressure.
#include <cmath>

#include "models/plasticity/ThermalModels.h"

namespace tephra {
namespace {

// constant_Tm: T_m = <T_m0>, or the material's <melt_temp> (ConstantTm.xml has no child).
class ConstantTm final : public MeltingTemperatureModel {
 public:
  explicit ConstantTm(double Tm) : Tm_(Tm) {}
  std::string type() const override { return "constant_Tm"; }
  double melt_temperature(const PlasticState&) const override { return Tm_; }
  double Tm_;
};

// linear_Tm (named only in VT ch. 13; forms of Vaango's LinearMeltTemp):
//   pressure form  T_m = T_m0 + b p̄         (<b>, or b = a T_m0/K_T when <a> and <K_T> are given)
//   volume form    T_m = T_m0 (1 + a ρ_0/ρ) (<a>, or a = 2(Γ_0 - 1/3) from <Gamma_0>, Lindemann)
class LinearTm final : public MeltingTemperatureModel {
 public:
  double Tm0 = 0, a = 0, b = 0;
  bool pressure_form = false;
  std::string type() const override { return "linear_Tm"; }
  double melt_temperature(const PlasticState& s) const override {
    return pressure_form ? Tm0 + b * s.pressure : Tm0 * (1.0 + a / s.eta());
  }
};

// scg_Tm, eq. 13.1: T_m = T_m0 exp[2a(1 - 1/η)] η^{2(Γ_0 - a - 1/3)}.
class ScgTm final : public MeltingTemperatureModel {
 public:
  double Tm0, Gamma0, a;
  std::string type() const override { return "scg_Tm"; }
  double melt_temperature(const PlasticState& s) const override {
    const double eta = s.eta();
    return Tm0 * std::exp(2.0 * a * (1.0 - 1.0 / eta)) * std::pow(eta, 2.0 * (Gamma0 - a - 1.0 / 3.0));
  }
};

// bps_Tm (Burakovsky-Preston-Silbar), eq. 13.2-13.3:
//   T_m(p̄) = T_m(0) [1/η + (μ_0'/μ_0) p̄/η^{4/3}],  η = (1 + K_0' p̄/K_0)^{1/K_0'},
//   T_m(0) = κ λ μ_0 v_WS/(8π ln(z - 1) k_b) ln(α²/(4 b²ρ_c(T_m))),  v_WS = f a³.
// Erratum resolved: the manual's a = 3.6147e-9 is copper's lattice constant
// 3.6147e-10 m (inventory ch. 13); the value is taken as given, in metres.
// Tags: B0 = K_0, dB_dp0 = K_0', G0 = μ_0, dG_dp0 = μ_0', b2rhoTm = b²ρ_c(T_m),
// v_ws_a3_factor = f; Boltzmann_Constant defaults to CODATA's k_b.
class BpsTm final : public MeltingTemperatureModel {
 public:
  double K0, dK, mu0, dmu, Tm_zero;
  std::string type() const override { return "bps_Tm"; }
  double melt_temperature(const PlasticState& s) const override {
    const double p = s.pressure;
    const double eta = std::pow(1.0 + dK * p / K0, 1.0 / dK);
    return Tm_zero * (1.0 / eta + dmu / mu0 * p / std::pow(eta, 4.0 / 3.0));
  }
};

std::unique_ptr<MeltingTemperatureModel> make_constant(const ModelParameters& p, const SubModelContext& c) {
  const double Tm = p.has("T_m0") ? p.get_double("T_m0") : c.melt_temperature;
  if (!(Tm > 0)) p.fail("T_m0", "constant_Tm needs a positive <T_m0> (here) or <melt_temp> (in the material)");
  return std::make_unique<ConstantTm>(Tm);
}
std::unique_ptr<MeltingTemperatureModel> make_linear(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<LinearTm>();
  m->Tm0 = positive_parameter(p, "T_m0");
  if (p.has("b")) {
    m->pressure_form = true;
    m->b = p.get_double("b");
  } else if (p.has("a") && p.has("K_T")) {
    m->pressure_form = true;
    m->b = p.get_double("a") * m->Tm0 / positive_parameter(p, "K_T");
  } else if (p.has("a")) {
    m->a = p.get_double("a");
  } else if (p.has("Gamma_0")) {
    m->a = 2.0 * (p.get_double("Gamma_0") - 1.0 / 3.0);
  } else {
    p.fail("T_m0", "linear_Tm needs <b>, <a> (with optional <K_T>) or <Gamma_0>");
  }
  return m;
}
std::unique_ptr<MeltingTemperatureModel> make_scg(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<ScgTm>();
  m->Tm0 = positive_parameter(p, "T_m0");
  m->Gamma0 = p.get_double("Gamma_0");
  m->a = p.get_double("a");
  return m;
}
std::unique_ptr<MeltingTemperatureModel> make_bps(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<BpsTm>();
  m->K0 = positive_parameter(p, "B0");
  m->dK = positive_parameter(p, "dB_dp0");
  m->mu0 = positive_parameter(p, "G0");
  m->dmu = p.get_double("dG_dp0");
  const double kappa = positive_parameter(p, "kappa"), z = p.get_double("z");
  if (!(z > 2)) p.fail("z", "coordination number must exceed 2");
  const double b2rho = positive_parameter(p, "b2rhoTm"), alpha = positive_parameter(p, "alpha");
  const double lambda = positive_parameter(p, "lambda"), a = positive_parameter(p, "a");
  const double f = positive_parameter(p, "v_ws_a3_factor");
  const double kb = p.get_double("Boltzmann_Constant", 1.380649e-23);
  const double v_ws = f * a * a * a;
  m->Tm_zero = kappa * lambda * m->mu0 * v_ws / (8.0 * M_PI * std::log(z - 1.0) * kb) *
               std::log(alpha * alpha / (4.0 * b2rho));
  return m;
}
}  // namespace

const std::vector<SubModelEntry<MeltingTemperatureModel>>& melting_temperature_models() {
  static const std::vector<SubModelEntry<MeltingTemperatureModel>> table = {
      {"constant_Tm", {}, &make_constant},
      {"linear_Tm", {}, &make_linear},
      {"scg_Tm", {}, &make_scg},
      {"bps_Tm", {}, &make_bps},
  };
  return table;
}

std::unique_ptr<MeltingTemperatureModel> create_melting_temperature_model(const std::string& key,
                                                                          const ModelParameters& p,
                                                                          const SubModelContext& ctx) {
  const auto* e = find_sub_model(melting_temperature_models(), key);
  return e ? e->create(p, ctx) : nullptr;
}

}  // namespace tephra
