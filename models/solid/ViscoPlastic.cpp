#include "models/solid/ViscoPlastic.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include <Eigen/Eigenvalues>

#include "models/ModelParameters.h"
#include "models/solid/Kinematics.h"
#include "models/solid/MetalFailure.h"
#include "models/solid/PointLoop.h"
#include "models/solid/PolarNewton.h"

namespace tephra {

namespace {
using RowMap = Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>;
// history columns (ViscoPlastic::history())
constexpr int kBeta = 0, kYield = 1, kDrag = 2, kStrain = 3, kLocalized = 4, kVarf = 5, kLastT = 6;
constexpr long kMaxSubsteps = 100000;

Eigen::Matrix3d dev(const Eigen::Matrix3d& a) { return a - a.trace() / 3.0 * Eigen::Matrix3d::Identity(); }

// The stiffness of the overstress law at y (see the header).
double stiffness(const SuvicState& y, double rate_eq, double G, const SuvicParams& p) {
  if (!(rate_eq > 0.0)) return 0.0;
  const Eigen::Matrix3d r = dev(y.tau) - y.beta;
  const double X = std::sqrt(1.5 * r.squaredNorm());
  const double beta_sat = p.b0 * std::pow(rate_eq / p.eps0, 1.0 / p.n_b);
  return 3.0 * G * p.N * rate_eq / std::max(X - y.R, 1e-300) + p.A1 * rate_eq / beta_sat;
}

SuvicState axpy(const SuvicState& y, double h, const SuvicState& r) {
  return {y.tau + h * r.tau, y.beta + h * r.beta, y.R + h * r.R, y.K + h * r.K};
}
}  // namespace

double SuvicParams::prefactor() const { return A * std::exp(-Q / (Rg * T)); }

double suvic_rates(const SuvicState& y, const Eigen::Matrix3d& d, double K_bulk, double G, const SuvicParams& p,
                   SuvicState& rate, double* power) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d r = dev(y.tau) - y.beta;
  const double X = std::sqrt(1.5 * r.squaredNorm());  // eq. 10.30
  const double over = (X - y.R) / y.K;                   // eq. 10.29
  Eigen::Matrix3d eps_i = Eigen::Matrix3d::Zero();
  rate.beta.setZero();
  rate.R = rate.K = 0.0;
  double rate_eq = 0.0;
  if (over > 0.0 && X > 0.0) {
    const double pre = p.prefactor();
    rate_eq = pre * std::pow(over, p.N);  // eq. 10.32
    eps_i = rate_eq * 1.5 * r / X;        // eq. 10.31
    const double q = rate_eq / p.eps0;
    const double sigma_sat = p.s0 * std::pow(q, 1.0 / p.N);  // eq. 10.36
    const double beta_sat = p.b0 * std::pow(q, 1.0 / p.n_b);  // eq. 10.37
    const double R_sat = p.r0 * std::pow(q, 1.0 / p.n_R);     // eq. 10.37
    const double K_sat = (sigma_sat - beta_sat - R_sat) / std::pow(rate_eq / pre, 1.0 / p.N);  // eq. 10.38 (erratum)
    rate.beta = (2.0 / 3.0) * p.A1 * eps_i - (p.A1 / beta_sat) * rate_eq * y.beta;  // eq. 10.33
    if (y.R < R_sat) rate.R = p.A3 * rate_eq * (1.0 - y.R / R_sat);                  // eq. 10.34
    if (y.K < K_sat) rate.K = p.A5 * rate_eq * (1.0 - y.K / K_sat);                  // eq. 10.35
  }
  rate.tau = (K_bulk - 2.0 * G / 3.0) * d.trace() * I + 2.0 * G * (d - eps_i);
  if (power) *power = rate_eq > 0.0 ? y.tau.cwiseProduct(eps_i).sum() : 0.0;  // tau : eps_dot^i
  return rate_eq;
}

