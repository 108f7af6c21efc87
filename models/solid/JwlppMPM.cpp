#include "models/solid/JwlppMPM.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/ViscousFluid.h"

namespace tephra {

double jwlpp_murnaghan_pressure(double J, const JwlppParams& p) {
  return std::expm1(-p.n * std::log(J)) / (p.n * p.kappa);  // (J^{-n} - 1)/(n kappa), eq. 3.16
}

double jwlpp_jwl_pressure(double J, const JwlppParams& p) {
  return p.A * std::exp(-p.R1 * J) + p.B * std::exp(-p.R2 * J) + p.C * std::pow(J, -(1.0 + p.omega));  // eq. 3.17
}

namespace {

// dp/dJ of eq. 3.15 at fixed f.
double mixture_dp_dJ(double J, double f, const JwlppParams& p) {
  const double dpm = -std::pow(J, -p.n - 1.0) / p.kappa;
  const double dpj = -p.R1 * p.A * std::exp(-p.R1 * J) - p.R2 * p.B * std::exp(-p.R2 * J) -
                     (1.0 + p.omega) * p.C * std::pow(J, -(2.0 + p.omega));
  return (1.0 - f) * dpm + f * dpj;
}

// Backward Euler substep: the root in [f_k, 1] of
//   r(f) = f - f_k - dt G (1 - f) p(f)^b,   p(f) = pm + f (pj - pm)   (p^b := 0 for p <= 0),
// r(f_k) <= 0 <= r(1) = 1 - f_k. Safeguarded Newton (bisection when Newton leaves the bracket).
bool backward_euler_substep(double f_k, double dt, double pm, double pj, const JwlppParams& p, double& f) {
  auto r = [&](double x, double& dr) {
    const double px = pm + x * (pj - pm);
    const double pb = px > 0.0 ? std::pow(px, p.b) : 0.0;
    const double dpb = px > 0.0 ? p.b * pb / px * (pj - pm) : 0.0;
    dr = 1.0 + dt * p.G * pb - dt * p.G * (1.0 - x) * dpb;
    return x - f_k - dt * p.G * (1.0 - x) * pb;
  };
  double lo = f_k, hi = 1.0, dr = 0.0;
  f = f_k;
  double res = r(f, dr);
  if (res >= 0.0) return true;  // no burn at this pressure
  for (int it = 0; it < p.newton_max_iterations; ++it) {
    if (res < 0.0) lo = f; else hi = f;
    double next = (dr > 0.0) ? f - res / dr : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    f = next;
    res = r(f, dr);
    if (std::abs(res) <= p.newton_tolerance || hi - lo <= 1e-15) return std::isfinite(f);
  }
  return false;  // not converged: the caller reports a numerical failure
}

}  // namespace

bool jwlpp_burn_update(double J_old, double J_new, double f_old, double p_old, double dt, const JwlppParams& p,
                       double& f_new, double& p_new) {
  if (!(p_old > p.ignition_pressure && f_old < p.max_burned_fraction) || !(dt > 0.0)) {
    f_new = f_old;  // no burn: eq. 3.15 with the old fraction
    p_new = (1.0 - f_new) * jwlpp_murnaghan_pressure(J_new, p) + f_new * jwlpp_jwl_pressure(J_new, p);
    return true;
  }
  const double steps_real = std::max(1.0, std::ceil(dt / p.max_burn_timestep));
  if (steps_real > 1e9) return false;  // a step of over 10^9 burn substeps: refuse, not hang
  const int steps = static_cast<int>(steps_real);
  const double dt_k = dt / steps;
  const double dJ = std::pow(J_new / J_old, 1.0 / steps);  // geometric interpolation of J (Vaango)
  double J = J_old, f = f_old, pk = p_old;
  for (int k = 0; k < steps; ++k) {
    J *= dJ;
    const double pm = jwlpp_murnaghan_pressure(J, p), pj = jwlpp_jwl_pressure(J, p);
    double f_next;
    if (p.fast_compute) {
      const double fac = dt_k * p.G * (pk > 0.0 ? std::pow(pk, p.b) : 0.0);  // two-stage: rate at the old p
      f_next = (f + fac) / (1.0 + fac);
    } else if (!backward_euler_substep(f, dt_k, pm, pj, p, f_next)) {
      return false;
    }
    f = std::min(f_next, p.max_burned_fraction);
    pk = (1.0 - f) * pm + f * pj;
  }
  f_new = f;
  p_new = (1.0 - f) * jwlpp_murnaghan_pressure(J_new, p) + f * jwlpp_jwl_pressure(J_new, p);
  return std::isfinite(f_new) && std::isfinite(p_new);
}

std::vector<HistoryVariable> JwlppMPM::history() const {
  return {{"progressF", 1, {0.0}, "burned (product) fraction f [-]"},
          {"progressdelF", 1, {0.0}, "increment of f in the last step [-]"}};
}

long JwlppMPM::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  std::span<double> f_col = out.history[0], df_col = out.history[1];
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J = in.F_new[i].determinant();
    const double J_old = in.F_old[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J) || !(J_old > 0.0)) return false;
    const double f_old = f_col[i];
    const double p_old = -in.stress_old[i].trace() / 3.0;
    double f_new = f_old, p_new = 0.0;
    if (!jwlpp_burn_update(J_old, J, f_old, p_old, in.dt, p_, f_new, p_new)) return false;
    f_col[i] = f_new;
    df_col[i] = f_new - f_old;
    out.stress[i] = -p_new * I + viscous_shear_stress(in.L[i], p_.viscosity);  // eq. 3.12
    const double c2 = -mixture_dp_dJ(J, f_new, p_) * J * J / in.density0;
    out.wave_speed[i] = std::sqrt(std::max(c2, 0.0));
    out.energy_density[i] = 0.0;
    const Eigen::Matrix3d tau = viscous_shear_stress(in.L[i], p_.viscosity);
    out.plastic_work[i] = p_.viscosity > 0.0 ? J * tau.squaredNorm() / (2.0 * p_.viscosity) * in.dt : 0.0;
    out.heating[i] = 0.0;
    return out.stress[i].allFinite() && c2 > 0.0;
  });
}

