#include "models/solid/CnhpDamage.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {
constexpr int kBbar = 0, kAlpha = 1, kLocalized = 2;  // history columns
}

std::vector<HistoryVariable> CnhpDamage::history() const {
  std::vector<HistoryVariable> h = plastic_.history();  // bElBar, plasticStrain
  h.push_back({"localized", 1, {0.0}, "failure flag: 0 intact, 1 failed (eroded, zero stress) [-]"});
  return h;
}

long CnhpDamage::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return for_each_point(in.F_new.size(), [&](size_t i) {
    double& localized = out.history[kLocalized][i];
    if (localized != 0.0) {  // eroded: zero stress, nothing stored, nothing dissipated
      const double J = in.F_new[i].determinant();
      if (!(J > 0.0) || !std::isfinite(J)) return false;
      out.stress[i] = Eigen::Matrix3d::Zero();
      out.energy_density[i] = 0.0;
      out.plastic_work[i] = 0.0;
      out.heating[i] = 0.0;
      // The intact material's speed (as cnh_damage): K_t = K/2 (1 + 1/J^2), c^2 = (K_t + 4G/3) J / rho0.
      const double K = plastic_.bulk_modulus(), G = plastic_.shear_modulus();
      out.wave_speed[i] = std::sqrt((0.5 * K * (1.0 + 1.0 / (J * J)) + 4.0 * G / 3.0) * J / in.density0);
      return true;
    }
    double hist[10];
    for (int k = 0; k < 9; ++k) hist[k] = out.history[kBbar][9 * i + k];
    hist[9] = out.history[kAlpha][i];
    CompNeoHookPlastic::PointOut po;
    if (!plastic_.update_point(in.F_old[i], in.F_new[i], in.density0, hist, po)) return false;
    for (int k = 0; k < 9; ++k) out.history[kBbar][9 * i + k] = hist[k];
    out.history[kAlpha][i] = hist[9];
    out.wave_speed[i] = po.r.wave_speed;
    out.heating[i] = 0.0;
    if (cnh_damage_criterion(in.F_new[i], po.r.stress, failure_) > failure_.failure_threshold) {
      localized = 1.0;
      out.stress[i] = Eigen::Matrix3d::Zero();
      out.energy_density[i] = 0.0;
      out.plastic_work[i] = po.plastic_work + po.r.energy_density;  // the stored energy lost with the stress
    } else {
      out.stress[i] = po.r.stress;
      out.energy_density[i] = po.r.energy_density;
      out.plastic_work[i] = po.plastic_work;
    }
    return true;
  });
}

ConstitutiveModelP CnhpDamage::create(const ModelParameters& params) {
  CompNeoHookPlasticParams p;
  p.bulk_modulus = params.get_double("bulk_modulus");
  p.shear_modulus = params.get_double("shear_modulus");
  if (!(p.bulk_modulus > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  if (!(p.shear_modulus > 0.0)) params.fail("shear_modulus", "shear_modulus must be > 0");
  p.use_plasticity = true;
  p.yield_stress = params.get_double("yield_stress");
  p.hardening_modulus = params.get_double("hardening_modulus");
  p.initial_alpha = params.get_double("alpha", 0.0);
  if (!(p.yield_stress > 0.0)) params.fail("yield_stress", "yield_stress must be > 0");
  if (!(p.hardening_modulus >= 0.0)) params.fail("hardening_modulus", "hardening_modulus must be >= 0");
  if (!(p.initial_alpha >= 0.0)) params.fail("alpha", "alpha (initial plastic strain) must be >= 0");
  CnhDamageParams f;
  f.elastic = {p.bulk_modulus, p.shear_modulus};
  f.failure_threshold = params.get_double("failure_variable_mean");
  if (!(f.failure_threshold > 0.0))
    params.fail("failure_variable_mean", "failure_variable_mean (failure threshold) must be > 0");
  f.failure_by_stress = params.get_bool("failure_by_stress", false);
  if (params.get_double("failure_variable_std", 0.0) != 0.0)
    params.missing_feature("failure_variable_std",
                           "cnhp_damage random failure thresholds (failure_variable_std != 0, distrib " +
                               params.get_string("failure_variable_distrib", "constant") + ")");
  if (params.get_bool("useModifiedEOS", false))
    params.missing_feature("useModifiedEOS", "cnhp_damage with useModifiedEOS = true");
  return std::make_shared<CnhpDamage>(p, f);
}

}  // namespace tephra
