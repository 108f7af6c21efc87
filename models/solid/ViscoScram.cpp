#include "models/solid/ViscoScram.h"

#include "models/solid/ModifiedEos.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <limits>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/Kinematics.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {
using M3 = Eigen::Matrix3d;
constexpr double kPi = 3.14159265358979323846;
// Vaango's "baseline" PBX 9501 fit of the crack-speed factor v_res = exp(b) eps_eff^a.
constexpr double kVresA = 0.90564746, kVresB = -2.90178468;
// RK4 sub-step bound h RTau_max <= 1/4 (RK4 is stable to h/tau ~ 2.78; 1/4 keeps
// the relative error of one relaxing element below ~1.3e-5 per sub-step).
constexpr double kMaxStepOverTau = 0.25;

M3 load(std::span<const double> col, std::size_t i) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(col.data() + 9 * i);
}
void store(std::span<double> col, std::size_t i, const M3& m) {
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(col.data() + 9 * i) = m;
}
}  // namespace

double ViscoScramCrackLaw::K_I(double c) const { return std::sqrt(1.5 * kPi * c) * sigma_e; }

double ViscoScramCrackLaw::rate(double c) const {
  if (v_res == 0.0) return 0.0;
  const double k = K_I(c);
  if (k < K_p) return v_res * std::pow(k / K_1, m);  // [24], slow growth
  return v_res * (1.0 - (K_0m / k) * (K_0m / k));    // fast growth
}

ViscoScramCrackLaw visco_scram_crack_law(const ViscoScramParams& P, double c, double p, const M3& s,
                                         const M3& d_dev) {
  ViscoScramCrackLaw law;
  law.m = P.crack_m;
  const double eps_eff = std::sqrt(1.5) * d_dev.norm();
  double v_res = eps_eff > 1e-8 ? std::exp(kVresA * std::log(eps_eff) + kVresB) : 0.0;
  const bool tension = p > 0.0;  // Vaango: compflag = -1 for sigma_m > 0
  if (tension) v_res *= P.cdot0;
  law.v_res = std::min(v_res, P.crack_vmax);
  law.sigma_e = std::sqrt(s.squaredNorm() + (tension ? 3.0 * p * p : 0.0));
  const double mu_p = tension ? 0.0 : std::sqrt(45.0 / (2.0 * (3.0 - 2.0 * P.mu * P.mu))) * P.mu;  // [31]
  const double A = -mu_p * p * std::sqrt(c);                                                        // [30]
  const double B = 1.0 + A / P.K0;
  law.K_0m = P.K0 * std::sqrt(1.0 + kPi * A * B / P.K0);
  law.K_p = law.K_0m * std::sqrt(1.0 + 2.0 / P.crack_m);                   // [28]
  law.K_1 = law.K_p * std::pow(1.0 + 0.5 * P.crack_m, 1.0 / P.crack_m);  // [29]
  return law;
}

void visco_scram_element_rates(const ViscoScramParams& P, const std::array<double, 5>& RTau, const M3& d_dev,
                               double c, double c_dot, const std::array<M3, 5>& s, std::array<M3, 5>& rate) {
  const double G = P.shear_modulus();
  M3 S = M3::Zero(), T = M3::Zero();
  for (int j = 0; j < 5; ++j) {
    S += s[j];
    T += RTau[j] * s[j];
  }
  const double a3 = P.crack_a * P.crack_a * P.crack_a;
  const double con1 = 3.0 * c * c * c_dot / a3;  // d/dt (c/a)^3
  const double coa3 = c * c * c / a3;
  const M3 crack = con1 * S + (2.0 * G * d_dev - T - con1 * S) * (coa3 / (1.0 + coa3));
  for (int i = 0; i < 5; ++i) rate[i] = 2.0 * P.G[i] * d_dev - RTau[i] * s[i] - (P.G[i] / G) * crack;
}

std::vector<HistoryVariable> ViscoScram::history() const {
  std::vector<HistoryVariable> h;
  for (int i = 1; i <= 5; ++i)
    h.push_back({"maxwellStress" + std::to_string(i), 9, std::vector<double>(9, 0.0),
                 "deviatoric stress of Maxwell element " + std::to_string(i) + ", unrotated frame R^T s R [Pa]"});
  h.push_back({"crackRad", 1, {p_.c0}, "mean crack radius c [m] (Vaango p.crackRad)"});
  h.push_back({"tempPrev", 1, {-1.0}, "temperature of the previous update [K] (-1: not yet set)"});
  h.push_back({"veHeatRate", 1, {0.0}, "viscous heating rate W_ve/(rho c_v) [K/s] (Vaango p.veHeatRate)"});
  h.push_back({"crHeatRate", 1, {0.0}, "crack heating rate W_cr/(rho c_v) [K/s] (Vaango p.crHeatRate)"});
  h.push_back({"volHeatRate", 1, {0.0}, "volumetric cooling rate Gamma T tr(d) [K/s] (Vaango p.volHeatRate)"});
  return h;
}

