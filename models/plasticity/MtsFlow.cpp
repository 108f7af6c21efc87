// Mechanical Threshold Stress flow stress, VT eq. 10.16-10.23:
//   σ_y = σ_a + (S_i σ_i + S_e σ_e) μ/μ_0,
//   S_x = [1 - ((k/b³) T/(g_0x μ) ln(ε̇_0x/ε̇))^{1/q_x}]^{1/p_x}     (10.17-10.18)
//   dσ_e/dε_p = θ(σ_e) = θ_0 [1 - F] + θ_IV F                          (10.19-10.20)
//   θ_0 = a_0 + a_1 ln ε̇ + a_2 sqrt(ε̇) - a_3 T                        (10.21)
//   F = tanh(α σ_e/σ_es)/tanh(α)                                         (10.22)
//   ln(σ_es/σ_0es) = (k/b³) T/(g_0es μ) ln(ε̇/ε̇_0es)                     (10.23)
// σ_e is a history variable (PlasticState::sigma_e, initially 0). The returns advance it
// over a step's Δε_p with evolve_internal_stress(): eq. 10.19 integrated at the step's ε̇_p and
// T by classical RK4 in ε_p, with n substeps so that n >= Δε_p L/0.1, L = θ_0 α/(σ_es tanh α)
// + |θ_IV| α/(σ_es tanh α) >= |∂θ/∂σ_e| (local error ~ (Δε_p L/n)^5/120 <= 1e-7 of the change).
// (An explicit σ_e,n + θ(σ_e,n) Δε_p overshoots by ~ ½ |∂θ/∂σ_e| Δε_p of σ_e's growth per step:
// 1.1 % in the flow stress of the adiCuMTS deck at its 0.0044 strain per step, session 15.)
// Hence ∂σ_y/∂ε_p = S_e (μ/μ_0) θ(σ_e,n+1).
// μ: the state's shear modulus (from the shear model, normally mts_shear with
// the same mu_0, D, T_0); when the state carries none, Varshni's μ(T) of eq.
// 7.5 from this model's own <mu_0>, <D>, <T_0>.
// The bases of S_x are clamped at 0 and 1 (no thermal activation beyond them).
// The low-temperature variant (<T_c>, <g_0i_c>, ...) is not implemented.
#include <algorithm>
#include <cmath>

#include "models/plasticity/FlowAd.h"

namespace tephra {
namespace {
class MtsFlow final : public FlowStressModel {
 public:
  double sigma_a, mu0, D, T0, kb3, g0i, g0e, edot0i, edot0e, pi, qi, pe, qe, sigma_i, a0, a1, a2, a3, thetaIV,
      alpha, edot_es0, g0es, sigma_es0;
  std::string type() const override { return "mechanical_threshold_stress"; }

