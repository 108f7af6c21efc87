#pragma once
// An independent reference for the axisymmetric ICE tests: the 1-D Euler
// equations of an ideal gas with cylindrical symmetry (no axial flow),
//   d(r U)/dt + d(r F(U))/dr = (0, p, 0),  U = (rho, rho u, E), F = (rho u, rho u^2 + p, (E + p) u),
// by a finite volume in r (V_i = r_i dr, faces r_{i+-1/2}, source p_i dr),
// HLL fluxes of MUSCL (minmod) face states of (rho, u, p), Heun's SSP-RK2
// time steps at cfl 0.4, reflecting walls at r = 0 (zero area) and r = R.
// Not the ICE algorithm: a Godunov-type conservative scheme (Toro ch. 10, 13, 14).
#include <functional>
#include <vector>

namespace tephra::test {

struct RadialState {
  std::vector<double> r, rho, u, p;  // cell centres and primitive values
};

// n cells on [0, R]; init(r) gives (rho, u, p) at r; runs to t_end.
RadialState solve_radial_euler(int n, double R, double gamma,
                               const std::function<void(double r, double& rho, double& u, double& p)>& init,
                               double t_end);

// Cell average over [a, b] of the piecewise-constant reference q (a, b inside [0, R]),
// weighted by r (the axisymmetric cell average).
double radial_average(const RadialState& s, const std::vector<double>& q, double a, double b);

}  // namespace tephra::test
