#include "models/solid/ElasticPlasticHP.h"

#include <stdexcept>

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
enum HistoryIndex { kEpsP = 0, kEpsPRate = 1, kPorosity = 2, kDamage = 3, kLocalized = 4, kStrainRate = 5, kHistoryCount = 6 };
constexpr int kMaxHistory = kHistoryCount + 5 + 9;  // + plasticVolumetricStrain, initialFieldsDrawn, T_0, T_last, mtsStructureStress, backStress
}  // namespace

std::vector<HistoryVariable> ElasticPlasticHP::history() const {
  // Vaango's ElasticPlasticHP labels (p.plasticStrain, ...).
  std::vector<HistoryVariable> h = {
      {"plasticStrain", 1, {0.0}, "equivalent plastic strain ε_p [-]"},
      {"plasticStrainRate", 1, {0.0}, "equivalent plastic strain rate ε̇_p = Δε_p/Δt [1/s]"},
      {"porosity", 1, {failure_.initial_porosity}, "void volume fraction φ [-]"},
      {"damage", 1, {failure_.initial_damage()}, "scalar damage D [-]"},
      {"localized", 1, {0.0}, "1 once the point failed (melting, TEPLA, max stress, stability), else 0"},
      {"strainRate", 1, {0.0}, "total equivalent strain rate sqrt(2/3) |d|, d = de/dt of the step [1/s]"}};
  if (k_evp_ >= 0)
    h.push_back({"plasticVolumetricStrain", 1, {0.0}, "ln J^p = sum of tr(Delta eps^p) (porous yield only) [-]"});
  if (k_drawn_ >= 0)
    h.push_back({"initialFieldsDrawn", 1, {0.0}, "1 once the Gaussian initial porosity/damage is drawn"});
  if (k_T0_ >= 0) {
    h.push_back({"thermalReferenceTemperature", 1, {0.0}, "T_0 of the thermal pressure, set at the first update [K]"});
    h.push_back({"lastTemperature", 1, {0.0}, "temperature of the last update [K]"});
  }
  if (k_sigma_e_ >= 0) h.push_back({"mtsStructureStress", 1, {0.0}, "MTS evolving structure stress sigma_e [Pa]"});
  if (k_beta_ >= 0)
    h.push_back({"backStress", 9, std::vector<double>(9, 0.0),
                 "backstress β (VT ch. 11), in the unrotated frame of the point [Pa]"});
  return h;
}

