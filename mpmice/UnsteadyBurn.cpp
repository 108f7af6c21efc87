// The unsteady WSB burn rate (mpmice/UnsteadyBurn.h).
#include "mpmice/UnsteadyBurn.h"

#include <cmath>
#include <sstream>

#include "core/base/Errors.h"

namespace tephra {

double steady_surface_gradient(const WsbParams& q, const WsbState& w, double T0) {
  return (w.surface_temperature - T0) * w.mass_flux * q.Cp / q.kc;
}

double unsteady_condensed_flux(const WsbParams& q, double beta, double Ts, double vc) {
  const double b = 2 * q.kc * beta / q.Qc;
  const double c = 2 * q.Ac * q.R * q.kc * Ts * Ts * std::exp(-q.Ec / (q.R * Ts)) / (q.Ec * q.Qc * vc);
  const double disc = b * b - 4 * c;
  if (!(disc >= 0)) {
    std::ostringstream os;
    os << "unsteady WSB burn rate: no mass flux at surface temperature " << Ts << " K and gradient " << beta
       << " K/m (b^2 - 4c = " << disc << " < 0; the time step is too large for the unsteady burn rate)";
    throw NumericalFailure(os.str());
  }
  return 2 * c / (std::sqrt(disc) + b);
}

UnsteadyBurnRate unsteady_burn_rate(const UnsteadyBurnParams& prm, double p, double T0, double vc, double dt,
                                    UnsteadyBurnState& s) {
  const WsbParams& q = prm.wsb;
  const WsbState w = wsb_burn_rate(q, p, T0, vc);
  const double beta_ss = steady_surface_gradient(q, w, T0);
  UnsteadyBurnRate out;
  out.steady_flux = w.mass_flux;
  if (!s.has_history()) {
    s.beta = beta_ss;
    s.Ts = w.surface_temperature;
    out.mass_flux = w.mass_flux;
    return out;
  }
  // n = Nc tau_c/dt, tau_c = kc/(Cp vc m*^2).
  const double n = prm.Nc * q.kc / (q.Cp * vc) / (dt * w.mass_flux * w.mass_flux);
  const double nT = prm.Ng * n;
  s.beta = n > 1 ? s.beta + (beta_ss - s.beta) / n : beta_ss;
  s.Ts = nT > 1 ? s.Ts + (w.surface_temperature - s.Ts) / nT : w.surface_temperature;
  double m = unsteady_condensed_flux(q, s.beta, s.Ts, vc);
  if (prm.Bm != 1.0) m = w.mass_flux * std::pow(m / w.mass_flux, prm.Bm);
  out.mass_flux = m;
  return out;
}

}  // namespace tephra
