// Equilibration pressure (ice/Equilibration.cpp) in a cell filled by two
// stiff materials with a trace of gas: the case of an MPMICE cell inside a
// steel wall next to the explosive (guni2dRT.ups, cell (25,17,-1) at step 0,
// which stopped the run with exit 4 before the convergence test below).
//
// Two Murnaghan materials (steel-like: rho0 7830, 1/K = 173 GPa, n = 4;
// PBX-like: rho0 1840, 1/K = 5.6 GPa, n = 7.4; P0 = 101325 Pa) with the cell
// fractions 0.921875 and 0.078125 (sum exactly 1 at P0) and an ideal gas at
// 1e-12 of its density. The total compressibility is C = -d sum theta/dp
// ~ 1.9e-11 /Pa, so sum theta is resolved to ~eps only within eps/C ~ 1e-5 Pa
// (1e-10 p): Newton cycled between two pressures 1.3e-5 Pa apart, and the
// old test |dp| <= 1e-11 p never held. The converged pressure must satisfy
//   sum_m rho_CC_m / rho_m(p) = 1,
// rho_m(p) = rho0 (n K (p - P0) + 1)^(1/n) (Murnaghan, p >= P0) and
// rho_gas = p / ((gamma - 1) c_v T): found here by bisection on that closed
// form (the oracle), about 0.05 Pa above P0 (the solids make room for the gas).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ice/Equilibration.h"
#include "models/eos/EquationOfState.h"
#include "models/eos/IdealGas.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

struct Murn {
  double n, K, rho0, P0;
  double rho(double p) const { return rho0 * std::pow(n * K * (p - P0) + 1.0, 1.0 / n); }
};

EquationOfStateP murnaghan(const Murn& m) {
  test::MapModelParameters p({{"n", m.n}, {"K", m.K}, {"rho0", m.rho0}, {"P0", m.P0}});
  return create_equation_of_state("Murnaghan", p, {});
}

TEST(IceEquilibration, StiffCellWithATraceOfGasConverges) {
  const Murn steel{4.0, 1.0 / 173e9, 7830.0, 101325.0}, pbx{7.4, 1.0 / 5.6e9, 1840.0, 101325.0};
  const EquationOfStateP es = murnaghan(steel), ep = murnaghan(pbx);
  const IdealGas gas(1.4, 716.0);
  const double T = 300.0, rho_gas0 = 101325.0 / (0.4 * 716.0 * T);
  std::vector<double> rs = {0.921875 * 7830.0}, rp = {0.078125 * 1840.0}, rg = {1e-12 * rho_gas0}, Tv = {T};
  std::vector<double> ms = {7830.0}, mp = {1840.0}, mg = {rho_gas0};  // starting guesses 1/sp_vol
  std::vector<double> ts(1), tp(1), tg(1), cs(1), cp(1), cg(1), p = {101325.0};
  std::vector<EquilibrationMaterial> mats = {
      {es.get(), rs, Tv, ms, ts, cs}, {ep.get(), rp, Tv, mp, tp, cp}, {&gas, rg, Tv, mg, tg, cg}};
  const EquilibrationResult r = equilibrate_pressure(mats, p, 100);
  ASSERT_TRUE(r.converged) << "iterations " << r.iterations;

  // The oracle: bisection on f(p) = sum theta(p) - 1 (decreasing in p).
  auto f = [&](double q) { return rs[0] / steel.rho(q) + rp[0] / pbx.rho(q) + rg[0] / (q / (0.4 * 716.0 * T)) - 1.0; };
  double lo = 101325.0, hi = 101326.0;
  ASSERT_GT(f(lo), 0.0);
  ASSERT_LT(f(hi), 0.0);
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  const double exact = 0.5 * (lo + hi);
  EXPECT_GT(exact - 101325.0, 0.04);  // the gas needs room: about 0.05 Pa
  // p is resolved to eps / C ~ 1e-5 Pa (header): 2e-10 relative is 2e-5 Pa.
  EXPECT_NEAR(p[0], exact, 2e-10 * exact);
  EXPECT_NEAR(ts[0] + tp[0] + tg[0], 1.0, 1e-14);
  EXPECT_LE(r.iterations, 20);
}

}  // namespace
}  // namespace tephra