bool ElasticPlasticHP::update_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new,
                                    const Eigen::Matrix3d& stress_old, double T, double dt, double density0,
                                    double* hist, PointOut& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double J = F_new.determinant();
  if (!(J > 0.0) || !(F_old.determinant() > 0.0) || !std::isfinite(J)) return false;
  const PolarDecomposition a = polar_decomposition(F_old), b = polar_decomposition(F_new);
  // Unrotated strain increment (midpoint rule for d_hat = sym(U_dot U^{-1})).
  const Eigen::Matrix3d G = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
  const Eigen::Matrix3d de = 0.5 * (G + G.transpose());
  // Vaango's p.strainRate: the total equivalent strain rate sqrt(2/3) |D| (Frobenius norm of the
  // rotated rate of deformation, unchanged by the rotation), here with D = de/dt.
  hist[kStrainRate] = dt > 0.0 ? std::sqrt(2.0 / 3.0) * de.norm() / dt : 0.0;
  const Eigen::Matrix3d tau_n = a.R.transpose() * stress_old * a.R;
  const double p_n = tau_n.trace() / 3.0;
  const Eigen::Matrix3d s_n = tau_n - p_n * I;

  // Thermal reference T_0 (first update) and the last temperature (rate-form EOS).
  double T0 = T, T_last = T;
  if (k_T0_ >= 0) {
    if (!(hist[k_T0_] > 0.0)) hist[k_T0_] = hist[k_Tprev_] = T;
    T0 = hist[k_T0_];
    T_last = hist[k_Tprev_];
    hist[k_Tprev_] = T;
  }

  // Volumetric part: the EOS gives the mechanical mean stress (VT ch. 6) at J^e = J/J^p.
  EosInput ei;
  ei.J = k_evp_ >= 0 ? J * std::exp(-hist[k_evp_]) : J;
  ei.p_old = p_n + 3.0 * eos_->bulk_modulus() * p_.alpha * (T_last - T0);  // the mechanical part at t_n
  ei.dt = dt;
  ei.trace_d = dt > 0.0 ? de.trace() / dt : 0.0;
  const EosResult eos = eos_->evaluate(ei);
  // Thermal pressure 3 κ α (T - T_0) (header; VT eq. 17.3-17.5, 18.12), κ = J^e dp/dJ^e.
  const double kappa_th = ei.J * eos.dp_dJ > 0.0 ? ei.J * eos.dp_dJ : eos_->bulk_modulus();
  const double p_th = 3.0 * kappa_th * p_.alpha * (T - T0);

  PlasticState st;
  st.eps_p = hist[kEpsP];
  st.eps_p_rate = 0.0;  // the elastic check uses the lowest rate (flow stress nondecreasing in rate)
  st.temperature = T;
  st.density0 = density0;
  st.density = density0 / J;
  st.pressure = -(eos.p - p_th);
  st.porosity = hist[kPorosity];
  st.sigma_e = k_sigma_e_ >= 0 ? hist[k_sigma_e_] : 0.0;
  const double sigma_e_n = st.sigma_e;
  st.melt_temperature = melt_->melt_temperature(st);
  const double mu = shear_->shear_modulus(st);
  st.shear_modulus = mu;

  // Deviatoric trial stress (VT eq. 17.50).
  const Eigen::Matrix3d s_trial = s_n + 2.0 * mu * (de - (de.trace() / 3.0) * I);
  const double q_trial = std::sqrt(1.5 * s_trial.squaredNorm());
  Eigen::Matrix3d s = s_trial;
  double delta = 0.0, H = 0.0, mean = eos.p - p_th, work = 0.0, tr_dp = 0.0;
  Eigen::Matrix3d xi = s_trial;  // returned stress relative to the backstress (flow direction of the tangent)
  std::optional<Tangent4> porous_tangent;  // porous yield with a stability check only
  const bool melted = p_.do_melting && T >= st.melt_temperature;
  if (melted) {
    s.setZero();
  } else if (dt > 0.0 && mu > 0.0 && yield_) {
    // Pressure-dependent yield (Gurson, Rousselier): two-invariant return (PorousReturn.h)
    // with the trial mean stress of the EOS and its tangent bulk modulus.
    const double kt = ei.J * eos.dp_dJ;
    PorousReturnInput pr;
    pr.q_trial = q_trial;
    pr.I1_trial = 3.0 * mean;
    pr.n_hat = unit_deviator(s_trial);
    pr.K = kt > 0.0 ? kt : eos_->bulk_modulus();
    pr.mu = mu;
    pr.dt = dt;
    pr.tolerance = std::max(p_.tolerance, 1e-11);
    pr.state = st;
    if (kin_) {  // yield on ξ = σ - β (VT 18.64-18.70; PorousReturn.h)
      pr.beta_n = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_);
      pr.H_lin = kin_->linear_modulus();
      pr.H_rec = kin_->recovery_modulus();
    }
    const FlowStress y0 = flow_->evaluate(st);
    const ShiftedTrial xt = shifted_trial(pr);
    if (yield_at(*yield_, xt.q, xt.I1, xt.n_hat, y0.sigma_y, st.porosity) > 0.0) {
      const PorousReturnResult r = porous_return(*yield_, *flow_, pr);
      if (!r.converged) return false;
      delta = r.delta_eps_p;
      const double I1 = r.I1 + r.backstress.trace();  // tr σ = tr ξ + tr β
      s = r.stress - (I1 / 3.0) * I;
      tr_dp = r.plastic_strain.trace();
      work = r.stress.cwiseProduct(r.plastic_strain).sum();  // σ : Δε^p = (1 - φ) σ_y Δε_p (+ β : Δε^p)
      if (kin_) Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_) = r.backstress;
      if (has_stability_check(failure_)) {  // the J2-I1 continuum tangent (VT §18.6.2) at the returned state
        porous_tangent = yield_continuum_tangent(*yield_, r.xi, r.sigma_y, r.hardening, st.porosity, pr.K, mu,
                                                 kin_.get(), r.backstress);
      }
      hist[k_evp_] += tr_dp;
      if (k_sigma_e_ >= 0) hist[k_sigma_e_] = r.sigma_e;  // MTS: sigma_e of the return (PorousReturn.h)
      // Mean stress: exact for the rate form (p_tr - K tr Δε^p); others at the new J^e.
      ei.J = J * std::exp(-hist[k_evp_]);
      mean = eos_->type() == "default_hypo" ? I1 / 3.0 : eos_->evaluate(ei).p - p_th;
    }
  } else if (dt > 0.0 && mu > 0.0) {
    // Von Mises return on ξ = s - β (header comment; β = 0 without kinematic hardening).
    const double c = std::sqrt(1.5);
    Eigen::Matrix3d beta_n = Eigen::Matrix3d::Zero();
    if (kin_) beta_n = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_);
    const double H1 = kin_ ? kin_->linear_modulus() : 0.0, H2 = kin_ ? kin_->recovery_modulus() : 0.0;
    const double q_xi_trial = std::sqrt(1.5 * (s_trial - beta_n).squaredNorm());
    const FlowStress y0 = flow_->evaluate(st);
    if (q_xi_trial > y0.sigma_y) {
      // g(Δ) = sqrt(3/2)|s_trial - a β_n| - (3μ + a H_1) Δ - σ_y(ε_p,n + Δ, Δ/dt, T), a = 1/(1 + c H_2 Δ).
      double lo = 0.0, hi = c * (s_trial.norm() + beta_n.norm()) / (3.0 * mu);  // g(hi) <= -σ_y <= 0
      double x = std::min(hi, (q_xi_trial - y0.sigma_y) / (3.0 * mu + H1 + std::max(0.0, y0.d_eps_p)));
      const double tol = p_.tolerance * std::max(q_xi_trial, 1.0);
      for (int it = 0; it < 100; ++it) {
        st.eps_p = hist[kEpsP] + x;
        st.eps_p_rate = x / dt;
        if (k_sigma_e_ >= 0) {  // MTS: sigma_e(Delta) by eq. 10.19 over Delta (theta(sigma_e) seeds d sigma_y/d eps_p)
          st.sigma_e = sigma_e_n;
          st.sigma_e = flow_->evolve_internal_stress(st, x);
        }
        const FlowStress y = flow_->evaluate(st);
        const double a = 1.0 / (1.0 + c * H2 * x), da = -c * H2 * a * a;
        const Eigen::Matrix3d xi_star = s_trial - a * beta_n;
        const double xi_norm = xi_star.norm();
        const double g = c * xi_norm - (3.0 * mu + a * H1) * x - y.sigma_y;
        H = y.d_eps_p;  // hardening modulus of the stability tangent (isothermal return)
        if (std::abs(g) <= tol) break;
        (g > 0.0 ? lo : hi) = x;
        const double dq = xi_norm > 0.0 ? -da * c * xi_star.cwiseProduct(beta_n).sum() / xi_norm : 0.0;
        const double dg = dq - 3.0 * mu - a * H1 - da * H1 * x - y.d_eps_p - y.d_eps_p_rate / dt;
        double next = dg < 0.0 ? x - g / dg : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // bisection safeguard
        if (hi - lo <= 1e-15 * std::max(hi, 1e-300)) break;
        x = next;
      }
      delta = x;
      const double a = 1.0 / (1.0 + c * H2 * delta);
      const Eigen::Matrix3d xi_star = s_trial - a * beta_n;
      const double xi_norm = xi_star.norm();
      const Eigen::Matrix3d dep = xi_norm > 0.0 ? Eigen::Matrix3d((c * delta / xi_norm) * xi_star) : Eigen::Matrix3d::Zero();
      s = s_trial - 2.0 * mu * dep;
      work = s.cwiseProduct(dep).sum();  // σ:Δε^p (tr Δε^p = 0); σ_y Δ when β = 0
      if (k_sigma_e_ >= 0) hist[k_sigma_e_] = st.sigma_e;
      xi = s;
      if (kin_) {
        const Eigen::Matrix3d beta = kin_->backstress_after(beta_n, dep);
        Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(hist + k_beta_) = beta;
        xi = s - beta;
        H += kin_->j2_modulus(beta, xi);  // kinematic part of the stability tangent's modulus
      }
    }
  }
  hist[kEpsP] += delta;
  hist[kEpsPRate] = dt > 0.0 ? delta / dt : 0.0;

  const Eigen::Matrix3d tau = mean * I + s;
  out.r.stress = b.R * tau * b.R.transpose();
  out.r.stress = (0.5 * (out.r.stress + out.r.stress.transpose())).eval();  // eval: no aliasing
  const double rho = density0 / J;
  const double kappa_t = J * eos.dp_dJ;  // tangent bulk modulus (VT eq. 17.164)
  const double kappa = kappa_t > 0.0 ? kappa_t : eos_->bulk_modulus();
  out.r.wave_speed = std::sqrt((kappa + 4.0 * mu / 3.0) / rho);
  out.r.energy_density = J * (mean * mean / (2.0 * eos_->bulk_modulus()) + (mu > 0.0 ? s.squaredNorm() / (4.0 * mu) : 0.0));
  out.plastic_work = J * work;
  out.heating = 0.0;
  if (!p_.isothermal && delta > 0.0) {
    st.eps_p = hist[kEpsP];
    st.eps_p_rate = hist[kEpsPRate];
    const double cp = p_.compute_specific_heat ? cp_->specific_heat(st) : p_.specific_heat;
    out.heating = p_.taylor_quinney * work / dt / (rho * cp);  // VT 17.27, h^T (J2: σ_y ε̇_p)
  }
  // Porosity, damage (uncoupled, after the return: Algorithm 1) and failure (VT ch. 12, 15, 16).
  if (delta > 0.0) {
    st.eps_p = hist[kEpsP];
    st.eps_p_rate = hist[kEpsPRate];
    evolve_porosity_and_damage(failure_, out.r.stress, st, dt, hist[kPorosity], hist[kDamage], tr_dp);
  }
  if (dt > 0.0 && metal_point_failed(failure_, melted, delta > 0.0, hist[kPorosity], hist[kDamage], out.r.stress))
    hist[kLocalized] = 1.0;
  if (delta > 0.0 && (porous_tangent ? metal_point_unstable(failure_, de, tau, dt, *porous_tangent)
                                     : metal_point_unstable(failure_, de, tau, xi, dt, kappa, mu, H)))
    hist[kLocalized] = 1.0;
  return out.r.stress.allFinite() && std::isfinite(out.heating) && std::isfinite(hist[kDamage]);
}

