#include "models/solid/MwViscoElastic.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/Kinematics.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {
using M3 = Eigen::Matrix3d;
using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
M3 load9(std::span<double> col, size_t i) { return Eigen::Map<const RowMajor3>(&col[9 * i]); }
void store9(std::span<double> col, size_t i, const M3& m) {
  Eigen::Map<RowMajor3> dst(&col[9 * i]);
  dst = m;
}
}  // namespace

std::vector<HistoryVariable> MwViscoElastic::history() const {
  const std::vector<double> zero9(9, 0.0);
  return {{"stress_e", 9, zero9, "elastic-branch stress, unrotated frame [Pa]"},
          {"stress_ve_d", 9, zero9, "Maxwell deviatoric stress, unrotated frame [Pa]"},
          {"stress_ve_v", 1, {0.0}, "Maxwell pressure (compression positive) [Pa]"}};
}

long MwViscoElastic::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const M3 I = M3::Identity();
  std::span<double> se_col = out.history[0], sd_col = out.history[1], pv_col = out.history[2];
  const double dt = in.dt;
  // beta = eta / (eta + 2G dt): 1 when the denominator vanishes (no spring or no time: nothing relaxes).
  const double den_d = p_.eta_d + 2.0 * p_.G_ve * dt, den_v = p_.eta_v + 3.0 * p_.K_ve * dt;
  const double beta_d = den_d > 0.0 ? p_.eta_d / den_d : 1.0;
  const double beta_v = den_v > 0.0 ? p_.eta_v / den_v : 1.0;
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    const PolarDecomposition a = polar_decomposition(in.F_old[i]), b = polar_decomposition(in.F_new[i]);
    const M3 G = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();  // midpoint increment of U (as hypo_elastic)
    const M3 de = 0.5 * (G + G.transpose());
    const double tr = de.trace();
    const M3 dev = de - (tr / 3.0) * I;
    const M3 se = load9(se_col, i) + (p_.K_e * tr) * I + (2.0 * p_.G_e) * dev;
    const M3 sd = beta_d * (load9(sd_col, i) + (2.0 * p_.G_ve) * dev);
    const double pv = beta_v * (pv_col[i] - p_.K_ve * tr);
    store9(se_col, i, se);
    store9(sd_col, i, sd);
    pv_col[i] = pv;
    M3 sigma = b.R * (se + sd - pv * I) * b.R.transpose();
    out.stress[i] = 0.5 * (sigma + sigma.transpose());
    const double pe = -se.trace() / 3.0;
    const M3 se_dev = se + pe * I;
    double W = se_dev.squaredNorm() / (4.0 * p_.G_e) + pe * pe / (2.0 * p_.K_e);
    if (p_.G_ve > 0) W += sd.squaredNorm() / (4.0 * p_.G_ve);
    if (p_.K_ve > 0) W += pv * pv / (2.0 * p_.K_ve);
    out.energy_density[i] = J * W;
    double D = 0.0;
    if (p_.eta_d > 0) D += sd.squaredNorm() / p_.eta_d;
    if (p_.eta_v > 0) D += 3.0 * pv * pv / p_.eta_v;
    out.plastic_work[i] = J * D * dt;
    out.heating[i] = 0.0;
    out.wave_speed[i] = std::sqrt((bulk_modulus() + 4.0 * shear_modulus() / 3.0) * J / in.density0);
    return out.stress[i].allFinite();
  });
}

std::optional<SolidEosPoint> MwViscoElastic::pressure_at_density(double rho, double density0, double) const {
  const double K = bulk_modulus();
  SolidEosPoint e;
  e.pressure = K * (1.0 - density0 / rho);
  e.dp_drho = K * density0 / (rho * rho);
  e.c2 = (K + 4.0 * shear_modulus() / 3.0) / rho;
  return e;
}

std::optional<double> MwViscoElastic::density_at_pressure(double p_gauge, double density0, double) const {
  const double x = 1.0 - p_gauge / bulk_modulus();
  if (!(x > 0.0)) return std::numeric_limits<double>::infinity();
  return density0 / x;
}

ConstitutiveModelP MwViscoElastic::create(const ModelParameters& params) {
  MwViscoElasticParams p;
  auto read = [&](const char* name, bool strictly_positive) {
    const double v = params.get_double(name);
    if (strictly_positive ? !(v > 0.0) : !(v >= 0.0))
      params.fail(name, std::string(name) + (strictly_positive ? " must be > 0" : " must be >= 0"));
    return v;
  };
  p.G_e = read("e_shear_modulus", true);
  p.K_e = read("e_bulk_modulus", true);
  p.G_ve = read("ve_shear_modulus", false);
  p.K_ve = read("ve_bulk_modulus", false);
  p.eta_v = read("ve_volumetric_viscosity", false);
  p.eta_d = read("ve_deviatoric_viscosity", false);
  return std::make_shared<MwViscoElastic>(p);
}

}  // namespace tephra
