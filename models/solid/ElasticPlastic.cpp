#include "models/solid/ElasticPlastic.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/plasticity/ContinuumTangent.h"
#include "models/plasticity/PorousReturn.h"
#include "models/solid/Kinematics.h"
#include "models/solid/MetalPointLoop.h"
#include "models/solid/SubModelAssembly.h"

namespace tephra {

namespace {
// The fixed part of the history (history() order); optional columns follow.
enum HistoryIndex { kEpsP = 0, kEpsPRate, kStrainRate, kPorosity, kDamage, kLocalized, kFixedCount };
constexpr int kMaxHistory = kFixedCount + 5 + 9;  // + optional scalars, backStress (9)
}  // namespace

std::vector<HistoryVariable> ElasticPlastic::history() const {
  std::vector<HistoryVariable> h = {
      {"eqPlasticStrain", 1, {0.0}, "equivalent plastic strain eps_p [-]"},
      {"eqPlasticStrainRate", 1, {0.0}, "equivalent plastic strain rate eps_p_dot = Delta eps_p/dt [1/s]"},
      {"eqStrainRate", 1, {0.0}, "equivalent strain rate sqrt(2/3)|d| [1/s]"},
      {"porosity", 1, {failure_.initial_porosity}, "void volume fraction phi [-]"},
      {"damage", 1, {failure_.initial_damage()}, "scalar damage D [-]"},
      {"localized", 1, {0.0}, "1 once the point failed (melting, TEPLA, max stress), else 0"}};
  if (k_sigma_e_ >= 0) h.push_back({"mtsStructureStress", 1, {0.0}, "MTS evolving structure stress sigma_e [Pa]"});
  if (k_T0_ >= 0) {
    h.push_back({"thermalReferenceTemperature", 1, {0.0}, "T_0 of VT eq. 18.81, set at the first update [K]"});
    h.push_back({"lastTemperature", 1, {0.0}, "temperature of the last update [K]"});
  }
  if (k_evp_ >= 0)
    h.push_back({"plasticVolumetricStrain", 1, {0.0}, "ln J^p = sum of tr(Delta eps^p) (porous yield only) [-]"});
  if (k_drawn_ >= 0) h.push_back({"initialFieldsDrawn", 1, {0.0}, "1 once the Gaussian initial porosity/damage is drawn"});
  if (k_beta_ >= 0)
    h.push_back({"backStress", 9, std::vector<double>(9, 0.0),
                 "backstress beta (VT ch. 11, eq. 18.47-18.48), in the unrotated frame of the point [Pa]"});
  return h;
}

ElasticPlastic::Return ElasticPlastic::plastic_return(double q_trial, double mu, double dt, const PlasticState& st,
                                                      double c) const {
  // Without a backstress the return depends on s_trial through q_trial only: any deviator of that norm.
  Eigen::Matrix3d s_trial = Eigen::Matrix3d::Zero();
  s_trial(0, 0) = std::sqrt(2.0 / 3.0) * q_trial / std::sqrt(1.5);
  s_trial(1, 1) = s_trial(2, 2) = -0.5 * s_trial(0, 0);
  return plastic_return(s_trial, Eigen::Matrix3d::Zero(), mu, dt, st, c);
}

ElasticPlastic::Return ElasticPlastic::plastic_return(const Eigen::Matrix3d& s_trial, const Eigen::Matrix3d& beta_n,
                                                      double mu, double dt, const PlasticState& st, double c) const {
  Return r;
  const double eps_n = st.eps_p, T_n = st.temperature;
  const double k32 = std::sqrt(1.5);
  const double H1 = kin_ ? kin_->linear_modulus() : 0.0, H2 = kin_ ? kin_->recovery_modulus() : 0.0;
  PlasticState s = st;
  FlowStress y;
  // sigma_y and its derivatives at (Dg, T); MTS: sigma_e(Dg) from eq. 10.19 integrated over Dg
  // at the step's rate and T (FlowStressModel::evolve_internal_stress).
  auto evaluate = [&](double dg, double T) {
    s.eps_p = eps_n + dg;
    s.eps_p_rate = dg / dt;
    s.temperature = T;
    if (mts_) {
      s.sigma_e = st.sigma_e;
      s.sigma_e = flow_->evolve_internal_stress(s, dg);
    }
    y = flow_->evaluate(s);
  };
  // T(Dg) from r_T = T - T_n - Dg c sigma_y(Dg, T) = 0; returns dT/dDg.
  auto temperature_at = [&](double dg, double& T) {
    T = T_n;
    evaluate(dg, T);
    if (c > 0.0 && dg > 0.0)
      for (int k = 0; k < 30; ++k) {
        const double h = T - T_n - dg * c * y.sigma_y;
        const double dh = 1.0 - dg * c * y.d_T;
        T -= h / dh;
        evaluate(dg, T);
        if (std::abs(h) <= 1e-13 * T) break;
      }
    const double H = y.d_eps_p + y.d_eps_p_rate / dt;
    return c > 0.0 ? c * (y.sigma_y + dg * H) / (1.0 - dg * c * y.d_T) : 0.0;
  };
  // The backstress part (header): a(Dg) = 1/(1 + sqrt(3/2) H2 Dg), xi*(Dg) = s_trial - a beta_n,
  // q*(Dg) = sqrt(3/2)|xi*|; the residual is q* - (3 mu + a H1) Dg - sigma_y.
  auto q_star = [&](double dg, double& dq) {
    const double a = 1.0 / (1.0 + k32 * H2 * dg), da = -k32 * H2 * a * a;
    const Eigen::Matrix3d xs = s_trial - a * beta_n;
    const double n = xs.norm();
    dq = n > 0.0 ? -da * k32 * xs.cwiseProduct(beta_n).sum() / n - da * H1 * dg - a * H1 : -a * H1;
    return k32 * n - a * H1 * dg;
  };

  double dq0 = 0.0;
  const double q0 = q_star(0.0, dq0);  // sqrt(3/2)|s_trial - beta_n|
  double lo = 0.0, hi = k32 * (s_trial.norm() + beta_n.norm()) / (3.0 * mu);  // residual(hi) <= -sigma_y <= 0
  double T = T_n;
  temperature_at(0.0, T);
  const double tol = p_.tolerance * q0;
  double x = std::min(hi, (q0 - y.sigma_y) / (3.0 * mu + H1 + std::max(0.0, y.d_eps_p)));
  double g = 0.0;
  for (int it = 1; it <= 100; ++it) {
    r.iterations = it;
    const double dTdx = temperature_at(x, T);
    double dq = 0.0;
    g = q_star(x, dq) - 3.0 * mu * x - y.sigma_y;
    if (std::abs(g) <= tol) break;
    (g > 0.0 ? lo : hi) = x;
    const double dg = dq - 3.0 * mu - y.d_eps_p - y.d_eps_p_rate / dt - y.d_T * dTdx;
    double next = dg < 0.0 ? x - g / dg : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // bisection safeguard
    if (hi - lo <= 1e-15 * std::max(hi, 1e-300)) break;
    x = next;
  }
  r.delta_gamma = x;
  r.temperature = T;
  r.sigma_y = y.sigma_y;
  r.hardening = y.d_eps_p;
  r.d_T = y.d_T;
  r.sigma_e = mts_ ? s.sigma_e : st.sigma_e;
  r.residual = g;
  // Flow direction n = xi*/|xi*| (parallel to xi_{n+1}) and the plastic strain increment.
  const double a = 1.0 / (1.0 + k32 * H2 * x);
  const Eigen::Matrix3d xs = s_trial - a * beta_n;
  const double n = xs.norm();
  r.plastic_strain = n > 0.0 ? Eigen::Matrix3d((k32 * x / n) * xs) : Eigen::Matrix3d::Zero();
  return r;
}

bool ElasticPlastic::update_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new,
                                  const Eigen::Matrix3d& stress_old, double T, double dt, double density0,
                                  double* hist, PointOut& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double J = F_new.determinant();
  if (!(J > 0.0) || !(F_old.determinant() > 0.0) || !std::isfinite(J) || !std::isfinite(T)) return false;
  const PolarDecomposition a = polar_decomposition(F_old), b = polar_decomposition(F_new);
  // Unrotated strain increment (midpoint rule for d_hat = sym(U_dot U^{-1})).
  const Eigen::Matrix3d G = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
  const Eigen::Matrix3d de = 0.5 * (G + G.transpose());
  const Eigen::Matrix3d tau_n = a.R.transpose() * stress_old * a.R;
  const double p_n = tau_n.trace() / 3.0;
  const Eigen::Matrix3d s_n = tau_n - p_n * I;
  const double rho = density0 / J;

