#include "models/solid/PressureTable.h"

#include <algorithm>
#include <cmath>

namespace tephra {

PressureTable::PressureTable(std::vector<double> eta, std::vector<double> p) : eta_(std::move(eta)), p_(std::move(p)) {
  const std::size_t n = eta_.size();
  slope_.resize(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) slope_[k] = (p_[k + 1] - p_[k]) / (eta_[k + 1] - eta_[k]);
  // W from the first knot, accumulated segment by segment.
  W_knot_.assign(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k)
    W_knot_[k + 1] = W_knot_[k] + antiderivative(k, eta_[k + 1]) - antiderivative(k, eta_[k]);
  W_at_one_ = energy_from_first_knot(1.0);
}

std::size_t PressureTable::segment(double eta) const {
  // The first knot >= eta; its left neighbour starts the segment (clamped to the ends).
  const auto it = std::lower_bound(eta_.begin(), eta_.end(), eta);
  const std::size_t hi = static_cast<std::size_t>(it - eta_.begin());
  if (hi == 0) return 0;
  return std::min(hi - 1, eta_.size() - 2);
}

double PressureTable::pressure(double eta) const {
  const std::size_t k = segment(eta);
  const double s = (eta - eta_[k]) / (eta_[k + 1] - eta_[k]);  // eq. 22.2
  return (1.0 - s) * p_[k] + s * p_[k + 1];                    // eq. 22.3
}

double PressureTable::slope(double eta) const { return slope_[segment(eta)]; }

double PressureTable::antiderivative(std::size_t k, double eta) const {
  const double c = p_[k] - slope_[k] * eta_[k];  // p = c + s eta on segment k
  return -c / eta + slope_[k] * std::log(eta);
}

double PressureTable::energy_from_first_knot(double eta) const {
  const std::size_t k = segment(eta);
  return W_knot_[k] + antiderivative(k, eta) - antiderivative(k, eta_[k]);
}

double PressureTable::energy(double eta) const { return energy_from_first_knot(eta) - W_at_one_; }

double PressureTable::density_ratio(double p) const {
  // p_k is increasing: the same segment search on the pressures.
  const auto it = std::lower_bound(p_.begin(), p_.end(), p);
  const std::size_t hi = static_cast<std::size_t>(it - p_.begin());
  const std::size_t k = hi == 0 ? 0 : std::min(hi - 1, p_.size() - 2);
  return eta_[k] + (p - p_[k]) / slope_[k];
}

}  // namespace tephra
