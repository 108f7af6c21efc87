#include "models/solid/ViscoScramJwl.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "core/base/Errors.h"
#include "models/eos/DensitySolve.h"
#include "models/eos/JwlLaw.h"

namespace tephra {

// The law of models/eos/JwlLaw.h with cv = Cv/rho0 (Cv is per unit volume).
SolidEosPoint ViscoScramJwl::jwl(double rho, double rho0, double T) const {
  const PointThermo t = jwl_point(A, B, R1, R2, om, rho0, Cv / rho0, rho, T);
  SolidEosPoint e;
  e.pressure = t.p;
  e.dp_drho = t.dp_drho;
  e.c2 = e.dp_drho;
  return e;
}

double ViscoScramJwl::jwl_density(double p, double rho0, double T) const {
  auto f = [&](double rho) { return jwl(rho, rho0, T).pressure - p; };
  auto fail = [&](const char* why) {
    std::ostringstream os;
    os.precision(17);
    os << "visco_scram JWL EOS: no density at p = " << p << " Pa, T = " << T << " K (" << why << ")";
    throw NumericalFailure(os.str());
  };
  // Upper end: p grows without bound in compression (the A term).
  double hi = rho0;
  for (int i = 0; f(hi) <= 0; ++i) {
    if (i > 200) fail("p(rho) stays below it in compression");
    hi *= 1.25;
  }
  // Lower end: the first sign change scanning down from hi (steps of 2 %
  // within a factor 100 of rho0, where the roots of the decks' constants
  // are far apart, then halving), so [lo, hi] holds the largest root.
  double lo = hi;
  for (int i = 0; f(lo) > 0; ++i) {
    if (i > 2300) fail("p(rho) stays above it in expansion");
    lo *= lo > 0.01 * rho0 ? 0.98 : 0.5;
  }
  if (f(lo) == 0) return lo;
  // The project's safeguarded Newton (models/eos/DensitySolve.h) inside the bracket.
  const double rho = solve_density_bracketed(
      [&](double r) {
        const SolidEosPoint e = jwl(r, rho0, T);
        return std::pair{e.pressure - p, e.dp_drho};
      },
      lo, hi, hi, 1e-15);
  if (!std::isfinite(rho)) fail("bracketed solve did not converge");
  return rho;
}

SolidEosPoint ViscoScramJwl::pressure(double rho, double rho0, double T, double p_ref) const {
  if (modified) {
    const double rho_ref = jwl_density(p_ref, rho0, T);
    if (rho < rho_ref) {
      const double K0 = rho_ref * jwl(rho_ref, rho0, T).dp_drho;
      const double r = std::pow(rho / rho_ref, K0 / p_ref);
      SolidEosPoint e;
      e.pressure = p_ref * r;
      e.dp_drho = K0 / rho * r;
      e.c2 = e.dp_drho;
      return e;
    }
  }
  return jwl(rho, rho0, T);
}

double ViscoScramJwl::density(double p, double rho0, double T, double p_ref) const {
  if (modified && p < p_ref) {
    const double rho_ref = jwl_density(p_ref, rho0, T);
    const double K0 = rho_ref * jwl(rho_ref, rho0, T).dp_drho;
    return rho_ref * std::pow(p / p_ref, p_ref / K0);
  }
  return jwl_density(p, rho0, T);
}

}  // namespace tephra
