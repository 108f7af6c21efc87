#include "tests/support/ExactRiemann.h"

#include <cmath>
#include <stdexcept>

namespace tephra::test {

ExactRiemann::ExactRiemann(GasState left, GasState right, double gamma) : L_(left), R_(right), g_(gamma) {
  cL_ = std::sqrt(g_ * L_.p / L_.rho);
  cR_ = std::sqrt(g_ * R_.p / R_.rho);
  // Two-rarefaction initial guess (Toro 4.46).
  const double z = (g_ - 1) / (2 * g_);
  double p = std::pow((cL_ + cR_ - 0.5 * (g_ - 1) * (R_.u - L_.u)) / (cL_ / std::pow(L_.p, z) + cR_ / std::pow(R_.p, z)),
                      1 / z);
  for (int it = 0; it < 100; ++it) {
    double dL = 0, dR = 0;
    const double F = f(p, L_, cL_, dL) + f(p, R_, cR_, dR) + R_.u - L_.u;
    double pn = p - F / (dL + dR);
    if (pn < 0) pn = 1e-8 * p;
    const bool done = std::abs(pn - p) <= 1e-14 * 0.5 * (pn + p);
    p = pn;
    if (done) break;
  }
  p_star_ = p;
  double dL = 0, dR = 0;
  u_star_ = 0.5 * (L_.u + R_.u) + 0.5 * (f(p, R_, cR_, dR) - f(p, L_, cL_, dL));
}

// Toro 4.6 (shock, p > p_K) and 4.7 (rarefaction) with derivative 4.37.
double ExactRiemann::f(double p, const GasState& k, double c, double& df) const {
  if (p > k.p) {
    const double A = 2 / ((g_ + 1) * k.rho), B = (g_ - 1) / (g_ + 1) * k.p;
    const double q = std::sqrt(A / (p + B));
    df = q * (1 - 0.5 * (p - k.p) / (B + p));
    return (p - k.p) * q;
  }
  const double pr = p / k.p;
  df = 1 / (k.rho * c) * std::pow(pr, -(g_ + 1) / (2 * g_));
  return 2 * c / (g_ - 1) * (std::pow(pr, (g_ - 1) / (2 * g_)) - 1);
}

// Toro sec. 4.5, Fig. 4.14.
GasState ExactRiemann::sample(double s) const {
  const double g = g_, gm = (g - 1) / (g + 1);
  if (s <= u_star_) {  // left of the contact
    if (p_star_ > L_.p) {
      const double SL = L_.u - cL_ * std::sqrt((g + 1) / (2 * g) * p_star_ / L_.p + (g - 1) / (2 * g));
      if (s <= SL) return L_;
      const double pr = p_star_ / L_.p;
      return {L_.rho * (pr + gm) / (gm * pr + 1), u_star_, p_star_};
    }
    const double cs = cL_ * std::pow(p_star_ / L_.p, (g - 1) / (2 * g));
    if (s <= L_.u - cL_) return L_;
    if (s >= u_star_ - cs) return {L_.rho * std::pow(p_star_ / L_.p, 1 / g), u_star_, p_star_};
    const double k = 2 / (g + 1) + gm / cL_ * (L_.u - s);
    return {L_.rho * std::pow(k, 2 / (g - 1)), 2 / (g + 1) * (cL_ + (g - 1) / 2 * L_.u + s),
            L_.p * std::pow(k, 2 * g / (g - 1))};
  }
  if (p_star_ > R_.p) {
    const double SR = R_.u + cR_ * std::sqrt((g + 1) / (2 * g) * p_star_ / R_.p + (g - 1) / (2 * g));
    if (s >= SR) return R_;
    const double pr = p_star_ / R_.p;
    return {R_.rho * (pr + gm) / (gm * pr + 1), u_star_, p_star_};
  }
  const double cs = cR_ * std::pow(p_star_ / R_.p, (g - 1) / (2 * g));
  if (s >= R_.u + cR_) return R_;
  if (s <= u_star_ + cs) return {R_.rho * std::pow(p_star_ / R_.p, 1 / g), u_star_, p_star_};
  const double k = 2 / (g + 1) - gm / cR_ * (R_.u - s);
  return {R_.rho * std::pow(k, 2 / (g - 1)), 2 / (g + 1) * (-cR_ + (g - 1) / 2 * R_.u + s),
          R_.p * std::pow(k, 2 * g / (g - 1))};
}

}  // namespace tephra::test
