#include "models/solid/PAlpha.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {
constexpr int kAlphaMin = 0, kTempAlpha1 = 1;  // history columns
}

double p_alpha_crush_curve(double alpha, const PAlphaParams& p) {
  return p.Ps - (p.Ps - p.Pe) * std::sqrt((alpha - 1.0) / (p.alphaP() - 1.0));
}

PAlphaPoint p_alpha_pressure(double alpha, double alpha_min_old, double alpha_min_new, double T, double T1,
                             const PAlphaParams& p) {
  const double a0 = p.alpha0(), aP = p.alphaP();
  const double rho = p.rhoS / alpha;
  const double cs = std::sqrt(p.Ks / p.rhoS), ce = std::sqrt(p.K0 / p.rho0);
  PAlphaPoint r;
  r.sound_speed = cs;
  double P = 0.0;
  // alpha <= a0 (Vaango: alpha < a0): the reference state alpha = a0 takes the elastic
  // branch's sound speed sqrt(K_0/rho_0) instead of c_s; the pressure (0) is the same.
  if (alpha <= a0 && alpha >= 1.0) {
    if (alpha <= alpha_min_old) {  // loading
      if (alpha > aP) {
        P = p.K0 * (1.0 - p.rho0 / rho);
        r.sound_speed = std::sqrt(p.K0 / rho);
      } else if (alpha > 1.0) {
        P = p_alpha_crush_curve(alpha, p);
        r.sound_speed = cs + (ce - cs) * (alpha - 1.0) / (a0 - 1.0);
        r.crushing = true;
      }
    } else {  // unloading
      if (alpha >= aP && alpha_min_old >= aP) {
        P = p.K0 * (1.0 - p.rho0 / rho);
        r.sound_speed = std::sqrt(p.K0 / rho);
      } else if ((alpha < aP && alpha > 1.0) || alpha_min_old < aP) {
        P = p_alpha_crush_curve(alpha, p);
        const double h = 1.0 + (ce - cs) * (alpha - 1.0) / (cs * (a0 - 1.0));
        const double dAel_dp = std::min((alpha * alpha / p.Ks) * (1.0 - 1.0 / (h * h)), -1.0 / p.Ks);
        P += (alpha - alpha_min_old) / dAel_dp;
        r.sound_speed = cs + (ce - cs) * (alpha - 1.0) / (a0 - 1.0);
      }
    }
  }
  if (alpha < 1.0 || alpha_min_new < 1.0) {  // fully dense: Mie-Grueneisen about rho_S
    const double zeta = rho / p.rhoS - 1.0;
    const double E = p.cv * (T - T1) * p.rhoS;
    P = p.Gamma0 * E;
    if (zeta != 0.0) {
      const double numer = p.rhoS * p.C0 * p.C0 * (1.0 / zeta + (1.0 - 0.5 * p.Gamma0));
      const double denom = 1.0 / zeta - (p.S_alpha - 1.0);
      P += numer / (denom * denom);
    }
    P += p.Ps;
    r.crushing = false;
  }
  if (alpha > a0 || P < 0.0) {  // tension / unloaded past zero: the unloading modulus K_u
    const double rho_max = std::min(p.rhoS, p.rhoS / alpha_min_new);
    P = p.Ku * (1.0 - rho_max / rho);
    r.crushing = false;
  }
  r.pressure = P;
  return r;
}

std::vector<HistoryVariable> PAlpha::history() const {
  return {{"alphaMin", 1, {p_.alpha0()}, "smallest distension rho_S/rho reached [-]"},
          {"tempAlpha1", 1, {p_.T0}, "temperature at full densification (Mie-Grueneisen reference) [K]"}};
}

long PAlpha::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    const double rho = in.density0 / J;
    const double alpha = p_.rhoS / rho;
    double& amin = out.history[kAlphaMin][i];
    double& T1 = out.history[kTempAlpha1][i];
    const double amin_old = amin, amin_new = std::min(alpha, amin_old);
    const double T = in.temperature[i];
    const PAlphaPoint r = p_alpha_pressure(alpha, amin_old, amin_new, T, T1, p_);
    if (!std::isfinite(r.pressure)) return false;
    // T_1 follows T while porous (Vaango tempAlpha1), frozen once dense.
    const bool dense = alpha < 1.0 || amin_new < 1.0;
    if (!dense && alpha <= p_.alpha0() && alpha >= 1.0) T1 = T;
    amin = amin_new;
    out.stress[i] = -r.pressure * Eigen::Matrix3d::Identity();
    out.wave_speed[i] = r.sound_speed;
    const bool elastic = !dense && !r.crushing && alpha > p_.alphaP() && amin_old >= p_.alphaP() && r.pressure >= 0.0;
    out.energy_density[i] = elastic ? 0.5 * p_.K0 * (1.0 - J) * (1.0 - J) : 0.0;
    out.plastic_work[i] = r.crushing ? -r.pressure * (J - J0) : 0.0;
    double heating = 0.0;
    if (in.dt > 0.0) {
      if (r.crushing) heating += -r.pressure * (J / J0 - 1.0) / (rho * p_.cv * in.dt);
      if (dense) heating += -T * p_.Gamma0 * p_.rhoS * in.L[i].trace() / rho;
    }
    out.heating[i] = heating;
    return true;
  });
}

ConstitutiveModelP PAlpha::create(const ModelParameters& params) {
  PAlphaParams p;
  auto req = [&](const char* n, double& v) {
    v = params.get_double(n);
    if (!(v > 0.0) || !std::isfinite(v)) params.fail(n, std::string(n) + " must be > 0");
  };
  req("Ps", p.Ps);
  req("Pe", p.Pe);
  req("rhoS", p.rhoS);
  req("K0", p.K0);
  req("Ks", p.Ks);
  req("T_0", p.T0);
  req("C_0", p.C0);
  p.Gamma0 = params.get_double("Gamma_0");
  p.S_alpha = params.get_double("S_alpha");
  p.Ku = params.get_double("Ku", 0.1 * p.K0);
  if (!(p.Ku > 0.0)) params.fail("Ku", "Ku must be > 0");
  if (!(p.Ps > p.Pe)) params.fail("Ps", "Ps (full compaction pressure) must exceed Pe (elastic limit)");
  if (!(p.Pe < p.K0)) params.fail("Pe", "Pe must be < K0 (the elastic limit rho_P = rho_0/(1 - Pe/K0))");
  p.rho0 = params.enclosing_double("density", std::numeric_limits<double>::quiet_NaN());
  p.cv = params.enclosing_double("specific_heat", std::numeric_limits<double>::quiet_NaN());
  if (!(p.rho0 > 0.0)) params.fail("rhoS", "p_alpha needs the material's <density> (the porous density rho_0)");
  if (!(p.cv > 0.0)) params.fail("rhoS", "p_alpha needs the material's <specific_heat> (crush heating)");
  if (!(p.rhoS > p.rho0)) params.fail("rhoS", "rhoS (solid density) must exceed the material <density>");
  if (!(p.alphaP() > 1.0))
    params.fail("Pe", "the elastic limit reaches full density: need rho_0/(1 - Pe/K0) < rhoS");
  if (params.has("alpha0")) {
    const double a0 = params.get_double("alpha0");
    if (std::abs(a0 - p.alpha0()) > 1e-6 * p.alpha0())
      params.fail("alpha0", "alpha0 must equal rhoS/density (Vaango computes it so; given " + std::to_string(a0) +
                                ", rhoS/density = " + std::to_string(p.alpha0()) + ")");
  }
  return std::make_shared<PAlpha>(p);
}

}  // namespace tephra
