#include "mpm/StrainWork.h"

#include <Eigen/LU>

namespace tephra {

double piola_work(const Particles& p, const std::vector<Mat3>& F_stress, const std::vector<Mat3>& F_old) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Mat3& Fs = F_stress[i];
    const Mat3 P = Fs.determinant() * p.stress[i] * Fs.inverse().transpose();
    sum += p.volume0[i] * P.cwiseProduct(p.F[i] - F_old[i]).sum();
  }
  return sum;
}

double plastic_work_of_step(const Particles& p, const std::vector<double>& plastic_work) {
  double sum = 0.0;
  // plastic_work is a step column, sized to the particle count with the others
  // (MpmComponent::size_step_columns, ParticleDeletion, migration).
  for (std::size_t i = 0; i < p.size(); ++i) sum += p.volume0[i] * plastic_work[i];
  return sum;
}

}  // namespace tephra
