#include "models/solid/CompNeoHookPlastic.h"

#include "models/solid/ModifiedEos.h"

#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {
constexpr int kBbar = 0;    // history column: bbar_e, 9 components
constexpr int kAlpha = 1;   // history column: equivalent plastic strain
constexpr int kAlphaSlot = 9;  // its place in the point's hist[] (after the 9 of bbar_e)
const double kSqrt23 = std::sqrt(2.0 / 3.0);

// The root x near x0 of det(A + x I) = 1 for a traceless symmetric A:
// det(A + x I) = x^3 - (tr(A^2)/2) x + det A (Cayley-Hamilton with tr A = 0).
// Newton from x0 = I_e (I_e - x = O(dgamma |s|/G)); the cubic is monotone
// increasing near the root since x^2 > tr(A^2)/6 for det bbar_e = 1.
double volume_preserving_trace(const Eigen::Matrix3d& A, double x0) {
  const double a2 = 0.5 * (A * A).trace(), d = A.determinant();
  double x = x0;
  for (int it = 0; it < 20; ++it) {
    const double g = x * x * x - a2 * x + d - 1.0;
    const double dx = g / (3.0 * x * x - a2);
    x -= dx;
    if (std::abs(dx) <= 1e-16 * std::abs(x)) break;
  }
  return x;
}
}  // namespace

std::vector<HistoryVariable> CompNeoHookPlastic::history() const {
  // Vaango's UCNH labels.
  return {{"bElBar", 9, {1, 0, 0, 0, 1, 0, 0, 0, 1}, "isochoric elastic left Cauchy-Green tensor J^{-2/3} F_e F_e^T [-]"},
          {"plasticStrain", 1, {p_.initial_alpha}, "equivalent plastic strain alpha [-]"}};
}

bool CompNeoHookPlastic::update_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new, double density0,
                                      double* hist, PointOut& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double K = p_.bulk_modulus, G = p_.shear_modulus, H = p_.hardening_modulus;
  const double J = F_new.determinant();
  if (!(J > 0.0) || !std::isfinite(J)) return false;
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> bbar(hist + kBbar);

  Eigen::Matrix3d bbar_trial;
  if (p_.use_plasticity) {
    const double J_old = F_old.determinant();
    if (!(J_old > 0.0)) return false;
    // Relative deformation gradient and its isochoric part (Box 9.1 step 1).
    const Eigen::Matrix3d f = F_new * F_old.inverse();
    const Eigen::Matrix3d fbar = std::cbrt(J_old / J) * f;  // det f = J / J_old
    bbar_trial = fbar * Eigen::Matrix3d(bbar) * fbar.transpose();
    bbar_trial = (0.5 * (bbar_trial + bbar_trial.transpose())).eval();  // exact symmetry: no round-off drift
  } else {
    bbar_trial = std::pow(J, -2.0 / 3.0) * (F_new * F_new.transpose());
  }
  const double Ie = bbar_trial.trace() / 3.0;
  const Eigen::Matrix3d s_trial = G * (bbar_trial - Ie * I);
  Eigen::Matrix3d s = s_trial;
  Eigen::Matrix3d bbar_new = bbar_trial;
  double dgamma = 0.0, plastic_work = 0.0;
  if (p_.use_plasticity) {
    const double norm_trial = s_trial.norm();
    const double alpha = hist[kAlphaSlot];
    const double f_trial = norm_trial - kSqrt23 * (p_.yield_stress + H * alpha);
    if (f_trial > 0.0) {
      const double mubar = G * Ie;
      dgamma = f_trial / (2.0 * mubar * (1.0 + H / (3.0 * mubar)));  // Box 9.1 step 3
      s = s_trial * (1.0 - 2.0 * mubar * dgamma / norm_trial);        // s_trial - 2 mubar dgamma n
      hist[kAlphaSlot] = alpha + kSqrt23 * dgamma;
      const Eigen::Matrix3d A = s / G;
      const double x = volume_preserving_trace(A, Ie);
      bbar_new = A + x * I;
      // Dissipation of the step: the stored energy the return releases at fixed F,
      // Psi(bbar_trial) - Psi(bbar_new) = G/2 (tr bbar_trial - tr bbar_new) = 3G/2 (I_e - x)
      // (> 0: shrinking dev at fixed I_e raises det, so x < I_e). With the
      // elastic predictor this closes the energy balance work = Psi + D; the
      // textbook |s| dgamma = (sigma_y + H alpha) dalpha agrees with it only to
      // O(|s|/G) (1.7% at sigma_y/G = 0.05 in uniaxial strain).
      plastic_work = 1.5 * G * (Ie - x);
    }
  }
  bbar = bbar_new;

  const double mean = 0.5 * K * (J - 1.0 / J);  // Vaango HyperElasticEOS: sigma_m = K/2 (J - 1/J)
  out.r.stress = mean * I + s / J;
  out.r.energy_density = 0.5 * K * (0.5 * (J * J - 1.0) - std::log(J)) + 0.5 * G * (bbar_new.trace() - 3.0);
  const double K_t = 0.5 * K * (1.0 + 1.0 / (J * J));
  out.r.wave_speed = std::sqrt((K_t + 4.0 * G / 3.0) * J / density0);
  out.plastic_work = plastic_work;  // per reference volume (Kirchhoff stress, bbar_e per reference state)
  return out.r.stress.allFinite() && bbar_new.allFinite();
}

