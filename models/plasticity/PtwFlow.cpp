// Preston-Tonks-Wallace flow stress, VT eq. 10.24-10.28 (Preston, Tonks and
// Wallace, J. Appl. Phys. 93 (2003) 211):
//   thermal regime: σ_y = 2 [τ_s + α ln(1 - φ exp(-β - θ ψ/(α φ)))] μ,
//   shock regime (τ_y >= τ_s): σ_y = 2 τ_s μ,
//   α = (s_0 - τ_y)/d,  β = (τ_s - τ_y)/α,  φ = exp(β) - 1,
//   τ_s = max{s_0 - (s_0 - s_∞) erf[κ T̂ ln(γ ξ̇/ε̇)], s_0 (ε̇/(γ ξ̇))^{s_1}},
//   τ_y = max{y_0 - (y_0 - y_∞) erf[κ T̂ ln(γ ξ̇/ε̇)], min{y_1 (ε̇/(γ ξ̇))^{y_2}, s_0 (ε̇/(γ ξ̇))^{s_1}}},
//   ξ̇ = ½ (4πρ/(3M))^{1/3} (μ/ρ)^{1/2},  T̂ = T/T_m.
// Erratum resolved (inventory ch. 10): (10.24) prints θ ε̇_p; PTW's law uses the
// plastic strain ψ = ε_p, as here. Tags: <p> is d, <beta> is s_1, <M> the
// atomic mass in amu. μ and T_m come from the state (ptw_shear and a melting
// model); <G0>, <alpha>, <alphap> (schema: optional) are PTW's shear-modulus
// constants, accepted and unused here (ptw_shear holds them). d = 0 is the
// Voce limit τ = τ_s - (τ_s - τ_y) exp(-θψ/(τ_s - τ_y)) of (10.24).
#include "models/plasticity/FlowAd.h"

namespace tephra {
namespace {
constexpr double kAtomicMassUnit = 1.66053906660e-27;  // [kg], CODATA 2018

class PtwFlow final : public FlowStressModel {
 public:
  double theta, d, s0, sinf, kappa, gamma, y0, yinf, y1, y2, s1, M;
  std::string type() const override { return "preston_tonks_wallace"; }
  template <class S>
  S tau(const S& psi, const S& rate_in, const S& T, double mu, double rho, double Tm) const {
    using namespace ad;
    const S rate = floor_rate(rate_in);
    const double xi_dot = 0.5 * std::cbrt(4.0 * M_PI * rho / (3.0 * M * kAtomicMassUnit)) * std::sqrt(mu / rho);
    const S ratio = rate / S(gamma * xi_dot);  // ε̇/(γ ξ̇)
    const S arg = S(kappa) * T / S(Tm) * log(S(1.0) / ratio);
    const S ts = max(S(s0) - S(s0 - sinf) * erf(arg), S(s0) * pow(ratio, s1));
    const S ty = max(S(y0) - S(y0 - yinf) * erf(arg), min(S(y1) * pow(ratio, y2), S(s0) * pow(ratio, s1)));
    if (value(ty) >= value(ts)) return ts;  // shock regime
    if (d == 0.0)  // the d -> 0 limit of (10.24): Voce, τ = τ_s - (τ_s - τ_y) exp(-θψ/(τ_s - τ_y))
      return ts - (ts - ty) * exp(-S(theta) * psi / (ts - ty));
    const S a = (S(s0) - ty) / S(d);
    const S b = (ts - ty) / a;
    const S phi = exp(b) - S(1.0);
    return ts + a * log(S(1.0) - phi * exp(-b - S(theta) * psi / (a * phi)));
  }
  FlowStress evaluate(const PlasticState& s) const override {
    if (!(s.shear_modulus > 0 && s.density > 0 && s.melt_temperature > 0))
      return {};  // melted (μ = 0) or no state: no strength
    if (s.temperature >= s.melt_temperature) return {};
    auto law = [&](const ad::Dual& ep, const ad::Dual& rate, const ad::Dual& T) {
      return ad::Dual(2.0 * s.shear_modulus) * tau(ep, rate, T, s.shear_modulus, s.density, s.melt_temperature);
    };
    return evaluate_flow_law(law, s);
  }
};
}  // namespace

FlowStressModelP create_ptw_flow(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<PtwFlow>();
  m->theta = p.get_double("theta");
  m->d = p.get_double("p");  // d = 0 (MaterialData/PTWPlasticTa.xml): the Voce limit
  if (m->d < 0) p.fail("p", "must be non-negative");
  m->s0 = positive_parameter(p, "s0");
  m->sinf = p.get_double("sinf");
  m->kappa = p.get_double("kappa");
  m->gamma = positive_parameter(p, "gamma");
  m->y0 = p.get_double("y0");
  m->yinf = p.get_double("yinf");
  m->y1 = p.get_double("y1");
  m->y2 = p.get_double("y2");
  m->s1 = p.get_double("beta");
  m->M = positive_parameter(p, "M");
  for (const char* shear : {"G0", "alpha", "alphap"}) (void)p.get_double(shear, 0.0);
  return m;
}

}  // namespace tephra
