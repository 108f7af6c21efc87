#include "tests/support/RadialEuler.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tephra::test {

namespace {

using Cons = std::array<double, 3>;

double minmod(double a, double b) { return a * b <= 0 ? 0.0 : (std::abs(a) < std::abs(b) ? a : b); }

// HLL flux (Toro 10.21) with Davis's wave-speed estimates.
Cons hll(double gamma, double rL, double uL, double pL, double rR, double uR, double pR) {
  const double cL = std::sqrt(gamma * pL / rL), cR = std::sqrt(gamma * pR / rR);
  const double sL = std::min(uL - cL, uR - cR), sR = std::max(uL + cL, uR + cR);
  const double EL = pL / (gamma - 1) + 0.5 * rL * uL * uL, ER = pR / (gamma - 1) + 0.5 * rR * uR * uR;
  const Cons FL{rL * uL, rL * uL * uL + pL, (EL + pL) * uL}, FR{rR * uR, rR * uR * uR + pR, (ER + pR) * uR};
  if (sL >= 0) return FL;
  if (sR <= 0) return FR;
  const Cons UL{rL, rL * uL, EL}, UR{rR, rR * uR, ER};
  Cons F;
  for (int k = 0; k < 3; ++k) F[k] = (sR * FL[k] - sL * FR[k] + sL * sR * (UR[k] - UL[k])) / (sR - sL);
  return F;
}

}  // namespace

RadialState solve_radial_euler(int n, double R, double gamma,
                               const std::function<void(double, double&, double&, double&)>& init, double t_end) {
  const double dr = R / n;
  std::vector<Cons> U(static_cast<std::size_t>(n));
  RadialState s;
  s.r.resize(std::size_t(n));
  for (int i = 0; i < n; ++i) {
    s.r[std::size_t(i)] = (i + 0.5) * dr;
    // Cell average of the initial state from 8 r-weighted samples.
    Cons avg{0, 0, 0};
    double wsum = 0;
    for (int q = 0; q < 8; ++q) {
      const double r = (i + (q + 0.5) / 8) * dr;
      double rho, u, p;
      init(r, rho, u, p);
      avg[0] += r * rho, avg[1] += r * rho * u, avg[2] += r * (p / (gamma - 1) + 0.5 * rho * u * u);
      wsum += r;
    }
    for (int k = 0; k < 3; ++k) U[std::size_t(i)][k] = avg[k] / wsum;
  }
  auto prim = [&](const Cons& c, double& rho, double& u, double& p) {
    rho = c[0], u = c[1] / c[0], p = (gamma - 1) * (c[2] - 0.5 * c[1] * c[1] / c[0]);
  };
  // d U_i/dt = -(r_{i+1/2} F_{i+1/2} - r_{i-1/2} F_{i-1/2})/(r_i dr) + (0, p_i/r_i, 0).
  auto rate = [&](const std::vector<Cons>& V, std::vector<Cons>& dU) {
    std::vector<double> rho(std::size_t(n) + 2), u(rho.size()), p(rho.size());
    for (int i = 0; i < n; ++i) prim(V[std::size_t(i)], rho[i + 1], u[i + 1], p[i + 1]);
    rho[0] = rho[1], u[0] = -u[1], p[0] = p[1];  // reflecting ghosts
    rho[n + 1] = rho[n], u[n + 1] = -u[n], p[n + 1] = p[n];
    std::vector<Cons> F(std::size_t(n) + 1);
    auto slope = [&](const std::vector<double>& q, int g) {  // g: ghosted index 1..n
      return minmod(q[g] - q[g - 1], q[g + 1] - q[g]);
    };
    for (int f = 0; f <= n; ++f) {  // face f between ghosted cells f and f+1
      const int gl = f, gr = f + 1;
      double rL = rho[gl], uL = u[gl], pL = p[gl], rR = rho[gr], uR = u[gr], pR = p[gr];
      if (gl >= 1) rL += 0.5 * slope(rho, gl), uL += 0.5 * slope(u, gl), pL += 0.5 * slope(p, gl);
      if (gr <= n) rR -= 0.5 * slope(rho, gr), uR -= 0.5 * slope(u, gr), pR -= 0.5 * slope(p, gr);
      F[std::size_t(f)] = hll(gamma, rL, uL, pL, rR, uR, pR);
    }
    dU.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) {
      const double rl = i * dr, rh = (i + 1) * dr, rc = (i + 0.5) * dr;
      for (int k = 0; k < 3; ++k)
        dU[std::size_t(i)][k] = -(rh * F[std::size_t(i) + 1][k] - rl * F[std::size_t(i)][k]) / (rc * dr);
      dU[std::size_t(i)][1] += p[i + 1] / rc;  // the hoop source p dr / (r dr)
    }
  };
  double t = 0;
  std::vector<Cons> k1, k2, U1(U.size());
  while (t < t_end) {
    double smax = 0;
    for (const Cons& c : U) {
      double rho, u, p;
      prim(c, rho, u, p);
      smax = std::max(smax, std::abs(u) + std::sqrt(gamma * p / rho));
    }
    const double dt = std::min(0.4 * dr / smax, t_end - t);
    rate(U, k1);
    for (std::size_t i = 0; i < U.size(); ++i)
      for (int k = 0; k < 3; ++k) U1[i][k] = U[i][k] + dt * k1[i][k];
    rate(U1, k2);
    for (std::size_t i = 0; i < U.size(); ++i)
      for (int k = 0; k < 3; ++k) U[i][k] = 0.5 * (U[i][k] + U1[i][k] + dt * k2[i][k]);
    t += dt;
  }
  s.rho.resize(std::size_t(n)), s.u.resize(std::size_t(n)), s.p.resize(std::size_t(n));
  for (int i = 0; i < n; ++i) prim(U[std::size_t(i)], s.rho[std::size_t(i)], s.u[std::size_t(i)], s.p[std::size_t(i)]);
  return s;
}

double radial_average(const RadialState& s, const std::vector<double>& q, double a, double b) {
  const double dr = 2 * s.r[0];
  double sum = 0, wsum = 0;
  for (std::size_t i = 0; i < s.r.size(); ++i) {
    const double lo = std::max(a, s.r[i] - 0.5 * dr), hi = std::min(b, s.r[i] + 0.5 * dr);
    if (hi <= lo) continue;
    const double w = 0.5 * (hi * hi - lo * lo);  // integral of r dr over the overlap
    sum += w * q[i];
    wsum += w;
  }
  return sum / wsum;
}

}  // namespace tephra::test