  // Thermal reference T_0 (first update) and the last temperature (rate-form EOS).
  double T0 = T, T_last = T;
  if (k_T0_ >= 0) {
    if (!(hist[k_T0_] > 0.0)) hist[k_T0_] = hist[k_Tprev_] = T;
    T0 = hist[k_T0_];
    T_last = hist[k_Tprev_];
  }

  // Moduli and melting temperature at the start of the step (VT §18.2).
  PlasticState st;
  st.eps_p = hist[kEpsP];
  st.eps_p_rate = 0.0;
  st.temperature = T;
  st.density0 = density0;
  st.density = rho;
  st.pressure = -p_n;
  st.porosity = hist[kPorosity];
  st.sigma_e = k_sigma_e_ >= 0 ? hist[k_sigma_e_] : 0.0;
  st.melt_temperature = melt_->melt_temperature(st);
  const double mu = shear_->shear_modulus(st);
  st.shear_modulus = mu;
  const double cp = p_.compute_specific_heat ? cp_->specific_heat(st) : p_.specific_heat;
  const double c = (p_.isothermal || dt <= 0.0) ? 0.0 : p_.taylor_quinney / (rho * cp);

  // Deviatoric trial stress (VT eq. 18.45).
  const Eigen::Matrix3d s_trial = s_n + 2.0 * mu * (de - (de.trace() / 3.0) * I);
  const double q_trial = std::sqrt(1.5 * s_trial.squaredNorm());
  Eigen::Matrix3d s = s_trial;
  double delta = 0.0, sigma_y = 0.0, T_new = T, H = 0.0, work = 0.0, tr_dp = 0.0;
  Eigen::Matrix3d xi = s_trial;  // the returned stress relative to the backstress (flow direction)
  std::optional<Tangent4> porous_tangent;  // porous yield with a stability check only
  bool melted = false, plastic = false;