  double mu_at(const PlasticState& s) const {
    if (s.shear_modulus > 0) return s.shear_modulus;
    return mu0 - D / (std::exp(T0 / s.temperature) - 1.0);
  }
  template <class S>
  S scale(const S& rate, const S& T, double mu, double g0, double edot0, double p, double q) const {
    using namespace ad;
    if (g0 <= 0 || edot0 <= 0) return S(1.0);  // no thermally activated barrier of this kind
    S x = S(kb3) * T / S(g0 * mu) * log(S(edot0) / rate);
    if (value(x) <= 0) return S(1.0);
    S base = S(1.0) - pow(x, 1.0 / q);
    if (value(base) <= 0) return S(0.0);
    return pow(base, 1.0 / p);
  }
  template <class S>
  S theta(const S& rate_in, const S& T, double mu, double sigma_e) const {
    using namespace ad;
    const S rate = floor_rate(rate_in);
    const S theta0 = S(a0) + S(a1) * log(rate) + S(a2) * sqrt(rate) - S(a3) * T;
    const S sigma_es = S(sigma_es0) * exp(S(kb3) * T / S(g0es * mu) * log(rate / S(edot_es0)));
    const S F = tanh(S(alpha) * S(sigma_e) / sigma_es) / S(std::tanh(alpha));
    return theta0 * (S(1.0) - F) + S(thetaIV) * F;
  }
  FlowStress evaluate(const PlasticState& s) const override {
    const double mu = mu_at(s);
    const double dse = ad::value(theta(ad::Dual(s.eps_p_rate), ad::Dual(s.temperature), mu, s.sigma_e));
    auto law = [&](const ad::Dual&, const ad::Dual& rate_in, const ad::Dual& T) {
      const ad::Dual rate = floor_rate(rate_in);
      const ad::Dual Si = sigma_i != 0 ? scale(rate, T, mu, g0i, edot0i, pi, qi) : ad::Dual(0.0);
      const ad::Dual Se = scale(rate, T, mu, g0e, edot0e, pe, qe);
      // σ_e depends on ε_p through its evolution law: seed ∂σ_e/∂ε_p = θ.
      ad::Dual se(s.sigma_e);
      se.d[0] = dse;
      return ad::Dual(sigma_a) + (Si * ad::Dual(sigma_i) + Se * se) * ad::Dual(mu / mu0);
    };
    return evaluate_flow_law(law, s);
  }
  double internal_stress_rate(const PlasticState& s) const override {
    return ad::value(theta(ad::Dual(s.eps_p_rate), ad::Dual(s.temperature), mu_at(s), s.sigma_e));
  }
  double evolve_internal_stress(const PlasticState& s, double dep) const override {
    if (!(dep > 0.0)) return s.sigma_e;
    const double mu = mu_at(s), T = s.temperature;
    const double rate = ad::value(floor_rate(ad::Dual(s.eps_p_rate)));
    auto th = [&](double se) { return ad::value(theta(ad::Dual(rate), ad::Dual(T), mu, se)); };
    // Lipschitz bound of θ in σ_e (header): |∂F/∂σ_e| <= α/(σ_es tanh α).
    const double theta0 = a0 + a1 * std::log(rate) + a2 * std::sqrt(rate) - a3 * T;
    const double sigma_es = sigma_es0 * std::exp(kb3 * T / (g0es * mu) * std::log(rate / edot_es0));
    const double L = (std::abs(theta0) + std::abs(thetaIV)) * alpha / (sigma_es * std::tanh(alpha));
    const int n = std::max(1, std::min(1000, int(std::ceil(dep * L / 0.1))));
    const double h = dep / n;
    double se = s.sigma_e;
    for (int k = 0; k < n; ++k) {
      const double k1 = th(se), k2 = th(se + 0.5 * h * k1), k3 = th(se + 0.5 * h * k2), k4 = th(se + h * k3);
      se += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    return se;
  }
};
}  // namespace

FlowStressModelP create_mts_flow(const ModelParameters& p, const SubModelContext&) {
  for (const char* low_T : {"T_c", "g_0i_c", "sigma_i_c", "g_0es_c", "sigma_es0_c", "a_0_c", "a_3_c"})
    if (p.has(low_T)) p.missing_feature(low_T, "the low-temperature variant of the MTS flow model");
  auto m = std::make_unique<MtsFlow>();
  m->sigma_a = p.get_double("sigma_a");
  m->mu0 = positive_parameter(p, "mu_0");
  m->D = p.get_double("D");
  m->T0 = p.get_double("T_0");
  m->kb3 = positive_parameter(p, "koverbcubed");
  m->g0i = p.get_double("g_0i");
  m->g0e = p.get_double("g_0e");
  m->edot0i = p.get_double("edot_0i");
  m->edot0e = p.get_double("edot_0e");
  m->pi = p.get_double("p_i");
  m->qi = p.get_double("q_i");
  m->pe = positive_parameter(p, "p_e");
  m->qe = positive_parameter(p, "q_e");
  m->sigma_i = p.get_double("sigma_i");
  if (m->sigma_i != 0 && m->g0i > 0 && m->edot0i > 0 && (m->pi <= 0 || m->qi <= 0))
    p.fail("p_i", "p_i and q_i must be positive when sigma_i, g_0i and edot_0i are");
  m->a0 = p.get_double("a_0");
  m->a1 = p.get_double("a_1");
  m->a2 = p.get_double("a_2");
  m->a3 = p.get_double("a_3");
  m->thetaIV = p.get_double("theta_IV");
  m->alpha = positive_parameter(p, "alpha");
  m->edot_es0 = positive_parameter(p, "edot_es0");
  m->g0es = positive_parameter(p, "g_0es");
  m->sigma_es0 = positive_parameter(p, "sigma_es0");
  return m;
}

}  // namespace tephra
