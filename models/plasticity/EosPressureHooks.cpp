// MPMICE pressure hooks of the metal-plasticity EOS sub-models (PlasticityEos.h).
#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "models/plasticity/PlasticityEos.h"

namespace tephra {

EosPressurePoint eos_pressure_at_density(const PlasticityEos& eos, double rho, double rho0) {
  const double J = rho0 / rho;
  const EosResult r = eos.at_volume_ratio(J), ref = eos.at_volume_ratio(1.0);
  EosPressurePoint e;
  e.pressure = -(r.p - ref.p);          // gauge, compression positive
  e.dp_drho = r.dp_dJ * rho0 / (rho * rho);  // dp̄/dρ = -(dp/dJ)(dJ/dρ), dJ/dρ = -ρ0/ρ²
  e.c2 = e.dp_drho;
  return e;
}

double eos_density_at_pressure(const PlasticityEos& eos, double p_gauge, double rho0) {
  // g(y) = p̄(J = e^y) - p_gauge, decreasing in y where dp/dJ > 0. Bracket by doubling |y|.
  auto g = [&](double y, double* dg) {
    const double J = std::exp(y);
    const EosResult r = eos.at_volume_ratio(J), ref = eos.at_volume_ratio(1.0);
    if (dg) *dg = -r.dp_dJ * J;
    return -(r.p - ref.p) - p_gauge;
  };
  auto fail = [&](const std::string& why) {
    std::ostringstream m;
    m << "equation_of_state '" << eos.type() << "': no density with gauge pressure " << p_gauge << " Pa (" << why
      << ")";
    throw NumericalFailure(m.str());
  };
  double g0 = g(0.0, nullptr);
  if (g0 == 0.0) return rho0;
  // g0 > 0: p̄(1) > p_gauge, the answer expands (y > 0); otherwise it compresses (y < 0).
  // Bracket: y_k = ±1e-3 2^k (k < 15, |y| < 17) until g changes sign; g(lo) > 0 > g(hi).
  const double dir = g0 > 0.0 ? 1.0 : -1.0;
  double lo = 0.0, hi = 0.0, y_prev = 0.0;
  bool found = false;
  for (double step = 1e-3; step < 20.0 && !found; step *= 2.0) {
    const double y = dir * step;
    const double gy = g(y, nullptr);
    if (!std::isfinite(gy)) break;
    if ((gy > 0.0) != (g0 > 0.0) || gy == 0.0) {
      found = true;
      lo = std::min(y_prev, y);
      hi = std::max(y_prev, y);
    }
    y_prev = y;
  }
  if (!found) fail("outside the range of p(J)");
  // Safeguarded Newton on [lo, hi] (g(lo) > 0 > g(hi)).
  double y = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    double dg = 0.0;
    const double gy = g(y, &dg);
    if (gy == 0.0) break;
    (gy > 0.0 ? lo : hi) = y;
    double next = (dg < 0.0) ? y - gy / dg : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - y) <= 1e-15 * std::max(1.0, std::abs(y))) {
      y = next;
      break;
    }
    y = next;
  }
  return rho0 / std::exp(y);
}

}  // namespace tephra