  // Mechanical mean stress (VT eq. 18.81 without the thermal term): the EOS at J^e = J/J^p
  // (J^p = 1 for isochoric J2 flow).
  EosInput ei;
  ei.J = k_evp_ >= 0 ? J * std::exp(-hist[k_evp_]) : J;
  ei.p_old = p_n + 3.0 * eos_->bulk_modulus() * p_.alpha * (T_last - T0);  // the mechanical part at t_n
  ei.dt = dt;
  ei.trace_d = dt > 0.0 ? de.trace() / dt : 0.0;
  const EosResult eos = eos_->evaluate(ei);
  const double kappa_t = ei.J * eos.dp_dJ;  // tangent bulk modulus kappa = J dp/dJ
  const double kappa = kappa_t > 0.0 ? kappa_t : eos_->bulk_modulus();
  double p_mech = eos.p;
  if (dt > 0.0) {
    const FlowStress y0 = flow_->evaluate(st);
    melted = T > st.melt_temperature || !(y0.sigma_y > 0.0);
    if (melted) {
      // Vaango: with <do_melting> the deviator vanishes; without it the old deviator is kept.
      s = p_.do_melting ? Eigen::Matrix3d::Zero() : s_n;
    } else if (yield_ && mu > 0.0) {
      // Pressure-dependent yield (Gurson, Rousselier): two-invariant return (PorousReturn.h),
      // isothermal at T; heating T_new = T + chi sigma:Delta eps^p/(rho C_p) after it.
      PorousReturnInput pr;
      pr.q_trial = q_trial;
      pr.I1_trial = 3.0 * (eos.p - 3.0 * kappa * p_.alpha * (T - T0));
      pr.n_hat = unit_deviator(s_trial);
      pr.K = kappa;
      pr.mu = mu;
      pr.dt = dt;
      pr.tolerance = std::max(p_.tolerance, 1e-11);
      pr.state = st;
      if (kin_) {  // yield on xi = sigma - beta (VT 18.64-18.70; PorousReturn.h)
        pr.beta_n = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_);
        pr.H_lin = kin_->linear_modulus();
        pr.H_rec = kin_->recovery_modulus();
      }
      const ShiftedTrial xt = shifted_trial(pr);
      if (yield_at(*yield_, xt.q, xt.I1, xt.n_hat, y0.sigma_y, st.porosity) > 0.0) {
        plastic = true;
        const PorousReturnResult r = porous_return(*yield_, *flow_, pr);
        if (!r.converged) return false;
        delta = r.delta_eps_p;
        sigma_y = r.sigma_y;
        const double I1 = r.I1 + r.backstress.trace();  // tr sigma = tr xi + tr beta
        s = r.stress - (I1 / 3.0) * I;
        tr_dp = r.plastic_strain.trace();
        // sigma : Delta eps^p (= (1 - phi) sigma_y Delta eps_p + beta : Delta eps^p with a backstress)
        work = r.stress.cwiseProduct(r.plastic_strain).sum();
        T_new = T + c * work;
        if (kin_) Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_) = r.backstress;
        if (has_stability_check(failure_)) {  // the J2-I1 continuum tangent (VT §18.6.2) at the returned state
          porous_tangent = yield_continuum_tangent(*yield_, r.xi, r.sigma_y, r.hardening, st.porosity, kappa, mu,
                                                   kin_.get(), r.backstress);
        }
        hist[k_evp_] += tr_dp;
        if (k_sigma_e_ >= 0) hist[k_sigma_e_] = r.sigma_e;  // MTS: sigma_e of the return (PorousReturn.h)
        if (eos_->type() == "default_hypo") {
          p_mech = I1 / 3.0 + 3.0 * kappa * p_.alpha * (T - T0);  // p_tr - kappa tr(Delta eps^p)
        } else {
          EosInput e2 = ei;
          e2.J = J * std::exp(-hist[k_evp_]);
          p_mech = eos_->evaluate(e2).p;
        }
      }
    } else if (mu > 0.0) {
      // J2 return on xi = s - beta (VT 18.49-18.52; beta = 0 without kinematic hardening).
      Eigen::Matrix3d beta_n = Eigen::Matrix3d::Zero();
      if (kin_) beta_n = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_);
      if (std::sqrt(1.5 * (s_trial - beta_n).squaredNorm()) > y0.sigma_y) {
        plastic = true;
        const Return r = plastic_return(s_trial, beta_n, mu, dt, st, c);
        delta = r.delta_gamma;
        sigma_y = r.sigma_y;
        T_new = r.temperature;
        if (k_sigma_e_ >= 0) hist[k_sigma_e_] = r.sigma_e;
        s = s_trial - 2.0 * mu * r.plastic_strain;  // VT 18.46 with M_dev = sqrt(3/2) xi/|xi|
        Eigen::Matrix3d beta = beta_n;
        if (kin_) {
          beta = kin_->backstress_after(beta_n, r.plastic_strain);
          Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_) = beta;
        }
        xi = s - beta;
        // Hardening modulus of the stability tangent: adiabatic isotropic part
        // dsigma_y/deps_p + dsigma_y/dT c sigma_y, plus the kinematic part (KinematicHardeningModel::j2_modulus).
        H = r.hardening + r.d_T * c * r.sigma_y + (kin_ ? kin_->j2_modulus(beta, xi) : 0.0);
        // Plastic work sigma : Delta eps^p (VT 12.14); sigma_y Dg without a backstress.
        work = kin_ ? s.cwiseProduct(r.plastic_strain).sum() : sigma_y * delta;
      }
    }
  }
  hist[kEpsP] += delta;
  hist[kEpsPRate] = dt > 0.0 ? delta / dt : 0.0;
  hist[kStrainRate] = dt > 0.0 ? std::sqrt(2.0 / 3.0) * de.norm() / dt : 0.0;

  // Mean stress (VT eq. 18.81): the EOS part minus the thermal pressure.
  const double sigma_m = p_mech - 3.0 * kappa * p_.alpha * (T_new - T0);
  if (k_T0_ >= 0) hist[k_Tprev_] = T_new;

  const Eigen::Matrix3d tau = sigma_m * I + s;
  out.r.stress = b.R * tau * b.R.transpose();
  out.r.stress = (0.5 * (out.r.stress + out.r.stress.transpose())).eval();  // eval: no aliasing
  out.r.wave_speed = std::sqrt((kappa + 4.0 * mu / 3.0) / rho);
  out.r.energy_density =
      J * (sigma_m * sigma_m / (2.0 * eos_->bulk_modulus()) + (mu > 0.0 ? s.squaredNorm() / (4.0 * mu) : 0.0));
  out.plastic_work = J * work;
  out.heating = dt > 0.0 ? (T_new - T) / dt : 0.0;  // = chi sigma_y eps_p_dot/(rho C_p) (VT 18.20)

  // Porosity, damage and failure (VT ch. 12, 15, 16), after a plastic step.
  if (plastic) {
    st.eps_p = hist[kEpsP];
    st.eps_p_rate = hist[kEpsPRate];
    st.temperature = T_new;
    evolve_porosity_and_damage(failure_, out.r.stress, st, dt, hist[kPorosity], hist[kDamage], tr_dp);
  }
  if (dt > 0.0 && metal_point_failed(failure_, melted, plastic, hist[kPorosity], hist[kDamage], out.r.stress))
    hist[kLocalized] = 1.0;
  if (plastic && (porous_tangent ? metal_point_unstable(failure_, de, tau, dt, *porous_tangent)
                                 : metal_point_unstable(failure_, de, tau, xi, dt, kappa, mu, H)))
    hist[kLocalized] = 1.0;
  return out.r.stress.allFinite() && std::isfinite(out.heating) && std::isfinite(hist[kDamage]);
}

