// Linear hardening, VT eq. 10.1: σ_y = σ_0 + K ε_p.
// Keys: `linear` (schema: <sigma_0>, <K>) and the deck spelling
// `isotropic_hardening` (<sigma_Y>, <K>), e.g. MaterialData/IsoHardPlasticAnnCopper.xml.
#include "models/plasticity/FlowStressModel.h"

namespace tephra {
namespace {
class LinearFlow final : public FlowStressModel {
 public:
  LinearFlow(double s0, double K) : s0_(s0), K_(K) {}
  std::string type() const override { return "linear"; }
  FlowStress evaluate(const PlasticState& s) const override { return {s0_ + K_ * s.eps_p, K_, 0.0, 0.0}; }

 private:
  double s0_, K_;
};
}  // namespace

FlowStressModelP create_linear_flow(const ModelParameters& p, const SubModelContext&) {
  const bool has_0 = p.has("sigma_0"), has_Y = p.has("sigma_Y");
  if (has_0 && has_Y) p.fail("sigma_Y", "give either <sigma_0> or <sigma_Y>, not both");
  const double s0 = has_Y ? p.get_double("sigma_Y") : p.get_double("sigma_0");
  if (s0 < 0) p.fail(has_Y ? "sigma_Y" : "sigma_0", "must be non-negative");
  return std::make_unique<LinearFlow>(s0, p.get_double("K"));
}

}  // namespace tephra