long ViscoScram::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const ViscoScramParams& P = p_;
  const double K = P.bulk_modulus(), G = P.shear_modulus();
  const double a3 = P.crack_a * P.crack_a * P.crack_a;
  const double dt = in.dt;
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    const PolarDecomposition pa = polar_decomposition(in.F_old[i]), pb = polar_decomposition(in.F_new[i]);
    const double T = in.temperature[i];
    double& T_prev = out.history[kTemperaturePrev][i];
    if (T_prev < 0.0 || dt == 0.0) T_prev = T;

    // Unrotated rate of deformation (midpoint rule for sym(U_dot U^{-1}), as hypo_elastic)
    // and the mechanical volume strain of the step (thermal strain 3 alpha dT removed).
    M3 d = M3::Zero();
    double dev_v = 0.0;
    if (dt > 0.0) {
      const M3 g = (pb.U - pa.U) * (0.5 * (pa.U + pb.U)).inverse();
      d = 0.5 * (g + g.transpose()) / dt;
      dev_v = std::log(J / J0) - 3.0 * P.alpha * (T - T_prev);
    }
    const M3 d_dev = d - (d.trace() / 3.0) * M3::Identity();
    const double ekk_dot = dt > 0.0 ? dev_v / dt : 0.0;

    // Relaxation rates, shifted by the WLF factor a_T when asked.
    std::array<double, 5> RTau = P.RTau;
    if (P.time_temperature) {
      const double dT = T - P.T0_wlf;
      const double a_T = std::exp(-P.C1_wlf * dT / (P.C2_wlf + dT));
      for (double& r : RTau) r /= a_T;
    }

    std::array<M3, 5> s;
    for (int k = 0; k < 5; ++k) s[k] = load(out.history[k], i);
    double c = out.history[kCrackRadius][i];
    const double p_old = in.stress_old[i].trace() / 3.0;
    M3 S = s[0] + s[1] + s[2] + s[3] + s[4];
    const ViscoScramCrackLaw law = visco_scram_crack_law(P, c, p_old, S, d_dev);

    // Classical RK4 of the system (s_1..s_5, c), sub-stepped so that every
    // relaxation rate -- RTau_i and the crack's 3 c^2 c_dot/(a^3 + c^3) -- times
    // h stays <= 1/4, and c grows by at most half of itself per sub-step.
    if (dt > 0.0) {
      const double rmax = *std::max_element(RTau.begin(), RTau.end());
      std::array<M3, 5> k1, k2, k3, k4, y;
      double t = 0.0;
      int count = 0;
      while (t < dt) {
        const double c1 = law.rate(c);
        const double stiff = rmax + 3.0 * c * c * std::abs(c1) / (a3 + c * c * c);
        double h = dt - t;
        if (stiff * h > kMaxStepOverTau) h = kMaxStepOverTau / stiff;
        if (c1 * h > 0.5 * c && c > 0.0) h = 0.5 * c / c1;
        if (++count > 100000) return false;  // no progress: report the point
        visco_scram_element_rates(P, RTau, d_dev, c, c1, s, k1);
        for (int k = 0; k < 5; ++k) y[k] = s[k] + 0.5 * h * k1[k];
        const double cy2 = c + 0.5 * h * c1, c2 = law.rate(cy2);
        visco_scram_element_rates(P, RTau, d_dev, cy2, c2, y, k2);
        for (int k = 0; k < 5; ++k) y[k] = s[k] + 0.5 * h * k2[k];
        const double cy3 = c + 0.5 * h * c2, c3 = law.rate(cy3);
        visco_scram_element_rates(P, RTau, d_dev, cy3, c3, y, k3);
        for (int k = 0; k < 5; ++k) y[k] = s[k] + h * k3[k];
        const double cy4 = c + h * c3, c4 = law.rate(cy4);
        visco_scram_element_rates(P, RTau, d_dev, cy4, c4, y, k4);
        for (int k = 0; k < 5; ++k) s[k] += (h / 6.0) * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
        c += (h / 6.0) * (c1 + 2.0 * c2 + 2.0 * c3 + c4);
        t = (dt - t - h <= 1e-14 * dt) ? dt : t + h;
      }
    }
    S = s[0] + s[1] + s[2] + s[3] + s[4];
    const double p_new = p_old + K * dev_v;
    M3 sigma = pb.R * (p_new * M3::Identity() + S) * pb.R.transpose();
    sigma = 0.5 * (sigma + sigma.transpose());
    if (!sigma.allFinite() || !std::isfinite(c)) return false;

    // Dissipation rates at t_{n+1} (Hackett & Bennett 2000).
    double w_ve = 0.0, energy = p_new * p_new / (2.0 * K);
    M3 Tsum = M3::Zero();
    for (int k = 0; k < 5; ++k) {
      if (P.G[k] > 0.0) {
        w_ve += s[k].squaredNorm() / (2.0 * P.G[k]) * RTau[k];
        energy += s[k].squaredNorm() / (4.0 * P.G[k]);
      }
      Tsum += RTau[k] * s[k];
    }
    const double c_dot = law.rate(c);
    const double coa3 = c * c * c / a3, topc = 3.0 * c * c * c_dot / a3;
    const M3 s_rate_cr = (2.0 * G * d_dev - topc * S - Tsum) / (1.0 + coa3);
    const double w_cr = (S.squaredNorm() * topc + (S.array() * s_rate_cr.array()).sum() * coa3) / (2.0 * G);
    const double rho_cv = in.density0 / J * P.specific_heat;
    const double ve = w_ve / rho_cv, cr = w_cr / rho_cv, vol = P.Gamma * T * ekk_dot;

    for (int k = 0; k < 5; ++k) store(out.history[k], i, s[k]);
    out.history[kCrackRadius][i] = c;
    out.history[kVeHeat][i] = ve;
    out.history[kCrHeat][i] = cr;
    out.history[kVolHeat][i] = vol;
    T_prev = T;
    out.stress[i] = sigma;
    out.wave_speed[i] = std::sqrt((K + 4.0 * G / 3.0) * J / in.density0);
    out.energy_density[i] = J * energy;
    out.plastic_work[i] = dt > 0.0 ? J * (w_ve + w_cr) * dt : 0.0;
    out.heating[i] = ve + cr - vol;
    return true;
  });
}