bool suvic_integrate(SuvicState& y, const Eigen::Matrix3d& d, double dt, double K_bulk, double G,
                     const SuvicParams& p, double& dissipation, double* eq_strain) {
  dissipation = 0.0;
  double strain = 0.0;
  double t = 0.0;
  for (long k = 0; t < dt; ++k) {
    if (k >= kMaxSubsteps) return false;
    SuvicState r1, r2;
    double w1 = 0.0, w2 = 0.0;
    const double e1 = suvic_rates(y, d, K_bulk, G, p, r1, &w1);
    const double lambda1 = stiffness(y, e1, G, p);
    double h = lambda1 > 0.0 ? std::min(dt - t, 0.05 / lambda1) : dt - t;
    // Heun: predictor y1 = y + h r1; the step is accepted when h times the stiffness at
    // both ends is <= 0.1 (an elastic predictor that overshoots into fast flow is cut).
    SuvicState y1;
    double e2 = 0.0;
    for (int tries = 0;; ++tries) {
      y1 = axpy(y, h, r1);
      e2 = suvic_rates(y1, d, K_bulk, G, p, r2, &w2);
      const double lambda = std::max(lambda1, stiffness(y1, e2, G, p));
      if (h * lambda <= 0.1 || tries >= 60) break;
      h = std::min(0.5 * h, 0.05 / lambda);
    }
    dissipation += 0.5 * h * (w1 + w2);
    strain += 0.5 * h * (e1 + e2);  // Heun's rule for int eps_dot_eq dt
    y.tau += 0.5 * h * (r1.tau + r2.tau);
    y.beta += 0.5 * h * (r1.beta + r2.beta);
    y.R += 0.5 * h * (r1.R + r2.R);
    y.K += 0.5 * h * (r1.K + r2.K);
    y.tau = 0.5 * (y.tau + y.tau.transpose()).eval();
    if (!y.tau.allFinite() || !y.beta.allFinite() || !std::isfinite(y.R) || !(y.K > 0.0)) return false;
    t = (dt - t <= h) ? dt : t + h;
  }
  if (eq_strain) *eq_strain = strain;
  return true;
}

bool suvic_truncate_rate(Eigen::Matrix3d& d, double tol) {
  bool all_below = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (std::abs(d(i, j)) < tol)
        d(i, j) = 0.0;
      else
        all_below = false;
    }
  return all_below;
}

double suvic_failure_measure(const SuvicFailure& f, const Eigen::Matrix3d& stress, const Eigen::Matrix3d& F) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  if (f.by_stress) return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(stress, Eigen::EigenvaluesOnly).eigenvalues()(2);
  if (f.by_pressure) return stress.trace() / 3.0;
  const Eigen::Matrix3d e = 0.5 * (I - (F * F.transpose()).inverse());  // Almansi strain
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(0.5 * (e + e.transpose()), Eigen::EigenvaluesOnly)
      .eigenvalues()(2);
}

std::vector<HistoryVariable> ViscoPlastic::history() const {
  std::vector<HistoryVariable> h = {
      {"backstress", 9, {0, 0, 0, 0, 0, 0, 0, 0, 0}, "deviatoric backstress beta, unrotated frame [Pa]"},
      {"yield", 1, {p_.R0}, "SUVIC-I yield stress R [Pa]"},
      {"drag", 1, {p_.K0}, "SUVIC-I drag stress K [Pa]"},
      {"plasticStrain", 1, {0.0}, "equivalent inelastic strain int eps_dot_eq dt"},
      {"localized", 1, {0.0}, "1 once the point failed (<check_failure>), else 0"},
      // A random failure variable is drawn at the point's first update (-1: not drawn yet).
      {"varf", 1, {m_.failure.random ? -1.0 : m_.failure.mean}, "failure variable v_f (stress [Pa] or strain)"}};
  if (m_.alpha != 0.0)
    h.push_back({"lastTemperature", 1, {0.0}, "temperature of the last update (thermal strain) [K]"});
  return h;
}

