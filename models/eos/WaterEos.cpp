// Water EOS: Thomsen & Hartka (liquid water, temperature and pressure
// dependent) and Knauss' linear sea-water EOS. Formulas: Uintah/Vaango ICE
// (Thomsen_Hartka_water.cc, KnaussSeaWater.cc); derivatives re-derived here.
#include <cmath>

#include "models/eos/EosModels.h"
#include "models/eos/PointEos.h"

namespace tephra {

namespace {

// Thomsen & Hartka: v = vo (1 - ko p + L x^2), x = a p + T - To. For given
// rho, T this is the quadratic L a^2 p^2 + (2 a L (T - To) - ko) p
// + (1 + L (T - To)^2 - 1/(vo rho)) = 0 in p; the physical root (Uintah's) is
//   p = (-beta - sqrt(beta^2 - 4 alpha gamma)) / (2 alpha).
// With d1 = ko - 2 a L x and y = 1 - ko p + L x^2:
//   dp/drho|_T = vo y^2/d1          (from dv/dp|_T = vo (2 a L x - ko))
//   dp/dT|_rho = 2 L x/d1           (from dv/dT|_p = 2 vo L x)
// and the heat capacity of Uintah's dp/de (its Thomsen-Hartka notebook):
//   c_v = co + b (To - T) + 2 p L vo (To - a p - 2 T).
// rho(p, T) = 1/(vo y) in closed form.
struct ThomsenHartka {
  double a, b, co, ko, To, L, vo;
  PointThermo point(double rho, double T) const {
    const double al = L * a * a, be = 2.0 * a * L * (T - To) - ko;
    const double ga = 1.0 + L * (T - To) * (T - To) - 1.0 / (vo * rho);
    const double p = (-be - std::sqrt(be * be - 4.0 * al * ga)) / (2.0 * al);
    const double x = a * p + T - To, y = 1.0 - ko * p + L * x * x, d1 = ko - 2.0 * a * L * x;
    return {p, vo * y * y / d1, 2.0 * L * x / d1};
  }
  double density(double p, double T) const {
    const double x = a * p + T - To;
    return 1.0 / (vo * (1.0 - ko * p + L * x * x));
  }
  double heat_capacity(double, double T, double p) const {
    return co + b * (To - T) + 2.0 * p * L * vo * (To - a * p - 2.0 * T);
  }
};

// Knauss sea water (linear in T, salinity S and p):
//   rho = rho0 + a (T - T0) + b (S - S0) + K (p - P0)
//   p = P0 + (rho - rho0 - a (T - T0) - b (S - S0))/K,  dp/drho = 1/K,  dp/dT = -a/K
// Uintah returns dp/de = -a/K (dp/dT without the 1/cv); here dp/de = -a/(K cv).
// The defaults are Vaango's (all parameters optional in its schema).
struct KnaussSeaWater {
  double a, b, K, T0, P0, S, S0, rho0, cv;
  PointThermo point(double rho, double T) const {
    return {P0 + (rho - rho0 - a * (T - T0) - b * (S - S0)) / K, 1.0 / K, -a / K};
  }
  double density(double p, double T) const { return rho0 + a * (T - T0) + b * (S - S0) + K * (p - P0); }
  double heat_capacity(double, double, double) const { return cv; }
};

}  // namespace

EquationOfStateP make_thomsen_hartka_water(const ModelParameters& p, const EosMaterialConstants&) {
  ThomsenHartka m{p.get_double("a"), p.get_double("b"), eos_positive(p, "co"), eos_positive(p, "ko"),
                  eos_positive(p, "To"), eos_positive(p, "L"), eos_positive(p, "vo")};
  if (m.a == 0.0) p.fail("a", "Thomsen_Hartka_water needs <a> != 0 (the pressure is the root of a quadratic in a)");
  return make_point_eos("Thomsen_Hartka_water", m);
}

EquationOfStateP make_knauss_sea_water(const ModelParameters& p, const EosMaterialConstants& c) {
  KnaussSeaWater m{p.get_double("a", -0.15), p.get_double("b", 0.0),    p.get_double("K", 4.5e-7),
                   p.get_double("T0", 283.15), p.get_double("P0", 101325.0), p.get_double("S", 35.0),
                   p.get_double("S0", 35.0),   p.get_double("rho0", 1027.0), c.cv};
  if (!(m.K > 0.0)) p.fail("K", "KnaussSeaWater needs <K> > 0");
  if (!(m.rho0 > 0.0)) p.fail("rho0", "KnaussSeaWater needs <rho0> > 0");
  return make_point_eos("KnaussSeaWater", m);
}

}  // namespace tephra