SolidEosPoint ViscoScram::absolute_pressure_at_density(double rho, double density0, double T, double p_ref) const {
  if (!p_.jwl) throw std::logic_error("visco_scram: absolute-pressure EOS without useJWLEOS");
  return p_.jwl->pressure(rho, density0, T, p_ref);
}

double ViscoScram::density_at_absolute_pressure(double p, double density0, double T, double p_ref) const {
  if (!p_.jwl) throw std::logic_error("visco_scram: absolute-pressure EOS without useJWLEOS");
  return p_.jwl->density(p, density0, T, p_ref);
}

// The standard EOS (gauge). With <useJWLEOS> the hooks are the absolute ones above.
std::optional<SolidEosPoint> ViscoScram::pressure_at_density(double rho, double density0, double) const {
  if (p_.jwl) return std::nullopt;
  const double K = p_.bulk_modulus();
  SolidEosPoint e;
  e.pressure = 0.5 * K * (rho / density0 - density0 / rho);
  e.dp_drho = 0.5 * K * (1.0 / density0 + density0 / (rho * rho));
  e.c2 = K / rho;
  return e;
}

std::optional<double> ViscoScram::density_at_pressure(double p_gauge, double density0, double) const {
  if (p_.jwl) return std::nullopt;
  const double x = p_gauge / p_.bulk_modulus();
  return density0 * (x + std::sqrt(x * x + 1.0));
}

SolidEosPoint ViscoScram::modified_eos_pressure(double rho, double density0, double p_ref) const {
  if (p_.jwl) throw std::logic_error("visco_scram useJWLEOS: the MPMICE EOS is absolute_pressure_at_density (needs T)");
  if (rho >= density0) return *pressure_at_density(rho, density0, 0.0);
  return modified_eos_expansion(rho, density0, p_.bulk_modulus(), p_ref);  // K0 = K (ModifiedEos.h)
}

double ViscoScram::modified_eos_density(double p_gauge, double density0, double p_ref) const {
  if (p_.jwl) throw std::logic_error("visco_scram useJWLEOS: the MPMICE EOS is density_at_absolute_pressure (needs T)");
  if (p_gauge >= 0.0) return *density_at_pressure(p_gauge, density0, 0.0);
  return modified_eos_expansion_density(p_gauge, density0, p_.bulk_modulus(), p_ref);
}

