// Shear-modulus sub-models, VT ch. 7. p̄ = PlasticState::pressure (compression +).
#include <cmath>

#include "models/plasticity/ThermalModels.h"

namespace tephra {
namespace {

// constant_shear: μ = <shear_modulus>, or the enclosing model's <shear_modulus>
// (MaterialData/ConstantShear.xml has no child; Vaango passes the parent's value).
class ConstantShear final : public ShearModulusModel {
 public:
  explicit ConstantShear(double mu) : mu_(mu) {}
  std::string type() const override { return "constant_shear"; }
  double shear_modulus(const PlasticState&) const override { return mu_; }
  double mu_;
};

// mts_shear (Varshni), eq. 7.5: μ(T) = μ_0 - D/(exp(T_0/T) - 1).
class MtsShear final : public ShearModulusModel {
 public:
  double mu0, D, T0;
  std::string type() const override { return "mts_shear"; }
  double shear_modulus(const PlasticState& s) const override {
    if (s.temperature <= 0) return mu0;  // T -> 0: exp(T_0/T) -> inf
    return mu0 - D / (std::exp(T0 / s.temperature) - 1.0);
  }
};

// scg_shear, eq. 7.6 with the erratum resolved as SCG (1980) and the tags:
//   μ = μ_0 [1 + A p̄/η^{1/3} - B (T - 300)],  η = ρ/ρ_0;  μ = 0 for T >= T_m.
class ScgShear final : public ShearModulusModel {
 public:
  double mu0, A, B;
  std::string type() const override { return "scg_shear"; }
  double shear_modulus(const PlasticState& s) const override {
    if (s.melt_temperature > 0 && s.temperature >= s.melt_temperature) return 0.0;
    return mu0 * (1.0 + A * s.pressure / std::cbrt(s.eta()) - B * (s.temperature - 300.0));
  }
};

// np_shear (Nadal-LePoac), eq. 7.7-7.8:
//   μ = [(μ_0 + ∂μ/∂p p̄/η^{1/3})(1 - T̂) + ρ k_b T/(C m)] / J(T̂),
//   J = 1 + exp[-(1 + 1/ζ)/(1 + ζ/(1 - T̂))],  T̂ = T/T_m ∈ [0, 1 + ζ];
// <slope_mu_p_over_mu0> is (1/μ_0) ∂μ/∂p, <m> the atomic mass in amu, so
// k_b/(m amu) = (k_b/amu)/m = 8314.46/m J/(kg K). μ = 0 beyond T̂ = 1 + ζ.
class NpShear final : public ShearModulusModel {
 public:
  double mu0, zeta, slope, C, m;
  std::string type() const override { return "np_shear"; }
  double shear_modulus(const PlasticState& s) const override {
    const double That = s.temperature / s.melt_temperature;
    if (That <= 0) return mu0;
    if (That >= 1.0 + zeta) return 0.0;
    const double J = (That >= 1.0) ? 2.0 : 1.0 + std::exp(-(1.0 + 1.0 / zeta) / (1.0 + zeta / (1.0 - That)));
    constexpr double k_over_amu = 1.380649e-23 / 1.66053906660e-27;  // CODATA 2018
    const double t1 = mu0 * (1.0 + slope * s.pressure / std::cbrt(s.eta())) * (1.0 - That);
    const double t2 = s.density * k_over_amu * s.temperature / (C * m);
    return (t1 + t2) / J;
  }
};

// ptw_shear, eq. 7.9-7.10: μ = μ_0 (1 + β p̄/η^{1/3}) (1 - α_p T/T_m), with
// β = <slope_mu_p_over_mu0> (per μ_0, as Vaango's PTWShear). <alpha> is read
// but unused (Vaango's PTWShear uses only <alphap>); the deck
// children <C>, <m>, <zeta> (MaterialData/PTWShear*.xml, copied from np_shear)
// are schema-valid and have no meaning for this model: accepted and unused.
class PtwShear final : public ShearModulusModel {
 public:
  double mu0, alphap, slope;
  std::string type() const override { return "ptw_shear"; }
  double shear_modulus(const PlasticState& s) const override {
    return mu0 * (1.0 + slope * s.pressure / std::cbrt(s.eta())) * (1.0 - alphap * s.temperature / s.melt_temperature);
  }
};

std::unique_ptr<ShearModulusModel> make_constant(const ModelParameters& p, const SubModelContext& c) {
  const double mu = p.has("shear_modulus") ? p.get_double("shear_modulus") : c.shear_modulus;
  if (!(mu > 0)) p.fail("shear_modulus", "constant_shear needs a positive <shear_modulus> (here or in the model)");
  return std::make_unique<ConstantShear>(mu);
}
std::unique_ptr<ShearModulusModel> make_mts(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<MtsShear>();
  m->mu0 = positive_parameter(p, "mu_0");
  m->D = p.get_double("D");
  m->T0 = p.get_double("T_0");
  return m;
}
std::unique_ptr<ShearModulusModel> make_scg(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<ScgShear>();
  m->mu0 = positive_parameter(p, "mu_0");
  m->A = p.get_double("A");
  m->B = p.get_double("B");
  return m;
}
std::unique_ptr<ShearModulusModel> make_np(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<NpShear>();
  m->mu0 = positive_parameter(p, "mu_0");
  m->zeta = positive_parameter(p, "zeta");
  m->slope = p.get_double("slope_mu_p_over_mu0");
  m->C = positive_parameter(p, "C");
  m->m = positive_parameter(p, "m");
  return m;
}
std::unique_ptr<ShearModulusModel> make_ptw(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<PtwShear>();
  m->mu0 = positive_parameter(p, "mu_0");
  // Both optional in Vaango's schema; MaterialData/NPShearTa.xml (type ptw_shear
  // with np_shear's children) has neither: α_p = 0 then (no thermal softening).
  (void)p.get_double("alpha", 0.0);
  m->alphap = p.get_double("alphap", 0.0);
  m->slope = p.get_double("slope_mu_p_over_mu0");
  for (const char* unused : {"C", "m", "zeta"}) (void)p.get_double(unused, 0.0);
  return m;
}
std::unique_ptr<ShearModulusModel> make_borja(const ModelParameters& p, const SubModelContext&) {
  p.missing_feature("type", "shear_modulus_model borja_shear (Cam-Clay, VT eq. 7.11-7.12)");
  return nullptr;  // not reached
}
}  // namespace

const std::vector<SubModelEntry<ShearModulusModel>>& shear_modulus_models() {
  static const std::vector<SubModelEntry<ShearModulusModel>> table = {
      {"constant_shear", {}, &make_constant}, {"mts_shear", {}, &make_mts}, {"scg_shear", {}, &make_scg},
      {"np_shear", {}, &make_np},             {"ptw_shear", {}, &make_ptw}, {"borja_shear", {}, &make_borja},
  };
  return table;
}

std::unique_ptr<ShearModulusModel> create_shear_modulus_model(const std::string& key, const ModelParameters& p,
                                                              const SubModelContext& ctx) {
  const auto* e = find_sub_model(shear_modulus_models(), key);
  return e ? e->create(p, ctx) : nullptr;
}

}  // namespace tephra
