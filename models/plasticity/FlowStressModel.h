#pragma once
// Flow-stress (isotropic hardening) models, Vaango theory manual ch. 10.
// Each model gives σ_y(ε_p, ε̇_p, T, p̄, ρ, ...) and the partial derivatives the
// return algorithms need (∂σ_y/∂ε_p, ∂σ_y/∂ε̇_p, ∂σ_y/∂T; ch. 10 preamble).
// Registry keys: Vaango's schema names plus the deck aliases (isotropic_hardening,
// mts_model). Pure point functions; no particle or grid type.
#include <memory>
#include <string>
#include <vector>

#include "models/plasticity/SubModelTable.h"

namespace tephra {

struct FlowStress {
  double sigma_y = 0.0;      // flow stress [Pa]
  double d_eps_p = 0.0;      // ∂σ_y/∂ε_p [Pa]
  double d_eps_p_rate = 0.0; // ∂σ_y/∂ε̇_p [Pa s]
  double d_T = 0.0;          // ∂σ_y/∂T [Pa/K]
};

class FlowStressModel {
 public:
  virtual ~FlowStressModel() = default;
  virtual std::string type() const = 0;  // canonical key
  virtual FlowStress evaluate(const PlasticState& s) const = 0;
  // Models with an evolving internal stress (MTS σ_e, eq. 10.19) give its rate
  // dσ_e/dε_p = θ(σ_e); 0 for the others.
  virtual double internal_stress_rate(const PlasticState&) const { return 0.0; }
  // σ_e after a plastic increment Δε_p from s.sigma_e (= σ_e,n) at the step's rate and
  // temperature (s.eps_p_rate, s.temperature held over the increment): the ODE
  // dσ_e/dε_p = θ(σ_e) integrated over [0, Δε_p] (MTS: RK4 substeps, MtsFlow.cpp), not the
  // explicit σ_e,n + θ(σ_e,n) Δε_p; s.sigma_e for the laws without an internal stress.
  virtual double evolve_internal_stress(const PlasticState& s, double /*dep*/) const { return s.sigma_e; }
};

using FlowStressModelP = std::unique_ptr<FlowStressModel>;
const std::vector<SubModelEntry<FlowStressModel>>& flow_stress_models();
// nullptr for an unknown key (the caller reports it with sub_model_keys()).
FlowStressModelP create_flow_stress_model(const std::string& key, const ModelParameters& p,
                                          const SubModelContext& ctx = {});

// Creators, one per model source file.
FlowStressModelP create_linear_flow(const ModelParameters&, const SubModelContext&);
FlowStressModelP create_johnson_cook_flow(const ModelParameters&, const SubModelContext&);
FlowStressModelP create_zerilli_armstrong_flow(const ModelParameters&, const SubModelContext&);
FlowStressModelP create_zerilli_armstrong_polymer_flow(const ModelParameters&, const SubModelContext&);
FlowStressModelP create_mts_flow(const ModelParameters&, const SubModelContext&);
FlowStressModelP create_ptw_flow(const ModelParameters&, const SubModelContext&);
FlowStressModelP create_scg_flow(const ModelParameters&, const SubModelContext&);

}  // namespace tephra
