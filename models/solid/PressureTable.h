#pragma once
// A pressure table p(eta) of the density ratio eta = rho/rho0 with linear
// interpolation (VT §22.1-22.2, eqs. 22.1-22.4 with one independent variable):
//   k = the segment [eta_k, eta_{k+1}] holding eta, s = (eta - eta_k)/(eta_{k+1} - eta_k),
//   p(eta) = (1 - s) p_k + s p_{k+1}.
// Outside the table the end segments are extended (linear extrapolation, as
// Vaango's TabularData::interpolate, whose segment search clamps to the ends but
// not the parameter s). A value on a knot uses the segment to its left (Vaango's
// lower_bound search), so dp/deta there is the left slope.
//
// Stored energy per reference volume of the pressure-only solid (DESIGN §2.1,
// VT eq. 4.3 with sigma = -p I): W(J) = -int_1^J p dJ', i.e. with J = 1/eta,
//   W(eta) = int_1^eta p(e)/e^2 de,
// exact on each segment p = c_k + s_k e:  int c_k/e^2 + s_k/e de = [-c_k/e + s_k ln e].
#include <cstddef>
#include <vector>

namespace tephra {

class PressureTable {
 public:
  // eta strictly increasing and > 0, p strictly increasing (a positive tangent
  // bulk modulus on every segment), at least two points; the caller validates.
  PressureTable(std::vector<double> eta, std::vector<double> p);

  std::size_t size() const { return eta_.size(); }
  const std::vector<double>& eta() const { return eta_; }
  const std::vector<double>& pressure() const { return p_; }

  std::size_t segment(double eta) const;  // k in [0, n-2]
  double pressure(double eta) const;      // p(eta), eq. 22.3-22.4
  double slope(double eta) const;         // dp/deta of the segment holding eta
  double energy(double eta) const;        // W(eta) above, W(1) = 0
  // The inverse of pressure(): eta with pressure(eta) = p (the same segments,
  // extended at the ends); <= 0 when no positive density gives p.
  double density_ratio(double p) const;

 private:
  double antiderivative(std::size_t k, double eta) const;  // -c_k/eta + s_k ln eta
  double energy_from_first_knot(double eta) const;
  std::vector<double> eta_, p_, slope_, W_knot_;
  double W_at_one_ = 0.0;
};

}  // namespace tephra