long ViscoPlastic::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const SuvicFailure& fail = m_.failure;
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    double& varf = out.history[kVarf][i];
    if (fail.random && varf < 0.0) varf = std::abs(fail.mean + fail.std * seeded_normal(0, i));
    const PolarDecomposition a = polar_decomposition_newton(in.F_old[i]), b = polar_decomposition_newton(in.F_new[i]);
    const auto stored = [&](const Eigen::Matrix3d& tau) {  // complementary energy, per reference volume
      const double pr = tau.trace() / 3.0;
      return J * (pr * pr / (2.0 * K_) + dev(tau).squaredNorm() / (4.0 * G_));
    };
    out.wave_speed[i] = std::sqrt((K_ + 4.0 * G_ / 3.0) * J / in.density0);
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
    if (out.history[kLocalized][i] != 0.0) {  // failed: the stress of the failure step (header)
      out.stress[i] = in.stress_old[i];
      out.energy_density[i] = stored(b.R.transpose() * out.stress[i] * b.R);
      return out.stress[i].allFinite();
    }
    // Unrotated strain increment (midpoint rule on U, as hypo_elastic).
    const Eigen::Matrix3d Gm = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
    Eigen::Matrix3d de = 0.5 * (Gm + Gm.transpose());
    if (in.dt > 0.0 && m_.tolerance > 0.0) {  // Vaango's <tolerance> on the laboratory D (header)
      Eigen::Matrix3d d_lab = b.R * (de / in.dt) * b.R.transpose();
      const Eigen::Matrix3d before = d_lab;
      if (suvic_truncate_rate(d_lab, m_.tolerance)) {  // the point "just sits there"
        if (m_.alpha != 0.0 && std::isfinite(in.temperature[i])) out.history[kLastT][i] = in.temperature[i];
        const Eigen::Matrix3d tau = a.R.transpose() * in.stress_old[i] * a.R;  // unrotated stress kept
        out.stress[i] = b.R * tau * b.R.transpose();
        out.energy_density[i] = stored(tau);
        return out.stress[i].allFinite();
      }
      if (d_lab != before) de = b.R.transpose() * d_lab * b.R * in.dt;
    }
    if (m_.alpha != 0.0) {  // thermal strain alpha (T_{n+1} - T_last) I (header)
      const double T = in.temperature[i];
      if (!std::isfinite(T)) return false;
      double& T_last = out.history[kLastT][i];
      if (!(T_last > 0.0)) T_last = T;  // the first update: the reference temperature
      de -= m_.alpha * (T - T_last) * I;
      T_last = T;
    }
    RowMap beta(&out.history[kBeta][9 * i]);
    const SuvicState start{a.R.transpose() * in.stress_old[i] * a.R, Eigen::Matrix3d(beta), out.history[kYield][i],
                           out.history[kDrag][i]};
    SuvicState y = start;
    double dissipation = 0.0, d_eq = 0.0;
    if (in.dt > 0.0) {
      if (!suvic_integrate(y, de / in.dt, in.dt, K_, G_, p_, dissipation, &d_eq)) return false;
    } else {  // initialization: an elastic increment (none for F_old = F_new)
      y.tau += (K_ - 2.0 * G_ / 3.0) * de.trace() * I + 2.0 * G_ * de;
    }
    Eigen::Matrix3d sigma = b.R * y.tau * b.R.transpose();
    if (d_eq > 0.0 && in.dt > 0.0) {  // Vaango's plastic heating (header)
      const double q = std::sqrt(1.5 * dev(sigma).squaredNorm());
      out.heating[i] = m_.taylor_quinney * q * d_eq / (in.dt * (in.density0 / J) * m_.specific_heat);
    }
    out.history[kStrain][i] += d_eq;
    if (fail.check && d_eq > 0.0) {
      bool localized = fail.melt_check && in.temperature[i] + out.heating[i] * in.dt > fail.melt_temperature;
      if (suvic_failure_measure(fail, sigma, in.F_new[i]) > varf) {
        localized = true;
        out.history[kLocalized][i] = 1.0;
        const double pm = sigma.trace() / 3.0;
        if (fail.zero_stress)
          sigma.setZero();
        else if (fail.no_tension)
          sigma = pm > 0.0 ? Eigen::Matrix3d::Zero() : Eigen::Matrix3d(pm * I);
      }
      if (localized) {  // Vaango's updateElastic: the internal variables keep their step-start values
        y.beta = start.beta;
        y.R = start.R;
        y.K = start.K;
      }
    }
    beta = y.beta;
    out.history[kYield][i] = y.R;
    out.history[kDrag][i] = y.K;
    out.stress[i] = sigma;
    out.energy_density[i] = stored(b.R.transpose() * sigma * b.R);
    out.plastic_work[i] = J * dissipation;
    return out.stress[i].allFinite();
  });
}

std::optional<SolidEosPoint> ViscoPlastic::pressure_at_density(double rho, double density0, double) const {
  SolidEosPoint e;
  e.pressure = 0.5 * K_ * (rho / density0 - density0 / rho);
  e.dp_drho = 0.5 * K_ * (1.0 / density0 + density0 / (rho * rho));
  e.c2 = K_ / rho;  // Vaango's speed of sound squared for this model
  return e;
}

std::optional<double> ViscoPlastic::density_at_pressure(double p_gauge, double density0, double) const {
  const double x = p_gauge / K_;
  return density0 * (x + std::sqrt(x * x + 1.0));
}

