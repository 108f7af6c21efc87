// Explosive EOS: JWL (Jones-Wilkins-Lee, with a thermal term) and JWLC (the
// JWL++ form with a cold C term, no temperature). Formulas: Uintah/Vaango ICE
// (JWL.cc, JWLC.cc); derivatives re-derived here.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "models/eos/DensitySolve.h"
#include "models/eos/EosModels.h"
#include "models/eos/JwlLaw.h"
#include "models/eos/PointEos.h"

namespace tephra {

namespace {

// JWL (models/eos/JwlLaw.h), cv = the material's specific heat.
// rho(p, T): bracketed Newton from [0, 1.001 p/(om cv T)] upwards (Uintah's
// starting bracket; p(0) = 0 < p).
struct Jwl {
  double A, B, R1, R2, om, rho0, cv;
  PointThermo point(double rho, double T) const { return jwl_point(A, B, R1, R2, om, rho0, cv, rho, T); }
  double density(double p, double T) const {
    return solve_density_bracketed(
        [&](double r) {
          const PointThermo t = point(r, T);
          return std::pair{t.p - p, t.dp_drho};
        },
        0.0, std::max(1.001 * p / (om * cv * T), 1e-3 * rho0));
  }
  double heat_capacity(double, double, double) const { return cv; }
};

// JWLC (Souers' JWL++ product EOS), temperature independent:
//   p = A exp(-R1 V) + B exp(-R2 V) + C (rho/rho0)^(1 + om)
//   dp/drho = (R1 V P1 + R2 V P2)/rho + (1 + om) P3/rho,  dp/de = 0
struct Jwlc {
  double A, B, C, R1, R2, om, rho0;
  // An absent product (tiny_rho, V = rho0/rho ~ 700 for ANFO at 1 atm) has
  // R V far beyond the underflow of exp: exp(-x) is exactly 0 in IEEE double
  // for x > 745.14, and libm reaches that 0 through its slow underflow path
  // (errno, xflow). exp_neg returns the same 0 without the call.
  static double exp_neg(double x) { return x > 746.0 ? 0.0 : std::exp(-x); }
  PointThermo point(double rho, double) const {
    const double V = rho0 / rho, P1 = A * exp_neg(R1 * V), P2 = B * exp_neg(R2 * V);
    const double P3 = C * std::pow(rho / rho0, 1.0 + om);
    return {P1 + P2 + P3, (R1 * V * P1 + R2 * V * P2 + (1.0 + om) * P3) / rho, 0.0};
  }
  // rho(p): Newton on g(x) = ln p(rho0 e^x) - ln p_target in x = ln(rho/rho0),
  //   g'(x) = rho (dp/drho) / p,
  // from x0 = ln(p_target/C)/(1 + om), where the C term alone gives p_target
  // (exact when the exponentials are negligible, rho << rho0: one step). In
  // these variables the C term is linear and the exponential terms are
  // smooth and concave, so Newton converges in a few steps over the whole
  // range (the plain bracketed Newton on rho from [0, rho0] needs 10-40
  // evaluations at the low pressures of an absent product). Safeguard: the
  // bracket [lo, hi] of the iterates with g < 0 and g > 0; a step leaving it
  // (or a non-finite one) is a bisection once both ends are known, and with
  // A, B >= 0 x0 is an upper end (p(x0) >= C e^{(1+om) x0} = p_target).
  // Stops when |dx| <= 1e-10 (then the next Newton correction, ~ dx^2, is
  // below round-off). Anything unusual (p <= 0, C <= 0, no convergence in
  // 60 steps) falls back to the bracketed solve of DensitySolve.h.
  double density(double p, double T) const {
    if (p > 0.0 && C > 0.0 && std::isfinite(p)) {
      const double lnp = std::log(p);
      double x = (lnp - std::log(C)) / (1.0 + om);
      double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
      for (int it = 0; it < 60; ++it) {
        const double rho = rho0 * std::exp(x);
        const PointThermo t = point(rho, T);
        const double g = std::log(t.p) - lnp;
        if (g == 0.0) return rho;
        if (g > 0.0) hi = std::min(hi, x);
        else lo = std::max(lo, x);
        double xn = x - g * t.p / (rho * t.dp_drho);
        if (!(std::isfinite(xn) && xn > lo && xn < hi)) {
          if (!(std::isfinite(lo) && std::isfinite(hi))) break;
          xn = 0.5 * (lo + hi);
        }
        const double dx = xn - x;
        x = xn;
        if (std::abs(dx) <= 1e-10) return rho0 * std::exp(x);
      }
    }
    return solve_density_bracketed(
        [&](double r) {
          const PointThermo t = point(r, T);
          return std::pair{t.p - p, t.dp_drho};
        },
        0.0, rho0);
  }
  double heat_capacity(double, double, double) const { return 1.0; }  // unused: dp/dT = 0
};

}  // namespace

EquationOfStateP make_jwl(const ModelParameters& p, const EosMaterialConstants& c) {
  Jwl m{eos_positive(p, "A"), p.get_double("B"), eos_positive(p, "R1"), eos_positive(p, "R2"),
        eos_positive(p, "om"), eos_positive(p, "rho0"), c.cv};
  // Vaango's JWL reads neither <Cv> nor <C>; the thermal term uses the
  // material's <specific_heat>. The EOSData files carry Tarver's volumetric
  // Cv [Pa/K] = rho0 cv: accepted when it agrees with rho0 * specific_heat
  // (1 %), otherwise the deck contradicts itself.
  if (p.has("Cv")) {
    const double Cv = p.get_double("Cv");
    if (!(std::abs(Cv - m.rho0 * m.cv) <= 0.01 * m.rho0 * m.cv))
      p.fail("Cv", "JWL <Cv> = " + std::to_string(Cv) + " Pa/K disagrees with rho0 * specific_heat = " +
                       std::to_string(m.rho0 * m.cv) + " (Vaango's JWL uses specific_heat and ignores <Cv>)");
  }
  return make_point_eos("JWL", m);
}

EquationOfStateP make_jwlc(const ModelParameters& p, const EosMaterialConstants&) {
  Jwlc m{eos_positive(p, "A"), p.get_double("B"), p.get_double("C"), eos_positive(p, "R1"),
         eos_positive(p, "R2"), eos_positive(p, "om"), eos_positive(p, "rho0")};
  return make_point_eos("JWLC", m);
}

}  // namespace tephra