std::optional<SolidEosPoint> JwlppMPM::pressure_at_density(double rho, double density0, double) const {
  SolidEosPoint e;
  const double lnx = std::log(rho / density0);
  e.pressure = std::expm1(p_.n * lnx) / (p_.n * p_.kappa);
  e.dp_drho = std::exp((p_.n - 1.0) * lnx) / (p_.kappa * density0);
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> JwlppMPM::density_at_pressure(double p_gauge, double density0, double) const {
  return density0 * std::exp(std::log1p(p_.n * p_.kappa * p_gauge) / p_.n);  // NaN below p = -1/(n kappa)
}

ConstitutiveModelP JwlppMPM::create(const ModelParameters& params) {
  JwlppParams p;
  auto positive = [&](const char* name) {
    const double v = params.get_double(name);
    if (!(v > 0.0)) params.fail(name, std::string(name) + " must be > 0");
    return v;
  };
  p.ignition_pressure = positive("ignition_pressure");
  p.viscosity = params.get_double("viscosity");
  if (!(p.viscosity >= 0.0)) params.fail("viscosity", "viscosity must be >= 0");
  p.kappa = positive("murnaghan_K");
  p.n = positive("murnaghan_n");
  p.A = positive("jwl_A");
  p.B = positive("jwl_B");
  p.C = positive("jwl_C");
  p.R1 = positive("jwl_R1");
  p.R2 = positive("jwl_R2");
  p.omega = positive("jwl_om");
  p.G = positive("reaction_G");
  p.b = positive("reaction_b");
  p.max_burn_timestep = params.get_double("max_burn_timestep_size", p.max_burn_timestep);
  if (!(p.max_burn_timestep > 0.0)) params.fail("max_burn_timestep_size", "max_burn_timestep_size must be > 0");
  p.max_burned_fraction = params.get_double("max_burned_fraction", p.max_burned_fraction);
  if (!(p.max_burned_fraction > 0.0 && p.max_burned_fraction <= 1.0))
    params.fail("max_burned_fraction", "max_burned_fraction must be in (0, 1]");
  p.fast_compute = params.get_bool("doFastStressCompute", false);
  p.newton_tolerance = params.get_double("tolerance_for_Newton_iterations", p.newton_tolerance);
  if (!(p.newton_tolerance > 0.0))
    params.fail("tolerance_for_Newton_iterations", "tolerance_for_Newton_iterations must be > 0");
  const double iters = params.get_double("max_number_of_Newton_iterations", p.newton_max_iterations);
  if (!(iters >= 1.0)) params.fail("max_number_of_Newton_iterations", "max_number_of_Newton_iterations must be >= 1");
  p.newton_max_iterations = static_cast<int>(iters);
  // jwl_rho0 (in the schema, not read by Vaango): must be the material density when given.
  if (params.has("jwl_rho0")) {
    const double r0 = positive("jwl_rho0");
    const double density = params.enclosing_double("density", r0);
    if (std::abs(density - r0) > 1e-12 * r0) params.fail("jwl_rho0", "jwl_rho0 must equal the material <density>");
  }
  if (params.get_bool("useInitialStress", false))
    params.missing_feature("useInitialStress", "jwlpp_mpm with useInitialStress = true (initial pressure)");
  if (params.has("initial_pressure"))
    params.missing_feature("initial_pressure", "jwlpp_mpm initial_pressure (needs useInitialStress)");
  if (params.get_bool("useTaylorSeriesForDefGrad", false))
    params.missing_feature("useTaylorSeriesForDefGrad", "jwlpp_mpm useTaylorSeriesForDefGrad = true");
  if (params.has("num_taylor_terms"))
    params.missing_feature("num_taylor_terms", "jwlpp_mpm num_taylor_terms (needs useTaylorSeriesForDefGrad)");
  return std::make_shared<JwlppMPM>(p);
}

}  // namespace tephra
