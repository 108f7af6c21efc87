// Kinematic hardening (VT ch. 11), internal variables (ch. 12) and damage (ch. 15).
#include <cmath>

#include "models/plasticity/YieldCondition.h"

namespace tephra {
namespace {

class NoKinematic final : public KinematicHardeningModel {
 public:
  std::string type() const override { return "none"; }
  Eigen::Matrix3d backstress_rate(const Eigen::Matrix3d&, const Eigen::Matrix3d&) const override {
    return Eigen::Matrix3d::Zero();
  }
  double linear_modulus() const override { return 0.0; }
  double recovery_modulus() const override { return 0.0; }
};

// Prager, eq. 11.2: β̇ = (2/3) s H ε̇^p. Armstrong-Frederick, eq. 11.3:
// β̇ = (2/3) s H_1 ε̇^p - s H_2 β ||ε̇^p||, ||·|| the Frobenius norm. H_2 = 0 is Prager.
class ArmstrongFrederick final : public KinematicHardeningModel {
 public:
  std::string key;
  double s = 1, H1 = 0, H2 = 0;
  std::string type() const override { return key; }
  Eigen::Matrix3d backstress_rate(const Eigen::Matrix3d& beta, const Eigen::Matrix3d& dp) const override {
    return 2.0 / 3.0 * s * H1 * dp - s * H2 * beta * dp.norm();
  }
  double linear_modulus() const override { return s * H1; }
  double recovery_modulus() const override { return s * H2; }
};

class MetalInternalVar final : public InternalVariableModel {
 public:
  double fn = 0, en = 0, sn = 1;
  std::string type() const override { return "metal_internal_var"; }
  double porosity_rate(const PlasticState& st, double tr_dp) const override {
    const double grow = (1.0 - st.porosity) * tr_dp;
    const double z = (st.eps_p - en) / sn;
    const double nuc = fn > 0 ? fn / (sn * std::sqrt(2.0 * M_PI)) * std::exp(-0.5 * z * z) * st.eps_p_rate : 0.0;
    return grow + nuc;
  }
};

double triaxiality(const Eigen::Matrix3d& stress) {  // σ* = tr σ/(3 σ_eff), 0 for zero deviator
  const double se = von_mises_stress(stress);
  return se > 0 ? stress.trace() / (3.0 * se) : 0.0;
}

// Hancock-MacKenzie, eq. 15.1-15.2: Ḋ = (1/1.65) ε̇_p exp(3σ*/2), σ* = tr σ/(3σ_eff).
// Tags <D0> (initial) and <Dc> (critical).
class HancockMacKenzie final : public DamageModel {
 public:
  double D0, Dc;
  std::string type() const override { return "hancock_mackenzie"; }
  double initial_damage() const override { return D0; }
  double critical_damage() const override { return Dc; }
  double damage_rate(const Eigen::Matrix3d& stress, const PlasticState& s) const override {
    return s.eps_p_rate / 1.65 * std::exp(1.5 * triaxiality(stress));
  }
};

// Johnson-Cook damage, eq. 15.3-15.6: Ḋ = ε̇_p/ε_f,
//   ε_f = [D1 + D2 exp(D3 σ*)] [1 + D4 ln ε̇*] [1 + D5 T*],
//   ε̇* = ε̇_p/ε̇_0 (ln term only for ε̇* > 1), T* = (T - T_r)/(T_m - T_r).
// ε̇_0, T_r, T_m are not damage tags; a composed model passes them in the context
// (<room_temp>, <melt_temp>); defaults 1/s, and T_m from the state.
class JohnsonCookDamage final : public DamageModel {
 public:
  double D1, D2, D3, D4, D5, Tr = 294.0, Tm = 0.0, epdot0 = 1.0;
  std::string type() const override { return "johnson_cook"; }
  double initial_damage() const override { return 0.0; }
  double critical_damage() const override { return 1.0; }
  double fracture_strain(double sstar, double rate, double T, double Tmelt) const {
    const double rs = rate / epdot0;
    const double Ts = (T - Tr) / (Tmelt - Tr);
    return (D1 + D2 * std::exp(D3 * sstar)) * (1.0 + D4 * (rs > 1.0 ? std::log(rs) : 0.0)) * (1.0 + D5 * Ts);
  }
  double damage_rate(const Eigen::Matrix3d& stress, const PlasticState& s) const override {
    const double Tmelt = Tm > 0 ? Tm : s.melt_temperature;
    return s.eps_p_rate / fracture_strain(triaxiality(stress), s.eps_p_rate, s.temperature, Tmelt);
  }
};

std::unique_ptr<KinematicHardeningModel> make_none(const ModelParameters&, const SubModelContext&) {
  return std::make_unique<NoKinematic>();
}
std::unique_ptr<KinematicHardeningModel> make_prager(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<ArmstrongFrederick>();
  m->key = "prager";
  m->s = p.get_double("beta", 1.0);
  m->H1 = p.get_double("hardening_modulus");
  return m;
}
std::unique_ptr<KinematicHardeningModel> make_af(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<ArmstrongFrederick>();
  m->key = "armstrong_frederick";
  m->s = p.get_double("beta", 1.0);
  m->H1 = p.get_double("hardening_modulus_1");
  m->H2 = p.get_double("hardening_modulus_2");
  return m;
}
std::unique_ptr<InternalVariableModel> make_metal(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<MetalInternalVar>();
  m->fn = p.get_double("vol_frac_nucleation", 0.0);
  m->en = p.get_double("mean_strain_nucleation", 0.0);
  m->sn = p.get_double("stddev_strain_nucleation", 1.0);
  if (m->fn > 0 && !(m->sn > 0)) p.fail("stddev_strain_nucleation", "must be positive");
  return m;
}
std::unique_ptr<DamageModel> make_hm(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<HancockMacKenzie>();
  m->D0 = p.get_double("D0", 0.0);
  m->Dc = p.get_double("Dc", 1.0);
  return m;
}
std::unique_ptr<DamageModel> make_jc(const ModelParameters& p, const SubModelContext& c) {
  auto m = std::make_unique<JohnsonCookDamage>();
  m->D1 = p.get_double("D1");
  m->D2 = p.get_double("D2");
  m->D3 = p.get_double("D3");
  m->D4 = p.get_double("D4");
  m->D5 = p.get_double("D5");
  if (c.room_temperature > 0) m->Tr = c.room_temperature;
  m->Tm = c.melt_temperature;
  return m;
}
}  // namespace

const std::vector<SubModelEntry<KinematicHardeningModel>>& kinematic_hardening_models() {
  static const std::vector<SubModelEntry<KinematicHardeningModel>> table = {
      {"none", {}, &make_none}, {"prager", {}, &make_prager}, {"armstrong_frederick", {}, &make_af}};
  return table;
}
const std::vector<SubModelEntry<InternalVariableModel>>& internal_variable_models() {
  static const std::vector<SubModelEntry<InternalVariableModel>> table = {
      {"metal_internal_var", {}, &make_metal}};
  return table;
}
const std::vector<SubModelEntry<DamageModel>>& damage_models() {
  static const std::vector<SubModelEntry<DamageModel>> table = {
      {"hancock_mackenzie", {}, &make_hm}, {"johnson_cook", {}, &make_jc}};
  return table;
}

#define TEPHRA_CREATE(Family, fn, table)                                                                  \
  std::unique_ptr<Family> fn(const std::string& key, const ModelParameters& p, const SubModelContext& c) { \
    const auto* e = find_sub_model(table(), key);                                                          \
    return e ? e->create(p, c) : nullptr;                                                                  \
  }
TEPHRA_CREATE(KinematicHardeningModel, create_kinematic_hardening_model, kinematic_hardening_models)
TEPHRA_CREATE(InternalVariableModel, create_internal_variable_model, internal_variable_models)
TEPHRA_CREATE(DamageModel, create_damage_model, damage_models)
#undef TEPHRA_CREATE

}  // namespace tephra
