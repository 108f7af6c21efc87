#include "models/solid/ViscoScramJwl.h"

#include <cmath>
#include <sstream>

#include "core/base/Errors.h"

namespace tephra {

SolidEosPoint ViscoScramJwl::jwl(double rho, double rho0, double T) const {
  const double V = rho0 / rho;
  const double P1 = A * std::exp(-R1 * V), P2 = B * std::exp(-R2 * V), P3 = om * Cv * T / V;
  SolidEosPoint e;
  e.pressure = P1 + P2 + P3;
  e.dp_drho = (R1 * rho0 * P1 + R2 * rho0 * P2) / (rho * rho) + om * Cv * T / rho0;
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
  // Newton from the upper end, bisection whenever a step leaves the bracket;
  // stops when the step or the bracket is below 1e-15 of rho.
  double x = hi;
  for (int i = 0; i < 500; ++i) {
    const SolidEosPoint e = jwl(x, rho0, T);
    double x1 = e.dp_drho > 0 ? x - (e.pressure - p) / e.dp_drho : 0.5 * (lo + hi);
    if (!(x1 > lo && x1 < hi)) x1 = 0.5 * (lo + hi);
    const double f1 = f(x1);
    if (f1 == 0) return x1;
    (f1 < 0 ? lo : hi) = x1;
    if (std::abs(x1 - x) <= 1e-15 * x1 || hi - lo <= 1e-15 * hi) return x1;
    x = x1;
  }
  fail("bracketed solve did not converge");
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
