// Continuum elasto-plastic tangent of a J2-I1 yield condition (ContinuumTangent.h, VT §18.6.2).
#include "models/plasticity/ContinuumTangent.h"

namespace tephra {

Tangent4 j2i1_elastoplastic_tangent(double K, double mu, const Eigen::Matrix3d& N, double H_p) {
  Tangent4 C = isotropic_tangent(K - 2.0 * mu / 3.0, mu);
  const Eigen::Matrix3d CN = C.contract(N);  // C^e : N (= N : C^e, C^e has major symmetry)
  const double denom = N.cwiseProduct(CN).sum() + H_p;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) C(i, j, k, l) -= CN(i, j) * CN(k, l) / denom;
  return C;
}

Tangent4 yield_continuum_tangent(const YieldCondition& yield, const Eigen::Matrix3d& sigma, double sigma_y, double H_y,
                                 double porosity, double K, double mu, const KinematicHardeningModel* kin,
                                 const Eigen::Matrix3d& beta) {
  const Eigen::Matrix3d N = yield.gradient(sigma, sigma_y, porosity);
  const double h = 1e-6 * sigma_y;
  const double df_dsy = (yield.value(sigma, sigma_y + h, porosity) - yield.value(sigma, sigma_y - h, porosity)) / (2 * h);
  const double h_alpha = sigma.cwiseProduct(N).sum() / ((1.0 - porosity) * sigma_y);
  double H_p = -df_dsy * H_y * h_alpha;
  if (kin) {  // N : h^beta (header)
    const Eigen::Matrix3d h_beta = 2.0 / 3.0 * kin->linear_modulus() * N - kin->recovery_modulus() * N.norm() * beta;
    H_p += N.cwiseProduct(h_beta).sum();
  }
  return j2i1_elastoplastic_tangent(K, mu, N, H_p);
}

}  // namespace tephra
