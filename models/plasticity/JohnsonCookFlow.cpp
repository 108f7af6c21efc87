// Johnson-Cook flow stress, VT eq. 10.2-10.3:
//   σ_y = [A + B ε_p^n] [1 + C ln ε̇*] [1 - T*^m],
//   ε̇* = ε̇_p/ε̇_0,  T* = (T - T_r)/(T_m - T_r).
// Choices (documented in docs/models/plasticity.md): ε̇* < 1 uses ε̇* = 1 (no
// rate softening below the reference rate, and no ln 0); T* < 0 uses m = 1
// (inventory ch. 10); T* >= 1 (melted) gives σ_y = 0.
// Vaango defaults (JohnsonCookFlow.cc): T_r = 298 K, T_m = 1793 K, epdot_0 = 1/s.
#include "models/plasticity/FlowAd.h"

namespace tephra {
namespace {
class JohnsonCookFlow final : public FlowStressModel {
 public:
  double A, B, C, n, m, Tr, Tm, epdot0;
  std::string type() const override { return "johnson_cook"; }
  template <class S>
  S law(const S& ep, const S& rate, const S& T) const {
    using namespace ad;
    const S strain = ep.v > 0 ? S(A) + S(B) * pow(ep, n) : S(A);
    S rate_star = rate / S(epdot0);
    const S rate_part = value(rate_star) > 1.0 ? S(1.0) + S(C) * log(rate_star) : S(1.0);
    const S Tstar = (T - S(Tr)) / S(Tm - Tr);
    if (value(Tstar) >= 1.0) return S(0.0);
    const S temp_part = value(Tstar) < 0.0 ? S(1.0) - Tstar : S(1.0) - pow(Tstar, m);
    return strain * rate_part * temp_part;
  }
  FlowStress evaluate(const PlasticState& s) const override {
    return evaluate_flow_law([this](auto&& a, auto&& b, auto&& c) { return law(a, b, c); }, s);
  }
};
}  // namespace

FlowStressModelP create_johnson_cook_flow(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<JohnsonCookFlow>();
  m->A = p.get_double("A");
  m->B = p.get_double("B");
  m->C = p.get_double("C");
  m->n = p.get_double("n");
  m->m = p.get_double("m");
  m->Tr = p.get_double("T_r", 298.0);
  m->Tm = p.get_double("T_m", 1793.0);
  m->epdot0 = p.get_double("epdot_0", 1.0);
  if (!(m->Tm > m->Tr)) p.fail("T_m", "must exceed T_r");
  if (!(m->epdot0 > 0)) p.fail("epdot_0", "must be positive");
  return m;
}

}  // namespace tephra
