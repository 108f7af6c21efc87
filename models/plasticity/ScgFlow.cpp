// Steinberg-Cochran-Guinan(-Lund) flow stress, VT eq. 10.4-10.7:
//   σ_y = [σ_a f(ε_p) + σ_t(ε̇_p, T)] μ(p, T)/μ_0,
//   σ_a f = min(σ_0 [1 + β (ε_p + ε_p0)]^n, Y_max)                       (10.5)
//   ε̇_p = [ (1/C_1) exp(2U_k/(k_b T) (1 - σ_t/σ_p)²) + C_2/σ_t ]^{-1}   (10.6)
//   C_1 = ρ_d L_d a b² ν/(2 w²),  C_2 = D/(ρ_d b²)                         (10.7)
// σ_t is found by bisection on (10.6) in [0, σ_p] (the rate is monotone in
// σ_t); its derivatives follow from the implicit-function theorem. When the
// deck gives none of the thermal (Steinberg-Lund) parameters, σ_t = 0: the
// rate-independent SCG model of 1980, which is what the MaterialData/SCG*.xml
// files describe (Vaango would require <energy_to_form_kink_pair> etc.).
// μ: the state's shear modulus (scg_shear); without one, eq. 7.6 from this
// model's <mu_0>, <A>, <B>. T_m: the state's; without one, eq. 13.1 from
// <T_m0>, <Gamma_0>, <a>. Above T_m the material has no strength (μ = 0).
#include "models/plasticity/FlowAd.h"

namespace tephra {
namespace {
class ScgFlow final : public FlowStressModel {
 public:
  double mu0, A, B, sigma0, beta, n, eps0, Ymax, Tm0, Gamma0, a;
  bool thermal = false;
  double C1 = 0, C2 = 0, Uk = 0, kb = 0, sigma_p = 0;
  std::string type() const override { return "steinberg_cochran_guinan"; }

  // ε̇(σ_t, T) of eq. 10.6 and its partials.
  struct Rate { double rate, d_tau, d_T; };
  Rate rate_of(double tau, double T) const {
    const double u = 1.0 - tau / sigma_p;
    const double X = 2.0 * Uk / (kb * T) * u * u;
    const double e = std::exp(X) / C1;
    const double Dn = e + (tau > 0 ? C2 / tau : INFINITY);
    const double D_tau = e * (-4.0 * Uk * u / (kb * T * sigma_p)) - C2 / (tau * tau);
    const double D_T = e * (-X / T);
    return {1.0 / Dn, -D_tau / (Dn * Dn), -D_T / (Dn * Dn)};
  }
  // σ_t and its derivatives (∂/∂ε̇, ∂/∂T).
  std::array<double, 3> thermal_stress(double rate, double T) const {
    if (!thermal || rate <= 0) return {0.0, 0.0, 0.0};
    if (rate >= rate_of(sigma_p, T).rate) return {sigma_p, 0.0, 0.0};
    double lo = 0.0, hi = sigma_p;
    for (int it = 0; it < 200 && hi - lo > 1e-14 * sigma_p; ++it) {
      const double mid = 0.5 * (lo + hi);
      (rate_of(mid, T).rate < rate ? lo : hi) = mid;
    }
    const double tau = 0.5 * (lo + hi);
    const Rate r = rate_of(tau, T);
    return {tau, 1.0 / r.d_tau, -r.d_T / r.d_tau};
  }
  FlowStress evaluate(const PlasticState& s) const override {
    const double eta = s.density0 > 0 ? s.eta() : 1.0;
    const double Tm = s.melt_temperature > 0
                          ? s.melt_temperature
                          : Tm0 * std::exp(2.0 * a * (1.0 - 1.0 / eta)) * std::pow(eta, 2.0 * (Gamma0 - a - 1.0 / 3.0));
    if (s.temperature >= Tm) return {};
    const bool own_mu = !(s.shear_modulus > 0);
    const double mu = own_mu ? mu0 * (1.0 + A * s.pressure / std::cbrt(eta) - B * (s.temperature - 300.0))
                             : s.shear_modulus;
    const double dmu_dT = own_mu ? -mu0 * B : 0.0;
    const double base = 1.0 + beta * (s.eps_p + eps0);
    const double hard = sigma0 * std::pow(base, n);
    const bool capped = hard >= Ymax;
    const double sa = capped ? Ymax : hard;
    const double dsa = capped ? 0.0 : sigma0 * n * beta * std::pow(base, n - 1.0);
    const auto [st, dst_rate, dst_T] = thermal_stress(s.eps_p_rate, s.temperature);
    const double r = mu / mu0;
    return {(sa + st) * r, dsa * r, dst_rate * r, dst_T * r + (sa + st) * dmu_dT / mu0};
  }
};
}  // namespace

FlowStressModelP create_scg_flow(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<ScgFlow>();
  m->mu0 = positive_parameter(p, "mu_0");
  m->A = p.get_double("A");
  m->B = p.get_double("B");
  m->sigma0 = p.get_double("sigma_0");
  m->beta = p.get_double("beta");
  m->n = p.get_double("n");
  m->eps0 = p.get_double("epsilon_p0");
  m->Ymax = p.get_double("Y_max");
  m->Tm0 = positive_parameter(p, "T_m0");
  m->Gamma0 = p.get_double("Gamma_0");
  m->a = p.get_double("a");
  static const char* const kThermal[] = {"C1", "C2", "dislocation_density", "length_of_dislocation_segment",
                                         "distance_between_Peierls_valleys", "length_of_Burger_vector",
                                         "Debye_frequency", "width_of_kink_loop", "drag_coefficient",
                                         "energy_to_form_kink_pair", "Boltzmann_constant", "Peierls_stress"};
  for (const char* t : kThermal) m->thermal = m->thermal || p.has(t);
  if (m->thermal) {
    m->C1 = p.get_double("C1", 0.0);
    m->C2 = p.get_double("C2", 0.0);
    if (m->C1 == 0.0 || m->C2 == 0.0) {  // eq. 10.7 from the dislocation constants
      const double rho = positive_parameter(p, "dislocation_density");
      const double L = positive_parameter(p, "length_of_dislocation_segment");
      const double aa = positive_parameter(p, "distance_between_Peierls_valleys");
      const double b = positive_parameter(p, "length_of_Burger_vector");
      const double nu = positive_parameter(p, "Debye_frequency");
      const double w = positive_parameter(p, "width_of_kink_loop");
      const double D = positive_parameter(p, "drag_coefficient");
      m->C1 = rho * L * aa * b * b * nu / (2.0 * w * w);
      m->C2 = D / (rho * b * b);
    }
    m->Uk = positive_parameter(p, "energy_to_form_kink_pair");
    m->kb = positive_parameter(p, "Boltzmann_constant");
    m->sigma_p = positive_parameter(p, "Peierls_stress");
  }
  return m;
}

}  // namespace tephra
