#pragma once
// Vaango's "cnhp_damage" (VT ch. 2 list item 17, "neo-Hookean hyperelastic-J2
// plastic with damage"): the hyperelastic-plastic solid of
// "comp_neo_hook_plastic" (CompNeoHookPlastic.h: multiplicative split, J2 return
// of Simo & Hughes 1998 Box 9.1, linear isotropic hardening) with the brittle
// failure and erosion of "cnh_damage" (CnhDamage.h): a point fails, once and
// for good, in the first step whose end state crosses
//   failure_by_stress = false (default): max eig((F^T F - I)/2) > failure_variable_mean
//   failure_by_stress = true:            max eig(sigma_intact)   > failure_variable_mean
// where sigma_intact is the elastic-plastic stress of the step. A failed point
// carries zero stress; the stored energy at failure is reported as that step's
// dissipated work (with the step's plastic dissipation). The seed has no
// equations for this model (the inventory lists it without a law); it is the
// composition of the two implemented laws, named by Vaango's schema tags.
// History: bElBar (9), plasticStrain (1) as comp_neo_hook_plastic; localized (1)
// as cnh_damage. Plastic history stops evolving once failed.
// Parameters: those of comp_neo_hook_plastic (bulk_modulus, shear_modulus,
// yield_stress, hardening_modulus, alpha) and of cnh_damage
// (failure_variable_mean, failure_by_stress, failure_variable_std = 0).
#include <memory>

#include "models/solid/CnhDamage.h"
#include "models/solid/CompNeoHookPlastic.h"
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

class CnhpDamage final : public ConstitutiveModel {
 public:
  CnhpDamage(const CompNeoHookPlasticParams& plastic, const CnhDamageParams& failure)
      : plastic_(plastic, "comp_neo_hook_plastic"), failure_(failure) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "cnhp_damage"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return plastic_.bulk_modulus(); }
  double shear_modulus() const override { return plastic_.shear_modulus(); }

 private:
  CompNeoHookPlastic plastic_;
  CnhDamageParams failure_;
};

}  // namespace tephra
