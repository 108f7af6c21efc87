#include "models/solid/CompMooneyRivlin.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/Kinematics.h"
#include "models/solid/ElasticPointLoop.h"

namespace tephra {

SolidPointResult comp_mooney_rivlin_point(const Eigen::Matrix3d& F, double density0,
                                          const CompMooneyRivlinParams& p) {
  const double C1 = p.C1, C2 = p.C2, C3 = p.C3(), C4 = p.C4();
  const Eigen::Matrix3d B = F * F.transpose();
  const Eigen::Matrix3d B2 = B * B;
  const double J = F.determinant();
  const double I1 = B.trace(), I2 = 0.5 * (I1 * I1 - B2.trace()), I3 = J * J;
  const double W3 = -2.0 * C3 / (I3 * I3 * I3) + 2.0 * C4 * (I3 - 1.0);
  SolidPointResult r;
  // VT eq. 4.12 (with the I of the erratum), = eq. 4.6 with W1 = C1, W2 = C2.
  r.stress = (2.0 / J) * ((C1 + C2 * I1) * B - C2 * B2) + (2.0 * J * W3) * Eigen::Matrix3d::Identity();
  // VT eq. 4.10.
  r.energy_density = C1 * (I1 - 3.0) + C2 * (I2 - 3.0) + C3 * (1.0 / (I3 * I3) - 1.0) + C4 * (I3 - 1.0) * (I3 - 1.0);
  // VT eq. 4.7: the stiffest principal direction.
  const Eigen::Vector3d lam = principal_stretches(F);
  double m = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double l2 = lam[i] * lam[i];
    m = std::max(m, 2.0 * C1 + 2.0 * C2 * (I1 - l2) + (20.0 * C3 / (I3 * I3) + 4.0 * C4 * I3 * (3.0 * I3 - 1.0)) / l2);
  }
  // m <= 0: W is not convex here (C4 < 0, i.e. nu below about 2/5, in volumetric
  // tension): no real wave speed; NaN makes the update reject the state.
  r.wave_speed = m > 0.0 ? std::sqrt(m / density0) : std::numeric_limits<double>::quiet_NaN();
  return r;
}

long CompMooneyRivlin::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_elastic_points(in, out, [&](const Eigen::Matrix3d& F, double rho0) { return comp_mooney_rivlin_point(F, rho0, p_); });
}

namespace {
// Hydrostatic p(J) = -W'(J) and W''(J) (header).
void cmr_hydrostatic(double J, const CompMooneyRivlinParams& p, double& pressure, double& W2) {
  const double C1 = p.C1, C2 = p.C2, C3 = p.C3(), C4 = p.C4();
  const double c = std::cbrt(J);
  pressure = -(2.0 * C1 / c + 4.0 * C2 * c - 4.0 * C3 / std::pow(J, 5) + 4.0 * C4 * J * (J * J - 1.0));
  W2 = -2.0 / 3.0 * C1 / (c * J) + 4.0 / 3.0 * C2 / (c * c) + 20.0 * C3 / std::pow(J, 6) + 4.0 * C4 * (3.0 * J * J - 1.0);
}
}  // namespace

std::optional<SolidEosPoint> CompMooneyRivlin::pressure_at_density(double rho, double density0, double) const {
  const double J = density0 / rho;
  SolidEosPoint e;
  double W2 = 0.0;
  cmr_hydrostatic(J, p_, e.pressure, W2);
  e.dp_drho = W2 * J * J / density0;
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> CompMooneyRivlin::density_at_pressure(double p_gauge, double density0, double T) const {
  // Newton in rho from rho0, bisection on a bracket once one is found (p increases with rho while W'' > 0).
  double rho = density0, lo = 0.0, hi = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 200; ++it) {
    const SolidEosPoint e = *pressure_at_density(rho, density0, T);
    const double r = e.pressure - p_gauge;
    if (std::abs(r) <= 1e-14 * (std::abs(p_gauge) + bulk_modulus())) return rho;
    if (r > 0) hi = rho; else lo = rho;
    double next = e.dp_drho > 0 ? rho - r / e.dp_drho : std::numeric_limits<double>::quiet_NaN();
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * rho;
    if (!(e.dp_drho > 0)) return std::numeric_limits<double>::quiet_NaN();  // not monotone here
    rho = next;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

ConstitutiveModelP CompMooneyRivlin::create(const ModelParameters& params) {
  CompMooneyRivlinParams p;
  p.C1 = params.get_double("he_constant_1");
  p.C2 = params.get_double("he_constant_2");
  p.nu = params.get_double("he_PR");
  if (!(p.C1 >= 0.0)) params.fail("he_constant_1", "he_constant_1 (C1) must be >= 0");
  if (!(p.C2 >= 0.0)) params.fail("he_constant_2", "he_constant_2 (C2) must be >= 0");
  if (!(p.C1 + p.C2 > 0.0)) params.fail("he_constant_1", "C1 + C2 (half the shear modulus) must be > 0");
  if (!(p.nu > -1.0 && p.nu < 0.5)) params.fail("he_PR", "he_PR (Poisson's ratio) must lie in (-1, 0.5)");
  return std::make_shared<CompMooneyRivlin>(p);
}

}  // namespace tephra
