#include "models/solid/HypoElastic.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/Kinematics.h"
#include "models/solid/PolarNewton.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {

// The material constants of the point function, formed once per update()
// instead of once per point: each is the expression the point function
// evaluated (the same operations on the same parameters), so the same bits.
struct HypoElasticConstants {
  double lambda;       // K - 2G/3
  double two_G;        // 2G
  double two_K;        // 2K
  double four_G;       // 4G
  double K_4G3;        // K + 4G/3
  explicit HypoElasticConstants(const HypoElasticParams& p)
      : lambda(p.K - 2.0 * p.G / 3.0), two_G(2.0 * p.G), two_K(2.0 * p.K), four_G(4.0 * p.G),
        K_4G3(p.K + 4.0 * p.G / 3.0) {}
};

// hypo_elastic_point with the constants and J = det F_new given.
inline SolidPointResult hypo_elastic_point_with(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new,
                                                const Eigen::Matrix3d& stress_old, double density0,
                                                const HypoElasticConstants& c, double thermal_strain, double J) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  // Newton polar decomposition (PolarNewton.h): the eigen-solve result to round-off, faster.
  const PolarDecomposition a = polar_decomposition_newton(F_old), b = polar_decomposition_newton(F_new);
  // Unrotated strain increment: midpoint rule for d_hat = sym(U_dot U^{-1}).
  const Eigen::Matrix3d G = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
  // Mechanical part: minus the thermal strain increment alpha (T_{n+1} - T_n) I (header).
  const Eigen::Matrix3d de = 0.5 * (G + G.transpose()) - thermal_strain * I;
  // VT eq. 4.2 in the unrotated frame.
  const Eigen::Matrix3d tau = a.R.transpose() * stress_old * a.R + (c.lambda * de.trace()) * I + c.two_G * de;
  SolidPointResult r;
  r.stress = b.R * tau * b.R.transpose();
  r.stress = 0.5 * (r.stress + r.stress.transpose());  // remove round-off asymmetry
  const double pr = r.stress.trace() / 3.0;
  const Eigen::Matrix3d s = r.stress - pr * I;
  r.energy_density = J * (pr * pr / c.two_K + s.squaredNorm() / c.four_G);
  r.wave_speed = std::sqrt(c.K_4G3 * J / density0);
  return r;
}

}  // namespace

SolidPointResult hypo_elastic_point(const Eigen::Matrix3d& F_old, const Eigen::Matrix3d& F_new,
                                    const Eigen::Matrix3d& stress_old, double density0,
                                    const HypoElasticParams& p, double thermal_strain) {
  return hypo_elastic_point_with(F_old, F_new, stress_old, density0, HypoElasticConstants(p), thermal_strain,
                                 F_new.determinant());
}

std::vector<HistoryVariable> HypoElastic::history() const {
  if (p_.alpha == 0.0) return {};
  return {{"lastTemperature", 1, {0.0}, "temperature of the last update (thermal strain alpha (T - T_last)) [K]"}};
}

long HypoElastic::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const HypoElasticConstants constants(p_);
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    double thermal_strain = 0.0;
    if (p_.alpha != 0.0) {
      const double T = in.temperature[i];
      if (!std::isfinite(T)) return false;
      double& T_last = out.history[0][i];
      if (!(T_last > 0.0)) T_last = T;  // the first update: the reference temperature
      thermal_strain = p_.alpha * (T - T_last);
      T_last = T;
    }
    const SolidPointResult r = hypo_elastic_point_with(in.F_old[i], in.F_new[i], in.stress_old[i], in.density0,
                                                       constants, thermal_strain, J);
    if (!r.stress.allFinite()) return false;
    out.stress[i] = r.stress;
    out.wave_speed[i] = r.wave_speed;
    out.energy_density[i] = r.energy_density;
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
    return true;
  });
}

std::optional<SolidEosPoint> HypoElastic::pressure_at_density(double rho, double density0, double) const {
  SolidEosPoint e;
  e.pressure = p_.K * (1.0 - density0 / rho);
  e.dp_drho = p_.K * density0 / (rho * rho);
  e.c2 = p_.K / rho;
  return e;
}

std::optional<double> HypoElastic::density_at_pressure(double p_gauge, double density0, double) const {
  const double x = 1.0 - p_gauge / p_.K;
  if (!(x > 0.0)) return std::numeric_limits<double>::infinity();
  return density0 / x;
}

ConstitutiveModelP HypoElastic::create_named(const ModelParameters& params, const std::string& type) {
  HypoElasticParams p;
  p.G = params.get_double("G");
  p.K = params.get_double("K");
  if (!(p.G > 0.0)) params.fail("G", "G (shear modulus) must be > 0");
  if (!(p.K > 0.0)) params.fail("K", "K (bulk modulus) must be > 0");
  p.alpha = params.get_double("alpha", 0.0);
  if (type == "hypo_elastic_mms" && p.alpha != 0.0)  // the manufactured solutions are isothermal
    params.missing_feature("alpha", type + " thermal stress (alpha != 0)");
  if (!std::isfinite(p.alpha)) params.fail("alpha", "alpha (thermal expansion) must be finite");
  if (!params.mpm_flag("DoThermalExpansion", true)) p.alpha = 0.0;  // the MPM flag (header)
  return std::make_shared<HypoElastic>(p, type);
}

ConstitutiveModelP HypoElastic::create(const ModelParameters& params) { return create_named(params, "hypo_elastic"); }

ConstitutiveModelP HypoElastic::create_mms(const ModelParameters& params) {
  return create_named(params, "hypo_elastic_mms");
}

}  // namespace tephra
