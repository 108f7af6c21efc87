#include "mpm/StrainWork.h"

namespace tephra {

double stress_power(const Particles& p, const std::vector<Mat3>& L) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // sigma : sym(l) = sigma : l for symmetric sigma; symmetrise anyway.
    const Mat3 d = 0.5 * (L[i] + L[i].transpose());
    sum += p.volume[i] * p.stress[i].cwiseProduct(d).sum();
  }
  return sum;
}

}  // namespace tephra
