// Point functions of the ICE step: ideal-gas EOS, equilibration pressure and
// the implicit exchange, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "ice/Equilibration.h"
#include "ice/Exchange.h"
#include "models/eos/IdealGas.h"

namespace tephra {
namespace {

// c^2 = gamma p / rho; dp/drho|_e and dp/de against central differences of
// p(rho, e) = (gamma-1) rho e; rho(p, T) inverts p(rho, T).
TEST(EosIdealGas, ClosedFormsAndDerivatives) {
  const IdealGas g(1.4, 717.5);
  const double rho = 1.2, T = 300, e = 717.5 * T;
  const EosState s = g.at(rho, T);
  EXPECT_DOUBLE_EQ(s.p, 0.4 * rho * e);
  EXPECT_NEAR(s.c2, 1.4 * s.p / rho, 1e-12 * s.c2);
  const double h = 1e-6 * rho;
  EXPECT_NEAR(s.dp_drho, (IdealGas::state(1.4, 717.5, rho + h, T).p - IdealGas::state(1.4, 717.5, rho - h, T).p) / (2 * h),
              1e-8 * s.dp_drho);
  EXPECT_NEAR(s.dp_de, 0.4 * rho, 1e-14);
  EXPECT_NEAR(g.density_at(s.p, T), rho, 1e-14 * rho);
  EXPECT_DOUBLE_EQ(g.thermal_expansivity_at(rho, T), 1.0 / T);
}

// Two ideal gases: theta_m = rho_CC_m (g_m - 1) cv_m T_m / p, so sum theta = 1
// gives p = sum_m rho_CC_m (g_m - 1) cv_m T_m exactly (Dalton).
TEST(IceEquilibration, TwoIdealGasesGiveDaltonsPressure) {
  const IdealGas a(1.4, 717.5), b(1.289, 652.9);
  std::vector<double> rA = {0.6, 1e-12}, TA = {300, 300}, rB = {0.9, 1.79}, TB = {400, 400};
  std::vector<double> mA = {1.0, 1.0}, mB = {1.0, 2.0}, thA(2), thB(2), cA(2), cB(2), p = {101325, 101325};
  std::vector<EquilibrationMaterial> mats = {{&a, rA, TA, mA, thA, cA}, {&b, rB, TB, mB, thB, cB}};
  const EquilibrationResult r = equilibrate_pressure(mats, p, 100);
  ASSERT_TRUE(r.converged);
  for (int i = 0; i < 2; ++i) {
    const double exact = rA[i] * 0.4 * 717.5 * TA[i] + rB[i] * 0.289 * 652.9 * TB[i];
    EXPECT_NEAR(p[i], exact, 1e-10 * exact);
    EXPECT_NEAR(thA[i] + thB[i], 1.0, 1e-12);
  }
}

// Newton stopped after 2 iterations from a near-vacuum guess (1e-12 Pa, the
// stall of JWLppCuRS2d's copper cell at 12.4 us): the bisection fallback
// (Uintah's MPMICE::binaryPressureSearch) still gives Dalton's pressure, to
// the tolerance |sum theta - 1| <= 1e-11, i.e. |p/p* - 1| <= 1e-11 here
// (sum theta = p*/p for ideal gases). A root above the bracket's 1/DBL_EPSILON
// Pa is reported as not converged, naming the cell.
TEST(IceEquilibration, BisectionFallbackWhenNewtonStalls) {
  const IdealGas a(1.4, 717.5), b(1.289, 652.9);
  std::vector<double> rA = {0.6, 0.00444819, 1e13}, TA = {300, 328.739, 300}, rB = {0.9, 0.0101541, 1.0},
                      TB = {400, 329.886, 400};
  std::vector<double> mA = {1.0, 1.0, 1.0}, mB = {1.0, 1.0, 1.0}, thA(3), thB(3), cA(3), cB(3), p = {1e-12, 1e-12, 1e-12};
  std::vector<EquilibrationMaterial> mats = {{&a, rA, TA, mA, thA, cA}, {&b, rB, TB, mB, thB, cB}};
  const EquilibrationResult r = equilibrate_pressure(mats, p, 2);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.failed_cell, 2);  // p* = 8.6e17 Pa > 1/DBL_EPSILON = 4.5e15 Pa
  for (int i = 0; i < 2; ++i) {
    const double exact = rA[i] * 0.4 * 717.5 * TA[i] + rB[i] * 0.289 * 652.9 * TB[i];
    EXPECT_NEAR(p[i], exact, 1e-11 * exact) << i;
    EXPECT_NEAR(thA[i] + thB[i], 1.0, 1e-11) << i;
    EXPECT_NEAR(cA[i], 1.4 * p[i] / mA[i], 1e-9 * cA[i]) << i;  // c^2 = gamma p / rho_micro at the root
  }
}

// Two materials, scalar exchange (inventory ch. 24 oracle):
//   x1' = ((1+b21) x1 + b12 x2) / ((1+b12)(1+b21) - b12 b21), b_mn = dt theta_n K v_m,
// and the mass-weighted sum M_m x_m (M_m = V theta_m / v_m) is conserved.
TEST(IceExchange, TwoMaterialClosedFormAndConservation) {
  const double dt = 1e-4, K = 3e5;
  std::vector<double> theta = {0.3, 0.7}, v = {0.8, 1.0 / 1.2}, C = {0, K, K, 0}, x = {10.0, -2.0};
  const double b12 = dt * theta[1] * K * v[0], b21 = dt * theta[0] * K * v[1];
  const double det = (1 + b12) * (1 + b21) - b12 * b21;
  const double x1 = ((1 + b21) * 10.0 + b12 * -2.0) / det, x2 = ((1 + b12) * -2.0 + b21 * 10.0) / det;
  const double before = theta[0] / v[0] * 10.0 + theta[1] / v[1] * -2.0;
  solve_exchange(dt, theta, v, {}, C, x);
  EXPECT_NEAR(x[0], x1, 1e-13 * std::abs(x1));
  EXPECT_NEAR(x[1], x2, 1e-13 * std::abs(x1));
  EXPECT_NEAR(theta[0] / v[0] * x[0] + theta[1] / v[1] * x[1], before, 1e-13 * std::abs(before));
}

// The two-material closed form (Cramer's rule, exchange_detail::TwoByTwo)
// and the general elimination solve the same 2 x 2 system: equal to round-off,
// with and without the heat scale 1/c_v and with unequal C12, C21 entries
// (the linear algebra alone; solve_exchange itself needs a symmetric C).
TEST(IceExchange, TwoMaterialClosedFormEqualsTheElimination) {
  const double dt = 2e-4;
  const std::vector<double> theta = {0.35, 0.65}, v = {0.9, 1.0 / 1.3}, scale = {1.0 / 716.0, 1.0 / 1000.0};
  const std::vector<double> C = {0, 3e3, 5e3, 0};
  for (const bool heat : {false, true}) {
    const std::span<const double> s = heat ? std::span<const double>(scale) : std::span<const double>();
    std::vector<double> x = {7.0, -3.0}, y = x;
    exchange_detail::TwoByTwo(dt, theta, v, s, C).solve(x);
    double a[4];
    exchange_detail::exchange_matrix(dt, theta, v, s, C, a);
    std::span<double> b(y);
    exchange_detail::solve_dominant(2, a, &b, 1);
    for (int m = 0; m < 2; ++m) EXPECT_NEAR(x[m], y[m], 1e-14 * std::abs(y[m])) << "heat " << heat << " m " << m;
  }
}

TEST(IceExchange, StiffLimitGivesTheMassWeightedVelocity) {
  std::vector<double> theta = {0.25, 0.75}, v = {1.0 / 8000.0, 1.0 / 1.2}, C = {0, 1e15, 1e15, 0};
  std::vector<double> ux = {0.0, 0.0}, uy = {5.0, -1.0}, uz = {0.0, 3.0};
  const double w0 = theta[0] / v[0], w1 = theta[1] / v[1];
  const double mix = (w0 * 5.0 + w1 * -1.0) / (w0 + w1);
  solve_exchange3(1e-3, theta, v, C, ux, uy, uz);
  EXPECT_NEAR(uy[0], mix, 1e-9);
  EXPECT_NEAR(uy[1], mix, 1e-9);
  EXPECT_NEAR(ux[0], 0.0, 1e-12);
}

// The round-off bound of the conserved sums (Exchange.h header), with
// u = 2^-53 the unit round-off and the sums S = sum_m w_m x_m evaluated in
// long double (so that the test's own summation does not count):
//   |S(x') - S(x)| <= (4 n + 12) u sum_m w_m (|x_m| + |x'_m|).
// Rounding steps (first order, Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed., eq. 3.4: a computed sum of n products is within
// gamma_n ~ n u of sum |terms|): xbar = fl(S)/fl(W), (2n + 2) u; the projection
// c = fl(sum w y)/fl(W) and y - c, (2n + 3) u of sum w |y| <= sum w (|x| +
// |x'|); the final xbar + y, u; the weights, computed as theta/(v s) in the
// solver and as (theta/v) cv here, 3 u on each side, 6 u. Sum: (4n + 12) u.
double exchange_sum_bound(int n) { return (4.0 * n + 12.0) * std::ldexp(1.0, -53); }

struct SumCheck {
  long double before = 0, after = 0, scale = 0;
};

// Inventory oracle 1 (seed-inventory-vaango-theory.md, ranked list (b)): K = H
// = 1e15, two to four materials (closed form and elimination), velocity and
// temperature. Every material ends at the weighted mean
//   u_mix = sum M u / sum M,  T_mix = sum M cv T / sum M cv
// to ~1/beta relative (beta ~ dt theta K v ~ 1e8..1e11; asserted 1e-6), and
// the sums sum M u, sum M cv T are kept to round-off (exchange_sum_bound;
// session 16's plain elimination drifted 1.3e-8 / 4.6e-12 for n = 3).
TEST(IceExchange, StiffLimitRelaxesToTheWeightedMeansAndConservesTheSums) {
  const double dt = 1e-3;
  for (const int n : {2, 3, 4}) {
    SCOPED_TRACE(n);
    const std::vector<double> theta = n == 2   ? std::vector<double>{0.3, 0.7}
                                      : n == 3 ? std::vector<double>{0.2, 0.5, 0.3}
                                               : std::vector<double>{0.2, 0.4, 0.3, 0.1};
    std::vector<double> v = {1.0 / 1160.0, 1.0 / 1.2, 1.0 / 2.5, 1.0 / 3.0};
    std::vector<double> cv = {1000.0, 716.0, 2500.0, 1500.0};
    v.resize(n);
    cv.resize(n);
    std::vector<double> scale(n), C(n * n, 1e15);
    for (int m = 0; m < n; ++m) {
      scale[m] = 1.0 / cv[m];
      C[m * n + m] = 0.0;
    }
    std::vector<double> ux = {120.0, -40.0, 7.0, 300.0}, uy = {0.0, 2.0, -3.0, 1.0}, uz = {1.0, 0.0, 0.5, -2.0},
                        T = {300.0, 2500.0, 900.0, 4000.0};
    ux.resize(n);
    uy.resize(n);
    uz.resize(n);
    T.resize(n);
    SumCheck mom, eng;
    double M = 0, Mcv = 0;
    for (int m = 0; m < n; ++m) {
      const long double Mm = theta[m] / v[m];
      M += Mm;
      Mcv += Mm * cv[m];
      mom.before += Mm * ux[m];
      eng.before += Mm * cv[m] * T[m];
      mom.scale += Mm * std::abs(ux[m]);
      eng.scale += Mm * cv[m] * T[m];
    }
    const double u_mix = double(mom.before / M), T_mix = double(eng.before / Mcv);
    solve_exchange3(dt, theta, v, C, ux, uy, uz);
    solve_exchange(dt, theta, v, scale, C, T);
    for (int m = 0; m < n; ++m) {
      const long double Mm = theta[m] / v[m];
      mom.after += Mm * ux[m];
      eng.after += Mm * cv[m] * T[m];
      mom.scale += Mm * std::abs(ux[m]);
      eng.scale += Mm * cv[m] * T[m];
      EXPECT_NEAR(ux[m], u_mix, 1e-6 * std::abs(u_mix)) << "m " << m;
      EXPECT_NEAR(T[m], T_mix, 1e-6 * T_mix) << "m " << m;
    }
    const double dmom = double(std::abs(mom.after - mom.before) / mom.scale);
    const double deng = double(std::abs(eng.after - eng.before) / eng.scale);
    std::printf("exchange n=%d: sum changes / sum w(|x|+|x'|): momentum %.3g, energy %.3g; bound %.3g\n", n, dmom,
                deng, exchange_sum_bound(n));
    EXPECT_LE(dmom, exchange_sum_bound(n));
    EXPECT_LE(deng, exchange_sum_bound(n));
  }
}

// The exchange solution of a x' = x by textbook Gaussian elimination (no
// pivoting, the matrix is diagonally dominant) in binary128 (113-bit
// significand, u_q = 2^-113 ~ 1e-34): its error ~u_q beta_max |x| <= 1e-34 *
// 1e15 * |x| is far below the double round-off tested against, whatever the
// cancellation in its pivots. Independent of Exchange.h's algorithm (no
// deviation form, no projection, no cancellation-free pivots).
using Quad = __float128;
std::vector<Quad> reference_exchange(double dt, const std::vector<double>& theta, const std::vector<double>& v,
                                     const std::vector<double>& s, const std::vector<double>& C,
                                     const std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  std::vector<Quad> a(n * n), y(n);
  for (int m = 0; m < n; ++m) {
    Quad diag = 1;
    for (int k = 0; k < n; ++k) {
      if (k == m) continue;
      const Quad beta = Quad(dt) * Quad(theta[k]) * Quad(C[m * n + k]) * Quad(v[m]) * Quad(s[m]);
      a[m * n + k] = -beta;
      diag += beta;
    }
    a[m * n + m] = diag;
    y[m] = x[m];
  }
  for (int p = 0; p < n; ++p)
    for (int r = p + 1; r < n; ++r) {
      const Quad f = a[r * n + p] / a[p * n + p];
      for (int c = p; c < n; ++c) a[r * n + c] -= f * a[p * n + c];
      y[r] -= f * y[p];
    }
  for (int p = n - 1; p >= 0; --p) {
    for (int c = p + 1; c < n; ++c) y[p] -= a[p * n + c] * y[c];
    y[p] /= a[p * n + p];
  }
  return y;
}

// Random cells: n = 3 and 4 materials, mass fractions theta/v spread over
// 1e-9 .. 1 (log-uniform densities 1e-3 .. 1e4 and volume fractions 1e-9 ..
// 1), exchange coefficients log-uniform in 1 .. 1e15, heat scale 1/cv with cv
// in 300 .. 5000, dt = 1e-6 .. 1e-3. Asserted for each draw:
//  - the conserved sum to the round-off bound exchange_sum_bound(n);
//  - the solution against the binary128 reference to 4 n u (|xbar| +
//    max |x - xbar|): the deviation solve's round-off (Exchange.h header),
//    where the plain elimination was off by ~u beta along the constant vector.
// And the two-material closed form against Cramer's rule (exact formula,
// TwoMaterialClosedFormAndConservation) at the same wide mass ratios.
TEST(IceExchange, ConservesTheSumsToRoundOffForWideMassRatios) {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double u = std::ldexp(1.0, -53);
  double worst_sum = 0, worst_sol = 0;
  for (const int n : {2, 3, 4}) {
    for (int draw = 0; draw < 2000; ++draw) {
      std::vector<double> theta(n), v(n), s(n), C(n * n, 0.0), x(n);
      double th_sum = 0;
      for (int m = 0; m < n; ++m) {
        theta[m] = std::pow(10.0, -9.0 * U(rng));
        th_sum += theta[m];
        v[m] = 1.0 / std::pow(10.0, -3.0 + 7.0 * U(rng));
        s[m] = draw % 2 ? 1.0 / (300.0 + 4700.0 * U(rng)) : 1.0;
        x[m] = (U(rng) - 0.5) * std::pow(10.0, 4.0 * U(rng));
      }
      for (double& t : theta) t /= th_sum;
      for (int m = 0; m < n; ++m)
        for (int k = m + 1; k < n; ++k) C[m * n + k] = C[k * n + m] = std::pow(10.0, 15.0 * U(rng));
      const double dt = std::pow(10.0, -6.0 + 3.0 * U(rng));
      const std::vector<Quad> ref = reference_exchange(dt, theta, v, s, C, x);
      std::vector<double> y = x;
      solve_exchange(dt, theta, v, s, C, y);
      long double before = 0, after = 0, scale = 0, W = 0;
      for (int m = 0; m < n; ++m) {
        const long double w = (long double)theta[m] / ((long double)v[m] * s[m]);
        before += w * x[m];
        after += w * y[m];
        scale += w * (std::abs(x[m]) + std::abs(y[m]));
        W += w;
      }
      const double dsum = double(std::abs(after - before) / scale);
      worst_sum = std::max(worst_sum, dsum);
      ASSERT_LE(dsum, exchange_sum_bound(n)) << "n " << n << " draw " << draw;
      const double xbar = double(before / W);
      double dev = 0;
      for (int m = 0; m < n; ++m) dev = std::max(dev, std::abs(x[m] - xbar));
      const double tol = 4.0 * n * u * (std::abs(xbar) + dev);
      for (int m = 0; m < n; ++m) {
        const double err = std::abs(double(Quad(y[m]) - ref[m]));
        worst_sol = std::max(worst_sol, err / (std::abs(xbar) + dev) / u);
        ASSERT_LE(err, tol) << "n " << n << " draw " << draw << " m " << m << " x " << x[0] << " " << x[1] << " " << x[2]
                            << " y " << y[0] << " " << y[1] << " " << y[2] << " ref " << double(ref[0]) << " "
                            << double(ref[1]) << " " << double(ref[2]) << " theta " << theta[0] << " " << theta[1]
                            << " " << theta[2] << " v " << v[0] << " " << v[1] << " " << v[2] << " C " << C[1] << " "
                            << C[2] << " " << C[5] << " dt " << dt << " s " << s[0];
      }
      if (n == 2) {  // Cramer's rule on the 2 x 2 system, b_mn = dt theta_n C v_m s_m
        const double b12 = dt * theta[1] * C[1] * v[0] * s[0], b21 = dt * theta[0] * C[2] * v[1] * s[1];
        const double det = 1.0 + b12 + b21;
        const double x1 = ((1 + b21) * x[0] + b12 * x[1]) / det, x2 = (b21 * x[0] + (1 + b12) * x[1]) / det;
        EXPECT_NEAR(y[0], x1, tol + 4 * u * std::abs(x1)) << draw;
        EXPECT_NEAR(y[1], x2, tol + 4 * u * std::abs(x2)) << draw;
      }
    }
  }
  std::printf("exchange, 6000 random cells: worst sum change %.3g of sum w(|x|+|x'|) (bound for n = 4: %.3g); "
              "worst solution error %.3g u (|xbar| + max|x - xbar|)\n",
              worst_sum, exchange_sum_bound(4), worst_sol);
}

// <heatExchangeCoeff> variable: Uintah's ExchangeCoefficients::
// getVariableExchangeCoeff, branch by branch in the squared mass ratio
// r^2 = (M_n/M_m)^2: < 1e-12 -> 1e12; [1e-12, 1e-5) -> 1/r^2; [1e-5, 1e5) ->
// 1e5; [1e5, 1e12) -> r^2; >= 1e12 -> 1e12. Symmetric, zero diagonal.
TEST(IceExchange, VariableHeatCoefficientsFollowUintahsBranches) {
  struct Case {
    double m1, expected;
  } cases[] = {{1e-7, 1e12},  {1e-6, 1e12},  {1e-4, 1e8},   {1.0 / 300.0, 1e5},
               {1.0, 1e5},    {100.0, 1e5},  {1e3, 1e6},    {1e5, 1e10},
               {1e6, 1e12},   {1e8, 1e12}};
  for (const Case& c : cases) {
    const double mass[2] = {1.0, c.m1};
    double H[4];
    variable_heat_coefficients(mass, H);
    EXPECT_EQ(H[0], 0.0);
    EXPECT_EQ(H[3], 0.0);
    EXPECT_EQ(H[1], H[2]);
    EXPECT_NEAR(H[1], c.expected, 1e-12 * c.expected) << "M1/M0 = " << c.m1;
  }
  // Three materials: every pair by its own ratio.
  const double mass[3] = {2.0, 2e-3, 2e4};
  double H[9];
  variable_heat_coefficients(mass, H);
  EXPECT_NEAR(H[0 * 3 + 1], 1e6, 1e-6);   // r = 1e-3: 1/r^2
  EXPECT_NEAR(H[0 * 3 + 2], 1e8, 1e-4);   // r = 1e4: r^2
  EXPECT_NEAR(H[1 * 3 + 2], 1e12, 1e-2);  // r = 1e7: clamp
  EXPECT_EQ(H[2 * 3 + 1], H[1 * 3 + 2]);
}

}  // namespace
}  // namespace tephra
