// Simple_Burn point functions (mpmice/SimpleBurn.h).
#include "mpmice/SimpleBurn.h"

#include <algorithm>
#include <cmath>

namespace tephra {

bool simple_burn_surface_cell(const double wm[8], double tiny) {
  double mx = wm[0], mn = wm[0];
  for (int n = 1; n < 8; ++n) mx = std::max(mx, wm[n]), mn = std::min(mn, wm[n]);
  if (!(mx > tiny)) return false;
  const double r = (mx - mn) / mx;
  return r > 0.4 && r < 1.0;
}

Vec3 simple_burn_surface_normal(const double wm[8], const Vec3& dx) {
  Vec3 g = Vec3::Zero();
  for (int n = 0; n < 8; ++n)
    for (int d = 0; d < 3; ++d) g[d] += ((n >> d) & 1) ? -wm[n] : wm[n];
  for (int d = 0; d < 3; ++d) g[d] *= 0.25 / dx[d];
  const double len = g.norm();
  return len > 0 ? Vec3(g / len) : Vec3::Zero();
}

double simple_burn_surface_area(const Vec3& n, const Vec3& dx) {
  const Vec3 a = n.cwiseAbs();
  const double mx = a.maxCoeff();
  if (!(mx > 0)) return 0.0;  // no gradient: inside the solid
  return dx[0] * dx[1] * dx[2] / (dx[0] * a[0] + dx[1] * a[1] + dx[2] * a[2]) * std::cbrt(1.0 / mx);
}

double simple_burn_mass(const SimpleBurnParams& prm, double dt, double area, double p, double T, double solid_mass) {
  if (!(T > prm.threshold_temperature && p > prm.threshold_pressure)) return 0.0;
  const double dm = dt * area * prm.burn_coeff * std::pow(p / prm.ref_pressure, 0.778);
  return std::min(dm, solid_mass);
}

}  // namespace tephra
