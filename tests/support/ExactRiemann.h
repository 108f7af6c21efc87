#pragma once
// Exact solution of the Riemann problem for the 1-D Euler equations of an
// ideal gas (Toro, "Riemann Solvers and Numerical Methods for Fluid
// Dynamics", 3rd ed., ch. 4: pressure function f(p) = f_L + f_R + u_R - u_L
// (eq. 4.5-4.7) solved by Newton from the two-rarefaction guess (4.46), then
// the sampling of sec. 4.5). Used as the oracle of the ICE shock-tube runs.
namespace tephra::test {

struct GasState {
  double rho = 0, u = 0, p = 0;
};

class ExactRiemann {
 public:
  ExactRiemann(GasState left, GasState right, double gamma);
  double p_star() const { return p_star_; }
  double u_star() const { return u_star_; }
  // State at similarity coordinate s = (x - x0)/t.
  GasState sample(double s) const;

 private:
  double f(double p, const GasState& k, double c, double& df) const;
  GasState L_, R_;
  double g_, cL_, cR_, p_star_ = 0, u_star_ = 0;
};

}  // namespace tephra::test