ConstitutiveModelP ViscoPlastic::create(const ModelParameters& params) {
  const double G = params.get_double("shear_modulus"), K = params.get_double("bulk_modulus");
  if (!(G > 0.0)) params.fail("shear_modulus", "shear_modulus must be > 0");
  if (!(K > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  SuvicModel m;
  m.alpha = params.get_double("coeff_thermal_expansion", m.alpha);
  if (!std::isfinite(m.alpha)) params.fail("coeff_thermal_expansion", "coeff_thermal_expansion must be finite");
  if (!params.mpm_flag("DoThermalExpansion", true)) m.alpha = 0.0;  // Vaango MPMFlags
  m.use_modified_eos = params.get_bool("useModifiedEOS", false);
  m.tolerance = params.get_double("tolerance", m.tolerance);
  if (!(m.tolerance >= 0.0) || !std::isfinite(m.tolerance)) params.fail("tolerance", "tolerance must be >= 0");
  m.initial_temperature = params.get_double("initial_material_temperature", m.initial_temperature);
  if (!(m.initial_temperature > 0.0) || !std::isfinite(m.initial_temperature))
    params.fail("initial_material_temperature", "initial_material_temperature must be > 0 K");
  params.get_bool("use_polar_decomposition_RMB", true);  // no effect: the polar decomposition is unique (header)
  m.specific_heat = params.enclosing_double("specific_heat", 0.0);
  if (!(m.specific_heat > 0.0))
    params.fail("shear_modulus", "visco_plastic plastic heating needs the material's <specific_heat> > 0");
  SuvicFailure& fl = m.failure;
  fl.check = params.get_bool("check_failure", false);
  fl.mean = params.get_double("failure_variable_mean", fl.mean);
  fl.std = params.get_double("failure_variable_std", fl.std);
  if (!std::isfinite(fl.mean)) params.fail("failure_variable_mean", "failure_variable_mean must be finite");
  if (!(fl.std >= 0.0) || !std::isfinite(fl.std))
    params.fail("failure_variable_std", "failure_variable_std must be >= 0");
  fl.random = params.get_string("failure_variable_distrib", "constant") != "constant";
  fl.by_stress = params.get_bool("failure_by_stress", true);
  fl.by_pressure = params.get_bool("failure_by_pressure", false);
  fl.zero_stress = params.get_bool("zero_stress_upon_failure", true);  // Vaango's default
  fl.no_tension = params.get_bool("allow_no_tension", false);
  fl.melt_check = params.get_bool("remove_particles", false);
  if (fl.melt_check) {
    fl.melt_temperature = params.enclosing_double("melt_temp", 0.0);
    if (!(fl.melt_temperature > 0.0))
      params.fail("remove_particles", "visco_plastic remove_particles needs the material's <melt_temp> > 0");
  }
  if (const ModelParameters* sc = params.block("stability_check")) {
    const std::string t = sc->type_attribute();
    if (t != "none" && !t.empty()) params.missing_feature("stability_check", "visco_plastic stability_check '" + t + "'");
  }
  if (const ModelParameters* eos = params.block("equation_of_state")) {
    const std::string t = eos->type_attribute();
    if (t != "default_hypo")
      params.missing_feature("equation_of_state", "visco_plastic <equation_of_state type=\"" + t + "\">");
    const double Ke = eos->get_double("bulk_modulus", K);
    if (Ke != K) eos->fail("bulk_modulus", "default_hypo bulk_modulus must equal the model's <bulk_modulus>");
  }
  const ModelParameters* f = params.block("viscoplastic_flow_model");
  if (!f) params.fail("viscoplastic_flow_model", "visco_plastic needs a <viscoplastic_flow_model type=\"suvic_i\">");
  if (f->type_attribute() != viscoplastic_flow_model_keys().front())
    params.missing_feature("viscoplastic_flow_model",
                           "viscoplastic_flow_model type '" + f->type_attribute() + "' (implemented: suvic_i)");
  SuvicParams p;
  auto rd = [&](const char* name, double& v, bool positive) {
    v = f->get_double(name, v);
    if (!std::isfinite(v) || (positive ? !(v > 0.0) : !(v >= 0.0)))
      f->fail(name, std::string(name) + (positive ? " must be > 0" : " must be >= 0"));
  };
  rd("coeff_backstress_evol", p.A1, false);
  rd("coeff_saturation_backstress", p.b0, true);
  rd("exponent_backstress", p.n_b, true);
  rd("ref_strainrate", p.eps0, true);
  rd("normalizing_inelastic_strainrate", p.A, true);
  rd("activation_energy", p.Q, false);
  rd("universal_gas_constant", p.Rg, true);
  rd("temperature", p.T, true);
  rd("exponent_inelastic_strainrate", p.N, true);
  rd("coeff_yieldstress_saturation", p.r0, true);
  rd("exponent_yieldstress", p.n_R, true);
  rd("coeff_yieldstress_evol", p.A3, false);
  rd("coeff_dragstress_evol", p.A5, false);
  rd("coeff_stress_saturation", p.s0, true);
  // Vaango reads the initial drag from the misspelt <intial_drag> (its schema has only that
  // spelling, so a deck can set K_0 only with it); <initial_drag> is accepted too (never both).
  if (f->has("intial_drag") && f->has("initial_drag"))
    f->fail("initial_drag", "give the initial drag once: <intial_drag> (Vaango's spelling) or <initial_drag>");
  rd(f->has("intial_drag") ? "intial_drag" : "initial_drag", p.K0, true);
  rd("initial_yield", p.R0, false);
  // Read, not used (static recovery, Vaango's theta integrator): see the header.
  f->get_double("exponent_backstress_evol", 1.0);
  f->get_double("normalizing_backstress", 1e6);
  f->get_double("exponent_dragstress", 4.0);
  f->get_double("integration_parameter_theta", 0.0);
  return std::make_shared<ViscoPlastic>(K, G, p, m);
}

}  // namespace tephra
