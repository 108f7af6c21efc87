// Benchmark (not a test): JWLC rho(p) (ANFO constants, EOSData/JWLEOSANFO.xml)
// through the EOS interface against the bracketed Newton on rho from
// [0, rho0] (DensitySolve.h, the solver JWLC used before), on a sweep of
// pressures 1e2 .. 1e11 Pa (absent product at atmospheric pressure up to the
// CJ region). Prints ns per solve and the point evaluations the bracketed
// solve needs on average. Run: build/bin/bench_jwlc_density [repeats=200]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#include "models/eos/DensitySolve.h"
#include "models/eos/EquationOfState.h"
#include "tests/support/SolidModelDriver.h"

using namespace tephra;

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 200;
  const double A = 2.9867e11, B = 4.11706e9, C = 7.206147e8, R1 = 4.95, R2 = 1.15, om = 0.35, rho0 = 1160.0;
  test::MapModelParameters params({{"A", A}, {"B", B}, {"C", C}, {"R1", R1}, {"R2", R2}, {"om", om}, {"rho0", rho0}});
  const EquationOfStateP eos = create_equation_of_state("JWLC", params, {});
  const int n = 1000;
  std::vector<double> p(n), T(n, 300.0), rho(n), ref(n);
  for (int i = 0; i < n; ++i) p[i] = std::pow(10.0, 2.0 + 9.0 * i / (n - 1));
  long long evals = 0;
  auto bracketed = [&](double pt) {
    return solve_density_bracketed(
        [&](double r) {
          ++evals;
          const double V = rho0 / r, P1 = A * std::exp(-R1 * V), P2 = B * std::exp(-R2 * V);
          const double P3 = C * std::pow(r / rho0, 1.0 + om);
          return std::pair{P1 + P2 + P3 - pt, (R1 * V * P1 + R2 * V * P2 + (1.0 + om) * P3) / r};
        },
        0.0, rho0);
  };
  auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) eos->density(p, T, rho);
  const double t_new = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r)
    for (int i = 0; i < n; ++i) ref[i] = bracketed(p[i]);
  const double t_old = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double worst = 0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(rho[i] - ref[i]) / ref[i]);
  const double calls = double(n) * repeats;
  std::printf("JWLC rho(p), %d pressures 1e2..1e11 Pa x %d repeats\n", n, repeats);
  std::printf("  EOS density() (log-Newton):      %8.1f ns per solve\n", 1e9 * t_new / calls);
  std::printf("  bracketed Newton on rho:         %8.1f ns per solve, %.1f evaluations per solve\n",
              1e9 * t_old / calls, double(evals) / calls);
  std::printf("  max relative difference of rho:  %.2e\n", worst);
  return 0;
}
