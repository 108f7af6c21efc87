// WSB steady burn rate (mpmice/SteadyBurn.h).
#include "mpmice/SteadyBurn.h"

#include <cmath>
#include <stdexcept>

namespace tephra {

namespace {

struct WsbGroups {
  double C1, C2, C3, C4, C5, Ec_R;
};

WsbGroups groups(const WsbParams& q, double p, double T0, double vc) {
  WsbGroups g;
  g.C1 = q.Ac * q.R * q.kc / (q.Ec * q.Cp * vc);
  g.C2 = T0 + q.Qc / (2 * q.Cp);
  g.C3 = 4 * q.kg * q.Bg * q.W * q.W * p * p / (q.Cp * q.R * q.R);
  g.C4 = T0 + q.Qc / q.Cp;
  g.C5 = q.Qg * g.C3 / q.Cp;
  g.Ec_R = q.Ec / q.R;
  return g;
}

// Condensed phase: m(Ts), Ts > C2.
double mass_flux(const WsbGroups& g, double Ts) { return std::sqrt(g.C1 * Ts * Ts / (Ts - g.C2) * std::exp(-g.Ec_R / Ts)); }

// Gas phase: F(Ts) = Ts of the flux m(Ts).
double F(const WsbGroups& g, double Ts) {
  const double m = mass_flux(g, Ts);
  const double d = std::sqrt(m * m + g.C3) + m;
  return g.C4 + g.C5 / (d * d);
}

}  // namespace

double wsb_residual(const WsbParams& prm, double p, double T0, double vc, double Ts) {
  const WsbGroups g = groups(prm, p, T0, vc);
  return Ts - F(g, Ts);
}

WsbState wsb_burn_rate(const WsbParams& prm, double p, double T0, double vc) {
  if (!(p > 0 && T0 > 0 && vc > 0)) throw std::invalid_argument("wsb_burn_rate: p, T0 and vc must be > 0");
  const WsbGroups g = groups(prm, p, T0, vc);
  // Bracket: g(C4) = C4 - F(C4) < 0 (F > C4); F is bounded, so doubling the
  // distance above C4 reaches g > 0.
  double lo = g.C4, hi = g.C4 + 100.0;
  while (hi - F(g, hi) <= 0) {
    hi = g.C4 + 2 * (hi - g.C4);
    if (hi > 1e6) throw std::runtime_error("wsb_burn_rate: no surface temperature below 1e6 K");
  }
  for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (mid - F(g, mid) < 0 ? lo : hi) = mid;
  }
  WsbState s;
  s.surface_temperature = 0.5 * (lo + hi);
  s.mass_flux = mass_flux(g, s.surface_temperature);
  return s;
}

}  // namespace tephra
