#pragma once
// Vaango's "cnh_damage" (VT ch. 2 list item 15, "neo-Hookean with damage"):
// the compressible neo-Hookean solid of "comp_neo_hook" (CompNeoHookean.h,
//   sigma = K/2 (J - 1/J) I + G J^{-5/3} dev(B))
// with a brittle failure criterion and erosion: a point fails, once and for
// good, in the first step whose end state crosses the threshold
//   failure_by_stress = false (default): max principal Green-Lagrange strain
//        e_max = max eig( (F^T F - I)/2 )          >  failure_variable_mean
//   failure_by_stress = true:  max principal Cauchy stress
//        s_max = max eig( sigma_intact )           >  failure_variable_mean
// A failed point carries zero stress from that step on (erosion, Vaango's
// "ZeroStress" treatment); its stored energy W(F) at failure is reported as the
// step's dissipated work, later steps dissipate nothing. The flag is the history
// variable "localized" (Vaango's p.localized label): 0 intact, 1 failed.
// The seed has no equations for this model (inventory: "brittle damage law not
// in the seed"); the criterion follows Vaango's schema tags.
// Parameters: <bulk_modulus>, <shear_modulus> [Pa] > 0; <failure_variable_mean>
// (threshold, > 0, required); <failure_by_stress> (bool, default false);
// <failure_variable_distrib> "constant" (default) or any distribution with
// <failure_variable_std> = 0; a random per-point threshold (std > 0) is a
// MissingFeature.
#include <Eigen/Core>

#include "models/solid/CompNeoHookean.h"
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct CnhDamageParams {
  CompNeoHookeanParams elastic;
  double failure_threshold = 0.0;  // strain [-] or stress [Pa]
  bool failure_by_stress = false;
};

// The criterion value of the intact state: max principal Green-Lagrange strain
// of F, or max principal value of the intact Cauchy stress.
double cnh_damage_criterion(const Eigen::Matrix3d& F, const Eigen::Matrix3d& intact_stress,
                            const CnhDamageParams& p);

class CnhDamage final : public ConstitutiveModel {
 public:
  explicit CnhDamage(const CnhDamageParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "cnh_damage"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.elastic.bulk_modulus; }
  double shear_modulus() const override { return p_.elastic.shear_modulus; }

 private:
  CnhDamageParams p_;
};

}  // namespace tephra
