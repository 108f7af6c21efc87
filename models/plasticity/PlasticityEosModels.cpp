// Equation-of-state sub-models, VT ch. 6. p = mean stress (tension positive).
#include <cmath>

#include "models/plasticity/PlasticityEos.h"

namespace tephra {
namespace {

// default_hypo, eq. 6.1-6.7: p_{n+1} = p_n + κ tr(d) Δt; ∂p/∂J = κ/J.
class DefaultHypo final : public PlasticityEos {
 public:
  explicit DefaultHypo(double K) : K_(K) {}
  std::string type() const override { return "default_hypo"; }
  EosResult evaluate(const EosInput& in) const override { return {in.p_old + K_ * in.trace_d * in.dt, K_ / in.J}; }
  EosResult at_volume_ratio(double J) const override { return {K_ * std::log(J), K_ / J}; }  // ∫ K dJ/J
  double bulk_modulus() const override { return K_; }
  double K_;
};

// default_hyper, eq. 6.8-6.9: p = ½κ(J - 1/J); dp/dJ = ½κ(1 + 1/J²).
class DefaultHyper final : public PlasticityEos {
 public:
  explicit DefaultHyper(double K) : K_(K) {}
  std::string type() const override { return "default_hyper"; }
  EosResult evaluate(const EosInput& in) const override {
    return {0.5 * K_ * (in.J - 1.0 / in.J), 0.5 * K_ * (1.0 + 1.0 / (in.J * in.J))};
  }
  double bulk_modulus() const override { return K_; }
  double K_;
};

// mie_gruneisen (eq. 6.10-6.12) and mie_gruneisen_energy (cubic Hugoniot, eq. 6.13):
//   x = 1 - J,  p = -ρ_0 C_0² x [1 - Γ_0 x/2] / [1 - S_α x - S_2 x² - S_3 x³]² - Γ_0 E,
// ∂p/∂J neglecting ∂E/∂J (as eq. 6.12). S_2 = S_3 = 0 is eq. 6.10 exactly;
// decks give <S_2>, <S_3> under both keys, so both accept them (default 0).
class MieGruneisen final : public PlasticityEos {
 public:
  std::string key;
  double rho0, C0, Gamma0, S1, S2, S3;
  std::string type() const override { return key; }
  EosResult evaluate(const EosInput& in) const override {
    const double x = 1.0 - in.J;
    const double K0 = rho0 * C0 * C0;
    const double num = x * (1.0 - 0.5 * Gamma0 * x), dnum = 1.0 - Gamma0 * x;  // d/dx
    const double den = 1.0 - x * (S1 + x * (S2 + x * S3)), dden = -(S1 + x * (2.0 * S2 + 3.0 * x * S3));
    const double q = num / (den * den);
    const double dq_dx = dnum / (den * den) - 2.0 * num * dden / (den * den * den);
    return {-K0 * q - Gamma0 * in.energy, K0 * dq_dx};  // dx/dJ = -1
  }
  double bulk_modulus() const override { return rho0 * C0 * C0; }
};

// air, water, granite: Vaango's Arena-family pressure models (Pressure_Air.cc,
// Pressure_Water.cc, Pressure_Granite.cc) with their fixed constants, written
// for the thermodynamic pressure p̄ (compression +) and returned as p = -p̄:
//   air (eq. 6.18): p̄ = p_r [exp(γ ε̄_v) - 1], ε̄_v = -ln J (0 in expansion), p_r = 101325 Pa, γ = 1.4
//   water, granite (Tait/Murnaghan): p̄ = p_0 + K_0/n (J^{-n} - 1)
//     water: p_0 = 1e-4 Pa, K_0 = 2.21e9 Pa, n = 6.029; granite: p_0 = 101325 Pa, K_0 = 40e9 Pa, n = 4.
class Air final : public PlasticityEos {
 public:
  std::string type() const override { return "air"; }
  EosResult evaluate(const EosInput& in) const override {
    const double ev = in.J > 1.0 ? 0.0 : -std::log(in.J);
    const double pbar = pr * (std::exp(gamma * ev) - 1.0);
    const double dpbar_dJ = in.J > 1.0 ? 0.0 : -gamma * (pbar + pr) / in.J;
    return {-pbar, -dpbar_dJ};
  }
  double bulk_modulus() const override { return gamma * pr; }
  static constexpr double pr = 101325.0, gamma = 1.4;
};

class Tait final : public PlasticityEos {
 public:
  Tait(std::string k, double p0, double K0, double n) : key(std::move(k)), p0_(p0), K0_(K0), n_(n) {}
  std::string type() const override { return key; }
  EosResult evaluate(const EosInput& in) const override {
    const double pbar = p0_ + K0_ / n_ * (std::pow(in.J, -n_) - 1.0);
    return {-pbar, K0_ * std::pow(in.J, -(n_ + 1.0))};
  }
  double bulk_modulus() const override { return K0_; }
  std::string key;
  double p0_, K0_, n_;
};

double bulk(const ModelParameters& p, const SubModelContext& c) {
  const double K = p.has("bulk_modulus") ? p.get_double("bulk_modulus") : c.bulk_modulus;
  if (!(K > 0)) p.fail("bulk_modulus", "needs a positive <bulk_modulus> (here or in the model)");
  return K;
}
std::unique_ptr<PlasticityEos> make_hypo(const ModelParameters& p, const SubModelContext& c) {
  return std::make_unique<DefaultHypo>(bulk(p, c));
}
std::unique_ptr<PlasticityEos> make_hyper(const ModelParameters& p, const SubModelContext& c) {
  return std::make_unique<DefaultHyper>(bulk(p, c));
}
std::unique_ptr<PlasticityEos> make_mg(const ModelParameters& p, const SubModelContext& c, const std::string& key) {
  auto m = std::make_unique<MieGruneisen>();
  m->key = key;
  m->C0 = positive_parameter(p, "C_0");
  m->Gamma0 = p.get_double("Gamma_0");
  m->S1 = p.get_double("S_alpha");
  m->S2 = p.get_double("S_2", 0.0);
  m->S3 = p.get_double("S_3", 0.0);
  // <rho_0>, or the material's <density> (most MaterialData/MieGruneisen*.xml omit it).
  m->rho0 = p.has("rho_0") ? p.get_double("rho_0") : c.density0;
  if (!(m->rho0 > 0)) p.fail("rho_0", "needs a positive <rho_0> (here) or the material's <density>");
  return m;
}
std::unique_ptr<PlasticityEos> make_mg1(const ModelParameters& p, const SubModelContext& c) {
  return make_mg(p, c, "mie_gruneisen");
}
std::unique_ptr<PlasticityEos> make_mge(const ModelParameters& p, const SubModelContext& c) {
  return make_mg(p, c, "mie_gruneisen_energy");
}
std::unique_ptr<PlasticityEos> make_air(const ModelParameters&, const SubModelContext&) {
  return std::make_unique<Air>();
}
std::unique_ptr<PlasticityEos> make_water(const ModelParameters&, const SubModelContext&) {
  return std::make_unique<Tait>("water", 1.0e-4, 2.21e9, 6.029);
}
std::unique_ptr<PlasticityEos> make_granite(const ModelParameters&, const SubModelContext&) {
  return std::make_unique<Tait>("granite", 101325.0, 40.0e9, 4.0);
}
std::unique_ptr<PlasticityEos> make_borja(const ModelParameters& p, const SubModelContext&) {
  p.missing_feature("type", "equation_of_state borja_pressure (Cam-Clay)");
  return nullptr;  // not reached
}
}  // namespace

const std::vector<SubModelEntry<PlasticityEos>>& plasticity_eos_models() {
  static const std::vector<SubModelEntry<PlasticityEos>> table = {
      {"default_hypo", {}, &make_hypo}, {"default_hyper", {}, &make_hyper},
      {"mie_gruneisen", {}, &make_mg1}, {"mie_gruneisen_energy", {}, &make_mge},
      {"air", {}, &make_air},           {"water", {}, &make_water},
      {"granite", {}, &make_granite},   {"borja_pressure", {}, &make_borja},
  };
  return table;
}

std::unique_ptr<PlasticityEos> create_plasticity_eos(const std::string& key, const ModelParameters& p,
                                                     const SubModelContext& ctx) {
  const auto* e = find_sub_model(plasticity_eos_models(), key);
  return e ? e->create(p, ctx) : nullptr;
}

}  // namespace tephra