long ElasticPlasticHP::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return update_metal_points<kMaxHistory>(*this, history_count_, in, out, k_drawn_, kPorosity, kDamage);
}

std::optional<SolidEosPoint> ElasticPlasticHP::pressure_at_density(double rho, double density0, double) const {
  const EosPressurePoint e = eos_pressure_at_density(*eos_, rho, density0);
  return SolidEosPoint{e.pressure, e.dp_drho, e.c2};
}

std::optional<double> ElasticPlasticHP::density_at_pressure(double p_gauge, double density0, double) const {
  return eos_density_at_pressure(*eos_, p_gauge, density0);
}

ConstitutiveModelP ElasticPlasticHP::create(const ModelParameters& params) {
  auto m = std::make_shared<ElasticPlasticHP>();
  ElasticPlasticHPParams& p = m->p_;
  p.bulk_modulus = params.get_double("bulk_modulus");
  p.shear_modulus = params.get_double("shear_modulus");
  if (!(p.bulk_modulus > 0.0)) params.fail("bulk_modulus", "must be > 0");
  if (!(p.shear_modulus > 0.0)) params.fail("shear_modulus", "must be > 0");
  p.taylor_quinney = params.get_double("taylor_quinney_coeff", 0.9);
  if (!(p.taylor_quinney >= 0.0 && p.taylor_quinney <= 1.0)) params.fail("taylor_quinney_coeff", "must be in [0, 1]");
  p.tolerance = params.get_double("tolerance", 1e-12);
  if (!(p.tolerance > 0.0)) params.fail("tolerance", "must be > 0");
  p.isothermal = params.get_bool("isothermal", false);
  p.do_melting = params.get_bool("do_melting", true);  // Vaango's default
  params.get_double("initial_material_temperature", 0.0);  // Vaango: unused in the explicit update (T_0: first T)
  p.alpha = params.get_double("coeff_thermal_expansion", 0.0);
  if (!(p.alpha >= 0.0)) params.fail("coeff_thermal_expansion", "must be >= 0");
  if (!params.mpm_flag("DoThermalExpansion", true)) p.alpha = 0.0;  // Vaango: alpha = 0 unless the MPM flag
  p.use_modified_eos = params.get_bool("useModifiedEOS", false);
  // <plastic_convergence_algo> (Vaango: radialReturn by default, biswajit required for gurson): both
  // select Tephra's returns, which solve the backward-Euler equations of the step to the tolerance
  // (von Mises: the implicit radial return; porous yields: the two-invariant return), not Vaango's
  // substepped semi-implicit iteration of Algorithm 1 (docs/models/plasticity.md).
  const std::string algo = params.get_string("plastic_convergence_algo", "radialReturn");
  if (algo != "radialReturn" && algo != "biswajit")
    params.fail("plastic_convergence_algo", "must be radialReturn or biswajit (here '" + algo + "')");
  const std::string dev = assembly::block_type(params, "deviatoric_stress_model");
  if (!dev.empty() && dev != "hypoElastic")
    params.missing_feature("deviatoric_stress_model", "elastic_plastic_hp deviatoric_stress_model '" + dev + "'");

  SubModelContext ctx;
  ctx.bulk_modulus = p.bulk_modulus;
  ctx.shear_modulus = p.shear_modulus;
  ctx.melt_temperature = params.enclosing_double("melt_temp", 0.0);
  ctx.specific_heat = params.enclosing_double("specific_heat", 0.0);
  ctx.room_temperature = params.enclosing_double("room_temp", 0.0);
  ctx.density0 = params.enclosing_double("density", 0.0);
  p.compute_specific_heat = params.get_bool("compute_specific_heat", false);
  p.specific_heat = ctx.specific_heat;
  if (!p.isothermal && !p.compute_specific_heat && !(p.specific_heat > 0.0))
    params.fail("isothermal", "elastic_plastic_hp with plastic heating needs the material's <specific_heat> > 0");
  m->failure_ = read_metal_failure(params, ctx, "elastic_plastic_hp");
  m->eos_ = assembly::sub_model(params, "elastic_plastic_hp", "equation_of_state", plasticity_eos_models(), "default_hypo", ctx,
                      [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                        return create_plasticity_eos(k, q, c);
                      });
  m->shear_ = assembly::sub_model(params, "elastic_plastic_hp", "shear_modulus_model", shear_modulus_models(), "constant_shear", ctx,
                        [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                          return create_shear_modulus_model(k, q, c);
                        });
  m->melt_ = assembly::sub_model(params, "elastic_plastic_hp", "melting_temp_model", melting_temperature_models(), "constant_Tm", ctx,
                       [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                         return create_melting_temperature_model(k, q, c);
                       });
  m->cp_ = assembly::sub_model(params, "elastic_plastic_hp", "specific_heat_model", specific_heat_models(), "constant_Cp", ctx,
                     [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                       return create_specific_heat_model(k, q, c);
                     });
  m->flow_ = assembly::sub_model(params, "elastic_plastic_hp", "flow_model", flow_stress_models(), "", ctx,
                       [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                         return create_flow_stress_model(k, q, c);
                       });
  // Yield condition: von Mises takes the radial return; others the two-invariant return.
  const auto yield = assembly::sub_model(params, "elastic_plastic_hp", "yield_condition", yield_conditions(), "", ctx,
                                         [](const std::string& k, const ModelParameters& q, const SubModelContext& c) {
                                           return create_yield_condition(k, q, c);
                                         });
  int k = kHistoryCount;
  if (yield->type() != "von_mises") {
    m->yield_ = yield;
    m->k_evp_ = k++;
  }
  if (m->failure_.random_initial_fields()) m->k_drawn_ = k++;
  if (p.alpha != 0.0) {
    m->k_T0_ = k++;
    m->k_Tprev_ = k++;
  }
  // Kinematic hardening (VT ch. 11): the backstress column goes last (flat offset = k).
  const auto kin = assembly::sub_model(params, "elastic_plastic_hp", "kinematic_hardening_model",
                                       kinematic_hardening_models(), "none", ctx,
                                       [](const std::string& key, const ModelParameters& q, const SubModelContext& c) {
                                         return create_kinematic_hardening_model(key, q, c);
                                       });
  // MTS: the structure stress sigma_e is a scalar history column (before the backstress).
  if (m->flow_->type() == "mechanical_threshold_stress") m->k_sigma_e_ = k++;
  if (kin->type() != "none") {  // with a porous yield too: the shifted two-invariant return (PorousReturn.h)
    m->kin_ = kin;
    m->k_beta_ = k++;
  }
  m->history_count_ = k;
  return m;
}

}  // namespace tephra
