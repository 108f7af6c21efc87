// Zerilli-Armstrong flow stress, VT eq. 10.8-10.10:
//   σ_y = σ_a + B exp(-β T) + B_0 sqrt(ε_p) exp(-α T),
//   σ_a = σ_g + k_H/sqrt(l) + K ε_p^n,  α = α_0 - α_1 ln ε̇,  β = β_0 - β_1 ln ε̇.
// <c_0> (schema, optional) replaces σ_g + k_H/sqrt(l) when given.
// ε̇ below kMinPlasticRate is floored (FlowAd.h).
#include "models/plasticity/FlowAd.h"

namespace tephra {
namespace {
class ZerilliArmstrongFlow final : public FlowStressModel {
 public:
  double c0, B, beta0, beta1, B0, alpha0, alpha1, K, n;
  std::string type() const override { return "zerilli_armstrong"; }
  template <class S>
  S law(const S& ep, const S& rate_in, const S& T) const {
    using namespace ad;
    const S rate = floor_rate(rate_in);
    const S lr = log(rate);
    const S alpha = S(alpha0) - S(alpha1) * lr, beta = S(beta0) - S(beta1) * lr;
    const S hard = (K != 0.0 && ep.v > 0) ? S(K) * pow(ep, n) : S(0.0);
    const S root = ep.v > 0 ? sqrt(ep) : S(0.0);
    return S(c0) + hard + S(B) * exp(-beta * T) + S(B0) * root * exp(-alpha * T);
  }
  FlowStress evaluate(const PlasticState& s) const override {
    return evaluate_flow_law([this](auto&& a, auto&& b, auto&& c) { return law(a, b, c); }, s);
  }
};
}  // namespace

FlowStressModelP create_zerilli_armstrong_flow(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<ZerilliArmstrongFlow>();
  if (p.has("c_0")) {
    m->c0 = p.get_double("c_0");
  } else {
    m->c0 = p.get_double("sigma_g", 0.0) + p.get_double("k_H", 0.0) * p.get_double("sqrt_l_inv", 0.0);
  }
  m->B = p.get_double("B");
  m->beta0 = p.get_double("beta_0");
  m->beta1 = p.get_double("beta_1");
  m->B0 = p.get_double("B_0");
  m->alpha0 = p.get_double("alpha_0");
  m->alpha1 = p.get_double("alpha_1");
  m->K = p.get_double("K");
  m->n = p.get_double("n");
  return m;
}

}  // namespace tephra
