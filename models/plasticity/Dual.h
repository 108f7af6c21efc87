#pragma once
// Forward-mode dual numbers with three derivative slots, so that each flow
// law is written once (templated on the scalar) and its derivatives with
// respect to (ε_p, ε̇_p, T) are exact, not finite differences. Only included
// by flow-model sources (keeps templates out of widely included headers).
#include <algorithm>
#include <array>
#include <cmath>

namespace tephra::ad {

struct Dual {
  double v = 0.0;
  std::array<double, 3> d{0.0, 0.0, 0.0};
  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants promote implicitly
  Dual(double value, int slot) : v(value) { d[slot] = 1.0; }
};

inline Dual chain(const Dual& a, double value, double slope) {
  Dual r(value);
  for (int i = 0; i < 3; ++i) r.d[i] = slope * a.d[i];
  return r;
}
inline Dual operator+(const Dual& a, const Dual& b) {
  Dual r(a.v + b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
inline Dual operator-(const Dual& a, const Dual& b) {
  Dual r(a.v - b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
inline Dual operator-(const Dual& a) { return chain(a, -a.v, -1.0); }
inline Dual operator*(const Dual& a, const Dual& b) {
  Dual r(a.v * b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
inline Dual operator/(const Dual& a, const Dual& b) {
  Dual r(a.v / b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = (a.d[i] * b.v - a.v * b.d[i]) / (b.v * b.v);
  return r;
}
inline Dual exp(const Dual& a) { const double e = std::exp(a.v); return chain(a, e, e); }
inline Dual log(const Dual& a) { return chain(a, std::log(a.v), 1.0 / a.v); }
inline Dual sqrt(const Dual& a) { const double s = std::sqrt(a.v); return chain(a, s, s > 0 ? 0.5 / s : 0.0); }
inline Dual pow(const Dual& a, double n) {
  const double p = std::pow(a.v, n);
  return chain(a, p, a.v != 0.0 ? n * p / a.v : 0.0);
}
inline Dual tanh(const Dual& a) { const double t = std::tanh(a.v); return chain(a, t, 1.0 - t * t); }
inline Dual erf(const Dual& a) {
  return chain(a, std::erf(a.v), 2.0 / std::sqrt(M_PI) * std::exp(-a.v * a.v));
}
inline const Dual& max(const Dual& a, const Dual& b) { return a.v >= b.v ? a : b; }
inline const Dual& min(const Dual& a, const Dual& b) { return a.v <= b.v ? a : b; }

// Plain doubles use the same spelling inside the templated laws.
using std::erf, std::exp, std::log, std::pow, std::sqrt, std::tanh;
inline double max(double a, double b) { return std::max(a, b); }
inline double min(double a, double b) { return std::min(a, b); }
inline double value(double a) { return a; }
inline double value(const Dual& a) { return a.v; }

}  // namespace tephra::ad
