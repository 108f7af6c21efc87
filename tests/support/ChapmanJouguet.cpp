#include "tests/support/ChapmanJouguet.h"

#include <cmath>
#include <stdexcept>

namespace tephra::test {

double JwlcProducts::p(double V) const {
  return A * std::exp(-R1 * V) + B * std::exp(-R2 * V) + C * std::pow(V, -(1 + om));
}

double JwlcProducts::dp_dV(double V) const {
  return -R1 * A * std::exp(-R1 * V) - R2 * B * std::exp(-R2 * V) - (1 + om) * C * std::pow(V, -(2 + om));
}

CjState chapman_jouguet(const JwlcProducts& e, double p0) {
  auto f = [&](double V) { return e.p(V) - p0 + e.dp_dV(V) * (1 - V); };
  double a = 0.3, b = 0.99;
  if (!(f(a) < 0 && f(b) > 0)) throw std::runtime_error("chapman_jouguet: [0.3, 0.99] does not bracket the CJ point");
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    (f(m) < 0 ? a : b) = m;
  }
  const double V = 0.5 * (a + b);
  return {V, e.p(V), std::sqrt(-e.dp_dV(V) / e.rho0)};
}

}  // namespace tephra::test
