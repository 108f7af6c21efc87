// DDT1 point functions (mpmice/Ddt1.h).
#include "mpmice/Ddt1.h"

#include <algorithm>
#include <cmath>

namespace tephra {

Ddt1Branch ddt1_branch(const Ddt1Thresholds& t, const Ddt1CellState& s) {
  if (!(s.reactant_fraction > 1e-10)) return Ddt1Branch::None;
  if (s.p > t.jwl_pressure && s.reactant_fraction > t.volume_fraction) return Ddt1Branch::Detonating;
  if (!(s.p < t.jwl_pressure && s.p > t.sb_pressure) || s.detonation_next) return Ddt1Branch::None;
  if (s.ignited_surface && s.gas_pressure >= t.sb_pressure) return Ddt1Branch::Conductive;
  if (t.crack_model && s.cracked && s.hot_neighbour) return Ddt1Branch::Convective;
  return Ddt1Branch::None;
}

Ddt1Detonation ddt1_detonation(double G, double b, double p, double reactant_mass, double product_mass, double rho0,
                               double cell_volume, double dt) {
  Ddt1Detonation d;
  const double total = reactant_mass + product_mass;
  d.F = total > 0 ? product_mass / total : 0.0;
  if (d.F >= 0 && d.F < 1) d.delF = G * std::pow(p, b) * (1 - d.F) * dt;
  d.mass = std::min({d.delF * total, reactant_mass, 0.2 * rho0 * cell_volume});
  return d;
}

double ddt1_crack_threshold(double p) { return std::sqrt(8.0e8 / std::pow(p, 2.84)); }

double ddt1_convective_area(double cell_volume) { return cell_volume / 0.002; }

double ddt1_flame_speed(const Ddt1InductionParams& prm, double p) { return prm.Fb * std::pow(p / prm.PS, prm.Fc); }

double ddt1_induction_factor(double IC, double theta) {
  constexpr double kHalfPi = 1.57079632679489661923;  // Uintah's phase shift pi/2
  return (1 + IC) / 2 + (1 - IC) / 2 * std::sin(2 * theta - kHalfPi);
}

double ddt1_induction_angle(const Vec3& n, const Vec3& h, double& cos_theta) {
  cos_theta = std::abs(n.dot(h)) / (h.norm() * n.norm());  // NaN for a zero vector, as Uintah's
  if (cos_theta > 1) cos_theta = 1.0;
  return std::acos(cos_theta);
}

double ddt1_induction_time(const Ddt1InductionParams& prm, double dx_mean, double A, double p) {
  return dx_mean * A / ddt1_flame_speed(prm, p);
}

}  // namespace tephra