ConstitutiveModelP ViscoScram::create(const ModelParameters& params) {
  ViscoScramParams p;
  p.nu = params.get_double("PR");
  if (!(p.nu > -1.0 && p.nu < 0.5)) params.fail("PR", "PR (Poisson's ratio) must be in (-1, 0.5)");
  for (int i = 0; i < 5; ++i) {
    const std::string g = "G" + std::to_string(i + 1), r = "RTau" + std::to_string(i + 1);
    p.G[i] = params.get_double(g);
    p.RTau[i] = params.get_double(r);
    if (!(p.G[i] >= 0.0)) params.fail(g, g + " (shear modulus of Maxwell element) must be >= 0");
    if (!(p.RTau[i] >= 0.0)) params.fail(r, r + " (inverse relaxation time) must be >= 0");
  }
  if (!(p.shear_modulus() > 0.0)) params.fail("G1", "G1 + ... + G5 must be > 0");
  p.crack_a = params.get_double("CrackParameterA");
  p.crack_m = params.get_double("CrackPowerValue");
  p.crack_vmax = params.get_double("CrackMaxGrowthRate");
  p.K0 = params.get_double("StressIntensityF");
  p.mu = params.get_double("CrackFriction");
  p.c0 = params.get_double("InitialCrackRadius");
  p.cdot0 = params.get_double("CrackGrowthRate");
  if (!(p.crack_a > 0.0)) params.fail("CrackParameterA", "must be > 0");
  if (!(p.crack_m > 0.0)) params.fail("CrackPowerValue", "must be > 0");
  if (!(p.crack_vmax >= 0.0)) params.fail("CrackMaxGrowthRate", "must be >= 0");
  if (!(p.K0 > 0.0)) params.fail("StressIntensityF", "must be > 0");
  if (!(p.mu >= 0.0 && 2.0 * p.mu * p.mu < 3.0)) params.fail("CrackFriction", "must be in [0, sqrt(3/2))");
  if (!(p.c0 >= 0.0)) params.fail("InitialCrackRadius", "must be >= 0");
  if (!(p.cdot0 >= 0.0)) params.fail("CrackGrowthRate", "must be >= 0");
  // Required by Vaango and unused by its update (c_v = the material's specific heat).
  params.get_double("Beta");
  params.get_double("DCp_DTemperature");
  p.Gamma = params.get_double("Gamma");
  p.alpha = params.get_double("CoeffThermalExpansion", 0.0);
  if (!params.mpm_flag("DoThermalExpansion", true)) p.alpha = 0.0;  // Vaango ViscoScram: alpha = 0 unless the MPM flag
  p.specific_heat = params.enclosing_double("specific_heat", 0.0);
  if (!(p.specific_heat > 0.0))
    params.fail("PR", "visco_scram heating needs the material's <specific_heat> > 0");

  p.time_temperature = params.get_bool("use_time_temperature_equation", false);
  p.T0_wlf = params.get_double("T0", 298.0);
  p.C1_wlf = params.get_double("C1", 6.5);
  p.C2_wlf = params.get_double("C2", 120.0);
  p.modified_eos = params.get_bool("useModifiedEOS", false);
  params.get_bool("useObjectiveRate", false);  // both settings: Green-Naghdi (ViscoScram.h)
  if (params.get_bool("randomize_parameters", false))
    params.missing_feature("randomize_parameters", "visco_scram randomized moduli (randomize_parameters = true)");
  // <useJWLEOS> (Vaango: takes precedence over the Murnaghan options, and
  // useJWLCEOS is then ignored): the MPMICE hooks of ViscoScramJwl.h.
  if (params.get_bool("useJWLEOS", false)) {
    ViscoScramJwl j;
    j.A = params.get_double("A");
    j.B = params.get_double("B");
    j.R1 = params.get_double("R1");
    j.R2 = params.get_double("R2");
    j.om = params.get_double("om");
    j.Cv = params.get_double("Cv");
    if (!(j.R1 > 0.0)) params.fail("R1", "visco_scram JWL <R1> must be > 0");
    if (!(j.R2 > 0.0)) params.fail("R2", "visco_scram JWL <R2> must be > 0");
    if (!(j.A > 0.0)) params.fail("A", "visco_scram JWL <A> must be > 0 (the compression branch)");
    if (!(j.Cv >= 0.0)) params.fail("Cv", "visco_scram JWL <Cv> must be >= 0");
    j.modified = p.modified_eos;
    p.jwl = j;
    params.has("rho0");  // Vaango reads no rho0: the material's <density> is rho0
    params.get_bool("useJWLCEOS", false);
    params.get_bool("useMurnahanEOS", false);
    params.get_bool("useBirchMurnaghanEOS", false);
  }
  if (!p.jwl)
    for (const char* eos : {"useJWLCEOS", "useMurnahanEOS", "useBirchMurnaghanEOS"})
    if (params.get_bool(eos, false))
      params.missing_feature(eos, std::string("visco_scram volumetric response <") + eos + "> = true");
  // Parameters of visco_scram_hotspot that Vaango's visco_scram does not read either.
  for (const char* unused : {"Chi", "delH", "Z", "EoverR", "dynamic_coeff_friction", "volfracHE"})
    params.has(unused);
  return std::make_shared<ViscoScram>(p);
}

}  // namespace tephra
