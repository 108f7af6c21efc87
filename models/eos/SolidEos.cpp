// Condensed-phase EOS: Murnaghan, Birch-Murnaghan (3rd order), linear
// Gruneisen-type, Tillotson. Formulas: Uintah/Vaango ICE (Murnaghan.cc,
// BirchMurnaghan.cc, Gruneisen.cc, Tillotson.cc); derivatives re-derived here.
// In Murnaghan and Birch-Murnaghan, <K> is a compressibility [1/Pa] (the
// inverse bulk modulus), as in Vaango.
#include <algorithm>
#include <cmath>
#include <utility>

#include "models/eos/DensitySolve.h"
#include "models/eos/EosModels.h"
#include "models/eos/PointEos.h"

namespace tephra {

namespace {

// Murnaghan (temperature independent), x = rho/rho0:
//   rho >= rho0: p = P0 + ((x^n - 1)/(n K)),   dp/drho = x^(n-1)/(K rho0)
//   rho <  rho0: p = P0 x^(1/(K P0)),          dp/drho = x^(1/(K P0) - 1)/(K rho0)
// (the expansion branch keeps p > 0); inverse in closed form:
//   p >= P0: rho = rho0 (n K (p - P0) + 1)^(1/n),  p < P0: rho = rho0 (p/P0)^(K P0).
struct Murnaghan {
  double n, K, rho0, P0;
  PointThermo point(double rho, double) const {
    const double x = rho / rho0;
    if (rho >= rho0) return {P0 + (std::pow(x, n) - 1.0) / (n * K), std::pow(x, n - 1.0) / (K * rho0), 0.0};
    const double m = 1.0 / (K * P0);
    return {P0 * std::pow(x, m), std::pow(x, m - 1.0) / (K * rho0), 0.0};
  }
  double density(double p, double) const {
    if (p >= P0) return rho0 * std::pow(n * K * (p - P0) + 1.0, 1.0 / n);
    return rho0 * std::pow(p / P0, K * P0);
  }
  double heat_capacity(double, double, double) const { return 1.0; }
};

// Birch-Murnaghan, 3rd order, x = rho/rho0 (Vaango BirchMurnaghan.cc, K = 1/K0, n = K0'):
//   rho >= rho0: p = P0 + 3/(2K) (x^(7/3) - x^(5/3)) (1 + 3/4 (n - 4)(x^(2/3) - 1))
//   rho <  rho0: the Murnaghan expansion branch above.
// dp/drho = (1/rho0) dp/dx with
//   dp/dx = 3/(2K) [ (7/3 x^(4/3) - 5/3 x^(2/3)) (1 + 3/4 (n-4)(x^(2/3) - 1))
//                    + (x^(7/3) - x^(5/3)) (n - 4)/2 x^(-1/3) ].
// Difference from Vaango: Vaango's compression branch has no P0 (p jumps by
// P0 at rho0 and rho(p) is not the inverse of p(rho) for p just above P0);
// the P0 here makes p continuous and the round trip exact. rho(p >= P0) by
// the bracketed Newton. <useSpecificHeatModel> true is unimplemented in
// Vaango as well (MissingFeature).
struct BirchMurnaghan {
  double n, K, rho0, P0;
  PointThermo point(double rho, double T) const {
    if (rho < rho0) return Murnaghan{n, K, rho0, P0}.point(rho, T);
    const double x = rho / rho0, x13 = std::cbrt(x), x23 = x13 * x13;
    const double x53 = x * x23, x73 = x53 * x23;
    const double f = 1.0 + 0.75 * (n - 4.0) * (x23 - 1.0);
    const double dpdx = 1.5 / K * ((7.0 / 3.0 * x * x13 - 5.0 / 3.0 * x23) * f + (x73 - x53) * 0.5 * (n - 4.0) / x13);
    return {P0 + 1.5 / K * (x73 - x53) * f, dpdx / rho0, 0.0};
  }
  double density(double p, double T) const {
    if (p < P0) return Murnaghan{n, K, rho0, P0}.density(p, T);
    return solve_density_bracketed(
        [&](double r) {
          const PointThermo t = point(r, T);
          return std::pair{t.p - p, t.dp_drho};
        },
        rho0, 1.1 * rho0);
  }
  double heat_capacity(double, double, double) const { return 1.0; }
};

// Linear Gruneisen-type solid (Vaango Gruneisen.cc):
//   p = P0 + A (rho/rho0 - 1) + B (T - T0),  dp/drho = A/rho0,  dp/dT = B (dp/de = B/cv)
//   rho(p, T) = rho0 (1 + ((p - P0) - B (T - T0))/A)
struct Gruneisen {
  double A, B, rho0, T0, P0, cv;
  PointThermo point(double rho, double T) const { return {P0 + A * (rho / rho0 - 1.0) + B * (T - T0), A / rho0, B}; }
  double density(double p, double T) const { return rho0 * (1.0 + ((p - P0) - B * (T - T0)) / A); }
  double heat_capacity(double, double, double) const { return cv; }
};

// Tillotson as Vaango implements it (Tillotson.cc): temperature independent,
// the specific energy frozen at E = 1.034777e-5 Es (Vaango's constant),
// eta = rho/rho0, mu = eta - 1, g(rho) = rho/(E/(E0 eta^2) + 1) = rho^3/(c + rho^2), c = E rho0^2/E0:
//   eta >= 1: p = a E rho + b E g + A mu + B mu^2
//   eta <  1: p = a E rho + b E g X,  X = exp(-alpha (1/eta - 1)^2)
//             (Vaango drops the A mu exp(-beta(1/eta - 1)) term, so <beta> and
//             <Esp> are read but do not enter)
//   g' = (3 rho^2 (c + rho^2) - 2 rho^4)/(c + rho^2)^2,  X' = 2 alpha (rho0/rho - 1)(rho0/rho^2) X
//   dp/drho = a E + b E g' + A/rho0 + 2 B mu/rho0   or   a E + b E (g' X + g X').
// rho(p) by the bracketed Newton (Vaango: damped Newton from the old rho).
struct Tillotson {
  double a, b, A, B, E0, Es, alpha, rho0;
  PointThermo point(double rho, double) const {
    const double E = 1.034777e-5 * Es, c = E * rho0 * rho0 / E0, r2 = rho * rho;
    const double g = rho * r2 / (c + r2), dg = (3.0 * r2 * (c + r2) - 2.0 * r2 * r2) / ((c + r2) * (c + r2));
    const double mu = rho / rho0 - 1.0;
    if (mu >= 0) return {a * E * rho + b * E * g + A * mu + B * mu * mu, a * E + b * E * dg + A / rho0 + 2.0 * B * mu / rho0, 0.0};
    const double s = rho0 / rho - 1.0, X = std::exp(-alpha * s * s), dX = 2.0 * alpha * s * rho0 / r2 * X;
    return {a * E * rho + b * E * g * X, a * E + b * E * (dg * X + g * dX), 0.0};
  }
  double density(double p, double T) const {
    return solve_density_bracketed(
        [&](double r) {
          const PointThermo t = point(r, T);
          return std::pair{t.p - p, t.dp_drho};
        },
        0.0, rho0);
  }
  double heat_capacity(double, double, double) const { return 1.0; }
};

}  // namespace

namespace {
double murnaghan_K(const ModelParameters& p) {
  // MurnaghanEOSPBX9501.xml (Vaango's EOSData) spells it <k>; Vaango would
  // stop at require("K"). Accepted as the same parameter; both is an error.
  if (p.has("k") && p.has("K")) p.fail("k", "give either <K> or <k>, not both");
  return eos_positive(p, p.has("k") ? "k" : "K");
}
}  // namespace

EquationOfStateP make_murnaghan(const ModelParameters& p, const EosMaterialConstants&) {
  return make_point_eos("Murnaghan", Murnaghan{eos_positive(p, "n"), murnaghan_K(p), eos_positive(p, "rho0"),
                                               eos_positive(p, "P0")});
}

EquationOfStateP make_birch_murnaghan(const ModelParameters& p, const EosMaterialConstants&) {
  if (p.get_bool("useSpecificHeatModel", false))
    p.missing_feature("useSpecificHeatModel",
                      "BirchMurnaghan <useSpecificHeatModel> true (Vaango does not implement its thermal pressure either)");
  return make_point_eos("BirchMurnaghan", BirchMurnaghan{eos_positive(p, "n"), eos_positive(p, "K"),
                                                         eos_positive(p, "rho0"), eos_positive(p, "P0")});
}

EquationOfStateP make_gruneisen(const ModelParameters& p, const EosMaterialConstants& c) {
  return make_point_eos("Gruneisen", Gruneisen{eos_positive(p, "A"), p.get_double("B"), eos_positive(p, "rho0"),
                                               eos_positive(p, "T0"), eos_positive(p, "P0"), c.cv});
}

EquationOfStateP make_tillotson(const ModelParameters& p, const EosMaterialConstants&) {
  Tillotson m{p.get_double("a"), p.get_double("b"), eos_positive(p, "A"), p.get_double("B"), eos_positive(p, "E0"),
              eos_positive(p, "Es"), eos_positive(p, "alpha"), eos_positive(p, "rho0")};
  eos_positive(p, "Esp");
  eos_positive(p, "beta");
  return make_point_eos("Tillotson", m);
}

}  // namespace tephra
