#include "models/solid/TransIsoHyper.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/VectorParameter.h"
#include "models/solid/ElasticPointLoop.h"

namespace tephra {

double TransIsoHyperParams::C6() const { return C3 * std::expm1(C4 * (lambda_star - 1.0)) - C5 * lambda_star; }

double trans_iso_fibre_stress(double lb, const TransIsoHyperParams& p) {
  if (lb < 1.0) return 0.0;
  if (lb < p.lambda_star) return p.C3 * std::expm1(p.C4 * (lb - 1.0));
  return p.C5 * lb + p.C6();
}

namespace {
// d(lb W_f')/dlb, for the wave speed.
double fibre_tangent(double lb, const TransIsoHyperParams& p) {
  if (!(lb > 1.0)) return 0.0;
  if (lb < p.lambda_star) return p.C3 * p.C4 * std::exp(p.C4 * (lb - 1.0));
  return p.C5;
}
// int_1^lb C3 (e^{C4(x-1)} - 1)/x dx = C3 [e^{-C4}(Ei(C4 lb) - Ei(C4)) - ln lb].
double exp_branch_energy(double lb, const TransIsoHyperParams& p) {
  return p.C3 * (std::exp(-p.C4) * (std::expint(p.C4 * lb) - std::expint(p.C4)) - std::log(lb));
}
}  // namespace

double trans_iso_fibre_energy(double lb, const TransIsoHyperParams& p) {
  if (lb <= 1.0) return 0.0;
  if (lb < p.lambda_star) return exp_branch_energy(lb, p);
  return exp_branch_energy(p.lambda_star, p) + p.C5 * (lb - p.lambda_star) + p.C6() * std::log(lb / p.lambda_star);
}

SolidPointResult trans_iso_hyper_point(const Eigen::Matrix3d& F, double density0, const TransIsoHyperParams& p) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double J = F.determinant();
  const double Jm13 = 1.0 / std::cbrt(J);
  const Eigen::Matrix3d Fb = Jm13 * F;
  const Eigen::Matrix3d Bb = Fb * Fb.transpose();
  const Eigen::Matrix3d Bb2 = Bb * Bb;
  const double I1 = Bb.trace(), I2 = 0.5 * (I1 * I1 - Bb2.trace());
  const Eigen::Vector3d Fa = Fb * p.a0;
  const double lb = Fa.norm();  // sqrt(a0 . Cb a0)
  const Eigen::Vector3d f = Fa / lb;
  const double lnJ = std::log(J);
  SolidPointResult r;
  const Eigen::Matrix3d sd =
      (2.0 / J) * ((p.C1 + p.C2 * I1) * Bb - p.C2 * Bb2 - ((p.C1 * I1 + 2.0 * p.C2 * I2) / 3.0) * I);
  const double fs = trans_iso_fibre_stress(lb, p);
  r.stress = (p.kappa * lnJ / J) * I + sd + (fs / J) * (f * f.transpose() - I / 3.0);
  r.energy_density = 0.5 * p.kappa * lnJ * lnJ + p.C1 * (I1 - 3.0) + p.C2 * (I2 - 3.0) + trans_iso_fibre_energy(lb, p);
  const double modulus = p.kappa + 4.0 * p.shear_modulus() / 3.0 + fibre_tangent(lb, p);
  r.wave_speed = std::sqrt(modulus * J / density0);
  return r;
}

long TransIsoHyper::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_elastic_points(in, out, [&](const Eigen::Matrix3d& F, double rho0) { return trans_iso_hyper_point(F, rho0, p_); });
}

TransIsoHyperParams read_trans_iso_hyper_params(const ModelParameters& params, const std::string& type) {
  TransIsoHyperParams p;
  p.kappa = params.get_double("bulk_modulus");
  p.C1 = params.get_double("c1");
  p.C2 = params.get_double("c2");
  p.C3 = params.get_double("c3");
  p.C4 = params.get_double("c4");
  p.C5 = params.get_double("c5");
  // Vaango's current name is <fiber_pStretch>; older decks use <fiber_stretch>.
  if (params.has("fiber_pStretch")) p.lambda_star = params.get_double("fiber_pStretch");
  else p.lambda_star = params.get_double("fiber_stretch");
  if (!(p.kappa > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  if (!(p.C1 + p.C2 > 0.0)) params.fail("c1", "c1 + c2 (half the shear modulus) must be > 0");
  if (!(p.C3 >= 0.0)) params.fail("c3", "c3 must be >= 0");
  if (!(p.C4 > 0.0)) params.fail("c4", "c4 must be > 0");
  if (!(p.C5 >= 0.0)) params.fail("c5", "c5 must be >= 0");
  if (!(p.lambda_star >= 1.0)) params.fail("fiber_stretch", "the fibre straightening stretch must be >= 1");
  p.a0 = vector_parameter(params, "direction_of_symm");
  if (!(p.a0.norm() > 0.0)) params.fail("direction_of_symm", "direction_of_symm must be a nonzero vector");
  p.a0.normalize();
  // Read as Vaango requires them; they only act with failure_option = true.
  params.get_double("max_fiber_strain");
  params.get_double("max_matrix_strain");
  if (params.get_bool("failure_option", false))
    params.missing_feature("failure_option", type + " fibre/matrix failure (failure_option = true)");
  if (params.get_bool("useModifiedEOS", false))
    params.missing_feature("useModifiedEOS", type + " with useModifiedEOS = true");
  return p;
}

ConstitutiveModelP TransIsoHyper::create(const ModelParameters& params) {
  return std::make_shared<TransIsoHyper>(read_trans_iso_hyper_params(params, "trans_iso_hyper"));
}

}  // namespace tephra