long ElasticPlastic::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_metal_points<kMaxHistory>(*this, history_count_, in, out, k_drawn_, kPorosity, kDamage);
}

std::optional<SolidEosPoint> ElasticPlastic::pressure_at_density(double rho, double density0, double) const {
  const EosPressurePoint e = eos_pressure_at_density(*eos_, rho, density0);
  return SolidEosPoint{e.pressure, e.dp_drho, e.c2};
}

std::optional<double> ElasticPlastic::density_at_pressure(double p_gauge, double density0, double) const {
  return eos_density_at_pressure(*eos_, p_gauge, density0);
}

ConstitutiveModelP ElasticPlastic::create(const ModelParameters& params) {
  using assembly::sub_model;
  const std::string name = "elastic_plastic";
  auto m = std::make_shared<ElasticPlastic>();
  ElasticPlasticParams& p = m->p_;
  p.bulk_modulus = params.get_double("bulk_modulus");
  p.shear_modulus = params.get_double("shear_modulus");
  if (!(p.bulk_modulus > 0.0)) params.fail("bulk_modulus", "must be > 0");
  if (!(p.shear_modulus > 0.0)) params.fail("shear_modulus", "must be > 0");
  p.alpha = params.get_double("coeff_thermal_expansion", 1.0e-5);
  if (!(p.alpha >= 0.0)) params.fail("coeff_thermal_expansion", "must be >= 0");
  if (!params.mpm_flag("DoThermalExpansion", true)) p.alpha = 0.0;  // Vaango: alpha = 0 unless the MPM flag
  p.taylor_quinney = params.get_double("taylor_quinney_coeff", 0.9);
  if (!(p.taylor_quinney >= 0.0 && p.taylor_quinney <= 1.0)) params.fail("taylor_quinney_coeff", "must be in [0, 1]");
  p.tolerance = params.get_double("tolerance", 1.0e-10);
  if (!(p.tolerance > 0.0 && p.tolerance < 1.0)) params.fail("tolerance", "must be in (0, 1)");
  p.isothermal = params.get_bool("isothermal", false);
  p.do_melting = params.get_bool("do_melting", true);
  p.compute_specific_heat = params.get_bool("compute_specific_heat", false);
  params.get_double("initial_material_temperature", 294.0);  // Vaango hands it to no law of this model
  p.use_modified_eos = params.get_bool("useModifiedEOS", false);


  SubModelContext ctx;
  ctx.bulk_modulus = p.bulk_modulus;
  ctx.shear_modulus = p.shear_modulus;
  ctx.melt_temperature = params.enclosing_double("melt_temp", 0.0);
  ctx.specific_heat = params.enclosing_double("specific_heat", 0.0);
  ctx.room_temperature = params.enclosing_double("room_temp", 0.0);
  ctx.density0 = params.enclosing_double("density", 0.0);
  p.specific_heat = ctx.specific_heat;
  if (!p.isothermal && !p.compute_specific_heat && !(p.specific_heat > 0.0))
    params.fail("isothermal", name + " with plastic heating needs the material's <specific_heat> > 0");

  m->failure_ = read_metal_failure(params, ctx, name);
  m->eos_ = sub_model(params, name, "equation_of_state", plasticity_eos_models(), "default_hypo", ctx,
                      [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                        return create_plasticity_eos(k, q, c);
                      });
  m->shear_ = sub_model(params, name, "shear_modulus_model", shear_modulus_models(), "constant_shear", ctx,
                        [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                          return create_shear_modulus_model(k, q, c);
                        });
  m->melt_ = sub_model(params, name, "melting_temp_model", melting_temperature_models(), "constant_Tm", ctx,
                       [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                         return create_melting_temperature_model(k, q, c);
                       });
  m->cp_ = sub_model(params, name, "specific_heat_model", specific_heat_models(), "constant_Cp", ctx,
                     [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                       return create_specific_heat_model(k, q, c);
                     });
  m->flow_ = sub_model(params, name, "flow_model", flow_stress_models(), "", ctx,
                       [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                         return create_flow_stress_model(k, q, c);
                       });
  int k = kFixedCount;
  m->mts_ = m->flow_->type() == "mechanical_threshold_stress";
  if (m->mts_) m->k_sigma_e_ = k++;
  if (p.alpha != 0.0) {
    m->k_T0_ = k++;
    m->k_Tprev_ = k++;
  }
  // Yield condition: von Mises takes the J2 return; others the two-invariant return.
  const auto yield = sub_model(params, name, "yield_condition", yield_conditions(), "", ctx,
                               [](const std::string& kk, const ModelParameters& q, const SubModelContext& cc) {
                                 return create_yield_condition(kk, q, cc);
                               });
  if (yield->type() != "von_mises") {
    m->yield_ = yield;
    m->k_evp_ = k++;
  }
  if (m->failure_.random_initial_fields()) m->k_drawn_ = k++;
  // Kinematic hardening (VT ch. 11, eq. 18.47-18.48): the backstress column goes last (flat offset = k).
  const auto kin = sub_model(params, name, "kinematic_hardening_model", kinematic_hardening_models(), "none", ctx,
                             [](const std::string& kk, const ModelParameters& q, const SubModelContext& cc) {
                               return create_kinematic_hardening_model(kk, q, cc);
                             });
  if (kin->type() != "none") {  // with a porous yield too: the shifted two-invariant return (PorousReturn.h)
    m->kin_ = kin;
    m->k_beta_ = k++;
  }
  m->history_count_ = k;
  return m;
}

}  // namespace tephra
