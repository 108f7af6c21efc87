// Polymer Zerilli-Armstrong flow stress, VT eq. 10.11-10.15:
//   σ_y = σ_g + B exp(-β T*) + B_0 sqrt(ω ε_p) exp(-α T*),  T* = T/T_0,
//   ω = ω_a + ω_b ln ε̇ + ω_p sqrt(p̄),  α = α_0 - α_1 ln ε̇,  β = β_0 - β_1 ln ε̇,
//   B = B_pa (1 + B_pb sqrt(p̄))^B_pn,  B_0 = B_0pa (1 + B_0pb sqrt(p̄))^B_0pn.
// p̄ < 0 (tension) uses p̄ = 0 in the square roots; ω ε_p < 0 gives no B_0 term.
// Parameter spellings: the schema's B_0pa/B_0pb/B_0pn and the manual's
// B_Opa/B_Opb/B_Opn are accepted; alpha_0/alpha_1 default to 0 (not in the
// schema for this model, listed in eq. 10.13).
#include "models/plasticity/FlowAd.h"

namespace tephra {
namespace {
class ZerilliArmstrongPolymerFlow final : public FlowStressModel {
 public:
  double sigma_g, Bpa, Bpb, Bpn, beta0, beta1, T0, B0pa, B0pb, B0pn, wa, wb, wp, alpha0, alpha1;
  std::string type() const override { return "zerilli_armstrong_polymer"; }
  template <class S>
  S law(const S& ep, const S& rate_in, const S& T, double pbar) const {
    using namespace ad;
    const S rate = floor_rate(rate_in);
    const S lr = log(rate);
    const double sp = std::sqrt(std::max(pbar, 0.0));
    const S Tstar = T / S(T0);
    const S alpha = S(alpha0) - S(alpha1) * lr, beta = S(beta0) - S(beta1) * lr;
    const double B = Bpa * std::pow(1.0 + Bpb * sp, Bpn), B0 = B0pa * std::pow(1.0 + B0pb * sp, B0pn);
    const S omega = S(wa + wp * sp) + S(wb) * lr;
    const S we = omega * ep;
    const S root = value(we) > 0 ? sqrt(we) : S(0.0);
    return S(sigma_g) + S(B) * exp(-beta * Tstar) + S(B0) * root * exp(-alpha * Tstar);
  }
  FlowStress evaluate(const PlasticState& s) const override {
    return evaluate_flow_law([&](auto&& a, auto&& b, auto&& c) { return law(a, b, c, s.pressure); }, s);
  }
};

double either(const ModelParameters& p, const std::string& a, const std::string& b) {
  if (p.has(a) && p.has(b)) p.fail(b, "given twice (as <" + a + "> and <" + b + ">)");
  return p.has(b) ? p.get_double(b) : p.get_double(a);
}
}  // namespace

FlowStressModelP create_zerilli_armstrong_polymer_flow(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<ZerilliArmstrongPolymerFlow>();
  m->sigma_g = p.get_double("sigma_g");
  m->Bpa = p.get_double("B_pa");
  m->Bpb = p.get_double("B_pb");
  m->Bpn = p.get_double("B_pn");
  m->beta0 = p.get_double("beta_0");
  m->beta1 = p.get_double("beta_1");
  m->T0 = positive_parameter(p, "T_0");
  m->B0pa = either(p, "B_0pa", "B_Opa");
  m->B0pb = either(p, "B_0pb", "B_Opb");
  m->B0pn = either(p, "B_0pn", "B_Opn");
  m->wa = p.get_double("omega_a");
  m->wb = p.get_double("omega_b");
  m->wp = p.get_double("omega_p");
  m->alpha0 = p.get_double("alpha_0", 0.0);
  m->alpha1 = p.get_double("alpha_1", 0.0);
  return m;
}

}  // namespace tephra
