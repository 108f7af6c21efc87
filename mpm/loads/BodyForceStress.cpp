#include "mpm/loads/BodyForceStress.h"

#include <Eigen/LU>

namespace tephra {

Mat3 body_force_stress(double rho0, const Vec3& b, const Vec3& x, const Vec3& surface_point) {
  Mat3 s = Mat3::Zero();
  for (int i = 0; i < 3; ++i) s(i, i) = -rho0 * b[i] * (x[i] - surface_point[i]);
  return s;
}

Mat3 small_strain_deformation_gradient(const Mat3& sigma, double K, double G) {
  const Mat3 eps = sigma / (2.0 * G) + (1.0 / (9.0 * K) - 1.0 / (6.0 * G)) * sigma.trace() * Mat3::Identity();
  return Mat3::Identity() + eps;
}

void initialize_stress_from_body_force(double rho0, const Vec3& b, const Vec3& surface_point, double K, double G,
                                       Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.stress[i] = body_force_stress(rho0, b, p.x[i], surface_point);
    p.F[i] = small_strain_deformation_gradient(p.stress[i], K, G);
    p.volume[i] = p.F[i].determinant() * p.volume0[i];
  }
}

}  // namespace tephra