long CompNeoHookPlastic::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return for_each_point(in.F_new.size(), [&](size_t i) {
    double hist[10];
    for (int k = 0; k < 9; ++k) hist[k] = out.history[kBbar][9 * i + k];
    hist[kAlphaSlot] = out.history[kAlpha][i];
    PointOut po;
    if (!update_point(in.F_old[i], in.F_new[i], in.density0, hist, po)) return false;
    for (int k = 0; k < 9; ++k) out.history[kBbar][9 * i + k] = hist[k];
    out.history[kAlpha][i] = hist[kAlphaSlot];
    out.stress[i] = po.r.stress;
    out.wave_speed[i] = po.r.wave_speed;
    out.energy_density[i] = po.r.energy_density;
    out.plastic_work[i] = po.plastic_work;
    out.heating[i] = 0.0;  // Vaango UCNH: pdTdt = 0
    return true;
  });
}

std::optional<SolidEosPoint> CompNeoHookPlastic::pressure_at_density(double rho, double density0, double) const {
  const double K = p_.bulk_modulus;
  SolidEosPoint e;
  e.pressure = 0.5 * K * (rho / density0 - density0 / rho);
  e.dp_drho = 0.5 * K * (1.0 / density0 + density0 / (rho * rho));
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> CompNeoHookPlastic::density_at_pressure(double p_gauge, double density0, double) const {
  const double q = p_gauge / p_.bulk_modulus;
  return density0 * (q + std::sqrt(q * q + 1.0));
}

SolidEosPoint modified_eos_pressure(double rho, double density0, double K, double p_ref) {
  if (rho < density0) return modified_eos_expansion(rho, density0, K, p_ref);
  SolidEosPoint e;
  e.pressure = 0.5 * K * (rho / density0 - density0 / rho);
  e.dp_drho = 0.5 * K * (1.0 / density0 + density0 / (rho * rho));
  e.c2 = e.dp_drho;
  return e;
}

double modified_eos_density(double p_gauge, double density0, double K, double p_ref) {
  if (p_gauge < 0.0) return modified_eos_expansion_density(p_gauge, density0, K, p_ref);
  const double q = p_gauge / K;
  return density0 * (q + std::sqrt(q * q + 1.0));
}

ConstitutiveModelP CompNeoHookPlastic::create(const ModelParameters& params, const std::string& type) {
  CompNeoHookPlasticParams p;
  p.bulk_modulus = params.get_double("bulk_modulus");
  p.shear_modulus = params.get_double("shear_modulus");
  if (!(p.bulk_modulus > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  if (!(p.shear_modulus > 0.0)) params.fail("shear_modulus", "shear_modulus must be > 0");
  p.use_modified_eos = params.get_bool("useModifiedEOS", false);
  p.use_plasticity = params.get_bool("usePlasticity", type == "comp_neo_hook_plastic");
  if (p.use_plasticity) {
    p.yield_stress = params.get_double("yield_stress");
    p.hardening_modulus = params.get_double("hardening_modulus");
    p.initial_alpha = params.get_double("alpha", 0.0);
    if (!(p.yield_stress > 0.0)) params.fail("yield_stress", "yield_stress must be > 0");
    if (!(p.hardening_modulus >= 0.0)) params.fail("hardening_modulus", "hardening_modulus must be >= 0");
    if (!(p.initial_alpha >= 0.0)) params.fail("alpha", "alpha (initial plastic strain) must be >= 0");
    const std::string dist = params.get_string("yield_distrib", "constant");
    if (dist != "constant")
      params.missing_feature("yield_distrib", type + " yield_distrib '" + dist + "' (implemented: constant)");
  }
  if (params.get_bool("useDamage", false))
    params.missing_feature("useDamage", type + " with useDamage = true (UCNH brittle damage)");
  if (params.get_bool("useInitialStress", false))
    params.missing_feature("useInitialStress", type + " with useInitialStress = true");
  if (const ModelParameters* eos = params.block("equation_of_state")) {
    const std::string t = eos->type_attribute();
    if (t != "default_hyper")
      params.missing_feature("equation_of_state", type + " <equation_of_state type=\"" + t + "\">");
    // Vaango's UCNH overrides the EOS block's bulk modulus with <bulk_modulus>
    // (d_eos->setBulkModulus): the value is read and not used.
    eos->get_double("bulk_modulus", 0.0);
  }
  // <strain_limit>, <reduction_factor> (in the MPMICE decks) belong to Vaango's
  // retired CompNeoHookPlas and are not read by UCNH either: accepted, unused.
  params.get_double("strain_limit", 0.0);
  params.get_double("reduction_factor", 0.0);
  return std::make_shared<CompNeoHookPlastic>(p, type);
}

}  // namespace tephra
