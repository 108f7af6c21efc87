#pragma once
// Yield conditions, VT ch. 8: f(ξ, σ_y, φ) with ξ = σ - β (the stress relative
// to the backstress) and the gradient ∂f/∂σ (the flow direction for associated
// flow, eq. 9.2). Tension positive.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/plasticity/SubModelTable.h"

namespace tephra {

class YieldCondition {
 public:
  virtual ~YieldCondition() = default;
  virtual std::string type() const = 0;
  virtual double value(const Eigen::Matrix3d& xi, double sigma_y, double porosity) const = 0;
  virtual Eigen::Matrix3d gradient(const Eigen::Matrix3d& xi, double sigma_y, double porosity) const = 0;
};

// Kinematic hardening, VT ch. 11: the backstress rate for a plastic strain
// rate ε̇^p (tensor); Prager (11.2) β̇ = (2/3) s H ε̇^p; Armstrong-Frederick
// (11.3) β̇ = (2/3) s H_1 ε̇^p - s H_2 β ||ε̇^p|| (s = the scalar tag <beta>).
class KinematicHardeningModel {
 public:
  virtual ~KinematicHardeningModel() = default;
  virtual std::string type() const = 0;
  virtual Eigen::Matrix3d backstress_rate(const Eigen::Matrix3d& backstress,
                                          const Eigen::Matrix3d& plastic_strain_rate) const = 0;
  // The moduli of the rate written as β̇ = (2/3) H_lin ε̇^p - H_rec β ||ε̇^p|| (scale <beta>
  // included): H_lin = s H (Prager), s H_1 (AF); H_rec = 0 (Prager), s H_2 (AF); both 0 for none.
  // The composed return (elastic_plastic_hp) integrates this rate by backward Euler.
  virtual double linear_modulus() const = 0;
  virtual double recovery_modulus() const = 0;
  // Backward Euler over a step with plastic strain increment Δε^p:
  //   β_{n+1} (1 + H_rec ||Δε^p||) = β_n + (2/3) H_lin Δε^p.
  Eigen::Matrix3d backstress_after(const Eigen::Matrix3d& beta_n, const Eigen::Matrix3d& delta_eps_p) const {
    return (beta_n + 2.0 / 3.0 * linear_modulus() * delta_eps_p) / (1.0 + recovery_modulus() * delta_eps_p.norm());
  }
  // The kinematic part of the J2 hardening modulus of the continuum tangent (VT 18.29 term
  // -∂f/∂β : h^β): with f = sqrt(3/2)|ξ| - σ_y, ξ = s - β, flow ε̇^p = γ̇ sqrt(3/2) n̂ (n̂ = ξ/|ξ|),
  // sqrt(3/2) n̂ : β̇ = γ̇ (H_lin - 3/2 H_rec β : n̂); 0 for none.
  double j2_modulus(const Eigen::Matrix3d& beta, const Eigen::Matrix3d& xi) const {
    const double n = xi.norm();
    return linear_modulus() - (n > 0.0 ? 1.5 * recovery_modulus() * beta.cwiseProduct(xi).sum() / n : 0.0);
  }
};

// Damage, VT ch. 15: the rate Ḋ for the state (ε̇_p, T) and the stress.
class DamageModel {
 public:
  virtual ~DamageModel() = default;
  virtual std::string type() const = 0;
  virtual double initial_damage() const = 0;
  virtual double critical_damage() const = 0;
  virtual double damage_rate(const Eigen::Matrix3d& stress, const PlasticState& s) const = 0;
};

// Internal variables, VT ch. 12 (metal_internal_var): ε̇_p = λ̇ (h = 1, eq. 12.4)
// and the porosity rate φ̇ = (1 - φ) tr ε̇^p + f_n/(s_n sqrt(2π)) exp(-½((ε_p - ε_n)/s_n)²) ε̇_p
// (eq. 12.5-12.9; nucleation only when f_n > 0).
class InternalVariableModel {
 public:
  virtual ~InternalVariableModel() = default;
  virtual std::string type() const = 0;
  virtual double porosity_rate(const PlasticState& s, double trace_plastic_strain_rate) const = 0;
};

const std::vector<SubModelEntry<YieldCondition>>& yield_conditions();
const std::vector<SubModelEntry<KinematicHardeningModel>>& kinematic_hardening_models();
const std::vector<SubModelEntry<DamageModel>>& damage_models();
const std::vector<SubModelEntry<InternalVariableModel>>& internal_variable_models();

std::unique_ptr<YieldCondition> create_yield_condition(const std::string& key, const ModelParameters& p,
                                                       const SubModelContext& ctx = {});
std::unique_ptr<KinematicHardeningModel> create_kinematic_hardening_model(const std::string& key,
                                                                          const ModelParameters& p,
                                                                          const SubModelContext& ctx = {});
std::unique_ptr<DamageModel> create_damage_model(const std::string& key, const ModelParameters& p,
                                                 const SubModelContext& ctx = {});
std::unique_ptr<InternalVariableModel> create_internal_variable_model(const std::string& key,
                                                                      const ModelParameters& p,
                                                                      const SubModelContext& ctx = {});

// Shared scalar measures: σ_eff = sqrt(3/2 s:s) with s = dev ξ.
double von_mises_stress(const Eigen::Matrix3d& xi);

}  // namespace tephra
