#pragma once
// Vaango's "hypo_elastic_mms" (VT ch. 2 list item 10, "hypoelastic with
// manufactured solutions"): the linear isotropic hypoelastic law of
// "hypo_elastic" (VT eq. 4.2, Green-Naghdi objective rate; HypoElastic.h) under
// its own type name, the material Vaango's MMS decks (<run_MMS_problem>) pair
// with a hypoelastic solid. The MMS body forces and exact fields live in mpm/mms
// (MmsProblem); this type only supplies the stress. Same parameters as
// hypo_elastic: <G>, <K> [Pa] required, <alpha> only 0 (MissingFeature otherwise).
//
// Note: the seed gives no separate equation for this type (VT ch. 2 lists it
// without a section); Tephra treats it as hypo_elastic's law, which is what the
// name and the shared parameter set (G, K) in Vaango's schema indicate.
#include "models/solid/HypoElastic.h"

namespace tephra {

class HypoElasticMms final : public ConstitutiveModel {
 public:
  explicit HypoElasticMms(const HypoElasticParams& p) : law_(p), p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "hypo_elastic_mms"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override {
    return law_.update(in, out);
  }
  double bulk_modulus() const override { return p_.K; }
  double shear_modulus() const override { return p_.G; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double rho0, double T) const override {
    return law_.pressure_at_density(rho, rho0, T);
  }
  std::optional<double> density_at_pressure(double p, double rho0, double T) const override {
    return law_.density_at_pressure(p, rho0, T);
  }

 private:
  HypoElastic law_;
  HypoElasticParams p_;
};

}  // namespace tephra
