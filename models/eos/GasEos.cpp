// Gas-like EOS with a co-volume: hard-sphere gas and the
// Tait-Sun-Tao (TST) cubic. Formulas: Uintah/Vaango ICE EOS
// (HardSphereGas.cc, TST.cc); derivatives re-derived here.
#include <algorithm>
#include <cmath>
#include <utility>

#include "models/eos/DensitySolve.h"
#include "models/eos/EosModels.h"
#include "models/eos/PointEos.h"

namespace tephra {

namespace {

// Hard-sphere (Noble-Abel) gas with co-volume b [m^3/kg]:
//   p = (gamma - 1) rho cv T / (1 - b rho)
//   dp/drho|_T = (gamma - 1) cv T / (1 - b rho)^2,  dp/dT|_rho = (gamma - 1) rho cv / (1 - b rho)
//   rho(p, T) = p / ((gamma - 1) cv T + b p)        (closed form)
//   beta = (1 - b rho)/T
struct HardSphereGas {
  double gamma, cv, b;
  PointThermo point(double rho, double T) const {
    const double s = 1.0 / (1.0 - b * rho), r = (gamma - 1.0) * cv;
    return {r * rho * T * s, r * T * s * s, r * rho * s};
  }
  double density(double p, double T) const { return p / ((gamma - 1.0) * cv * T + b * p); }
  double heat_capacity(double, double, double) const { return cv; }
};

// TST (two-constant cubic, Uintah TST.cc), v = 1/rho:
//   p = (Gamma - 1) cv T/(v - b) - a/((v + u b)(v + w b))
//   dp/dv|_T = -p1/(v - b) + p2 (1/(v + u b) + 1/(v + w b)),  p1, p2 the two terms
//   dp/drho|_T = -v^2 dp/dv,   dp/dT|_rho = (Gamma - 1) cv/(v - b)
// rho(p, T): Uintah solves the cubic in v with the trigonometric formula and
// takes the largest real root (the gas branch), using the ICE material's
// gamma there but the EOS's Gamma in p(rho, T); here Gamma is used in both so
// that rho(p(rho, T), T) = rho, and the root is found by the bracketed Newton
// on rho in (0, 1/b).
struct Tst {
  double cv, a, b, u, w, Gamma;
  PointThermo point(double rho, double T) const {
    const double v = 1.0 / rho, d1 = v - b, d2 = v + u * b, d3 = v + w * b;
    const double p1 = (Gamma - 1.0) * cv * T / d1, p2 = a / (d2 * d3);
    return {p1 - p2, v * v * (p1 / d1 - p2 * (1.0 / d2 + 1.0 / d3)), (Gamma - 1.0) * cv / d1};
  }
  double density(double p, double T) const {
    const double rho_max = 1.0 / b;
    // Gas branch: start from the ideal-gas density and bracket upwards.
    const double guess = std::min(p / ((Gamma - 1.0) * cv * T), 0.5 * rho_max);
    return solve_density_bracketed(
        [&](double r) {
          const PointThermo t = point(r, T);
          return std::pair{t.p - p, t.dp_drho};
        },
        0.0, guess, rho_max * (1.0 - 1e-12));
  }
  double heat_capacity(double, double, double) const { return cv; }
};

}  // namespace

double eos_required(const ModelParameters& p, const char* name) { return p.get_double(name); }
double eos_positive(const ModelParameters& p, const char* name) {
  const double v = p.get_double(name);
  if (!(v > 0.0)) p.fail(name, std::string("<") + name + "> must be > 0");
  return v;
}

EquationOfStateP make_hard_sphere_gas(const ModelParameters& p, const EosMaterialConstants& c) {
  const double b = p.get_double("b");
  if (!(b >= 0.0)) p.fail("b", "hard_sphere_gas co-volume <b> must be >= 0");
  if (!(c.gamma > 1.0)) p.fail("gamma", "hard_sphere_gas needs gamma > 1");
  return make_point_eos("hard_sphere_gas", HardSphereGas{c.gamma, c.cv, b});
}

EquationOfStateP make_tst(const ModelParameters& p, const EosMaterialConstants& c) {
  Tst m{c.cv, p.get_double("a"), eos_positive(p, "b"), p.get_double("u"), p.get_double("w"), p.get_double("Gamma")};
  if (!(m.Gamma > 1.0)) p.fail("Gamma", "TST needs <Gamma> > 1");
  return make_point_eos("TST", m);
}

}  // namespace tephra
