#include "models/solid/PolarOrthotropicHypoElastic.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/VectorParameter.h"
#include "models/solid/Kinematics.h"
#include "models/solid/PointLoop.h"
#include "models/solid/PolarNewton.h"

namespace tephra {

namespace {
constexpr int kR = 0, kTheta = 1, kZ = 2;  // history columns
using Vec6 = Eigen::Matrix<double, 6, 1>;

// Voigt (r, theta, z, theta-z, z-r, r-theta) of a symmetric tensor; engineering shear when `strain`.
Vec6 to_voigt(const Eigen::Matrix3d& a, bool strain) {
  const double f = strain ? 2.0 : 1.0;
  Vec6 v;
  v << a(0, 0), a(1, 1), a(2, 2), f * a(1, 2), f * a(2, 0), f * a(0, 1);
  return v;
}
Eigen::Matrix3d from_voigt_stress(const Vec6& v) {
  Eigen::Matrix3d a;
  a << v(0), v(5), v(4), v(5), v(1), v(3), v(4), v(3), v(2);
  return a;
}

Eigen::Vector3d axis(const PolarOrthotropicParams& p) { return (p.top - p.bottom).normalized(); }
// The in-plane reference direction a (theta = 0) and b = e_z x a (theta = pi/2).
void plane_basis(const PolarOrthotropicParams& p, Eigen::Vector3d& a, Eigen::Vector3d& b) {
  const Eigen::Vector3d ez = axis(p);
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
  if ((e1 - e1.dot(ez) * ez).norm() < 1e-8) e1 = Eigen::Vector3d::UnitY();
  a = (e1 - e1.dot(ez) * ez).normalized();
  b = ez.cross(a);
}

}  // namespace

Eigen::Matrix<double, 6, 6> PolarOrthotropicParams::compliance() const {
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
  S(0, 0) = 1.0 / Er;
  S(1, 1) = 1.0 / Et;
  S(2, 2) = 1.0 / Ez;
  S(0, 1) = S(1, 0) = -nu_tr / Et;
  S(0, 2) = S(2, 0) = -nu_zr / Ez;
  S(1, 2) = S(2, 1) = -nu_zt / Ez;
  S(3, 3) = 1.0 / G_tz;
  S(4, 4) = 1.0 / G_zr;
  S(5, 5) = 1.0 / G_rt;
  return S;
}

Eigen::Vector3d polar_coordinates(const Eigen::Vector3d& x, const PolarOrthotropicParams& p) {
  const Eigen::Vector3d ez = axis(p), d = x - p.bottom;
  Eigen::Vector3d a, b;
  plane_basis(p, a, b);
  const double z = d.dot(ez);
  const Eigen::Vector3d radial = d - z * ez;
  const double r = radial.norm();
  const double theta = r > 0.0 ? std::atan2(radial.dot(b), radial.dot(a)) : 0.0;
  return {r, theta, z};
}

Eigen::Matrix3d polar_frame(double theta, const PolarOrthotropicParams& p) {
  Eigen::Vector3d a, b;
  plane_basis(p, a, b);
  const Eigen::Vector3d er = std::cos(theta) * a + std::sin(theta) * b, ez = axis(p), et = ez.cross(er);
  Eigen::Matrix3d Q;
  Q.row(0) = er.transpose();
  Q.row(1) = et.transpose();
  Q.row(2) = ez.transpose();
  return Q;
}

PolarOrthotropicHypoElastic::PolarOrthotropicHypoElastic(const PolarOrthotropicParams& p) : p_(p) {
  S_ = p.compliance();
  C_ = S_.inverse();
  bulk_ = 1.0 / S_.topLeftCorner<3, 3>().sum();
  shear_ = std::max({p.G_tz, p.G_zr, p.G_rt});
  longitudinal_ = std::max({C_(0, 0), C_(1, 1), C_(2, 2)});
}

std::vector<HistoryVariable> PolarOrthotropicHypoElastic::history() const {
  return {{"RCoord", 1, {0.0}, "material cylindrical r of the particle (from its initial position) [m]"},
          {"ThetaCoord", 1, {0.0}, "material cylindrical theta [rad]"},
          {"ZCoord", 1, {0.0}, "material cylindrical z along the axis from symmetry_axis_bottom [m]"}};
}

long PolarOrthotropicHypoElastic::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const size_t n = in.F_new.size();
  if (in.position.size() != n) return n > 0 ? 0 : -1;  // the driver did not supply x_p
  return for_each_point(n, [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    if (in.dt == 0.0) {  // initialization: fix the material frame from x_p
      const Eigen::Vector3d c = polar_coordinates(in.position[i], p_);
      out.history[kR][i] = c[0];
      out.history[kTheta][i] = c[1];
      out.history[kZ][i] = c[2];
    }
    const Eigen::Matrix3d Q = polar_frame(out.history[kTheta][i], p_);
    const PolarDecomposition a = polar_decomposition_newton(in.F_old[i]), b = polar_decomposition_newton(in.F_new[i]);
    const Eigen::Matrix3d Gm = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
    const Eigen::Matrix3d de = 0.5 * (Gm + Gm.transpose());  // unrotated strain increment (midpoint on U)
    const Eigen::Matrix3d tau_loc = Q * (a.R.transpose() * in.stress_old[i] * a.R) * Q.transpose();
    const Vec6 s_new = to_voigt(tau_loc, false) + C_ * to_voigt(Q * de * Q.transpose(), true);
    const Eigen::Matrix3d sig_loc = from_voigt_stress(s_new);
    Eigen::Matrix3d sigma = b.R * (Q.transpose() * sig_loc * Q) * b.R.transpose();
    out.stress[i] = 0.5 * (sigma + sigma.transpose());
    out.wave_speed[i] = std::sqrt(longitudinal_ * J / in.density0);
    out.energy_density[i] = 0.5 * J * s_new.dot(S_ * s_new);
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
    return out.stress[i].allFinite();
  });
}

ConstitutiveModelP PolarOrthotropicHypoElastic::create(const ModelParameters& params) {
  PolarOrthotropicParams p;
  p.top = vector_parameter(params, "symmetry_axis_top");
  p.bottom = vector_parameter(params, "symmetry_axis_bottom");
  if (!((p.top - p.bottom).norm() > 0.0))
    params.fail("symmetry_axis_top", "the symmetry axis is a point (top == bottom)");
  auto pos = [&](const char* n, double& v) {
    v = params.get_double(n);
    if (!(v > 0.0) || !std::isfinite(v)) params.fail(n, std::string(n) + " must be > 0");
  };
  pos("E_r", p.Er);
  pos("E_theta", p.Et);
  pos("E_z", p.Ez);
  p.nu_tr = params.get_double("nu_theta_r");
  p.nu_zr = params.get_double("nu_z_r");
  p.nu_zt = params.get_double("nu_z_theta");
  pos("G_theta_z", p.G_tz);
  pos("G_z_r", p.G_zr);
  pos("G_r_theta", p.G_rt);
  // Positive-definite compliance (Vaango checks the leading minors of the 3x3 block).
  const Eigen::Matrix3d S3 = p.compliance().topLeftCorner<3, 3>();
  if (!(S3(0, 0) * S3(1, 1) - S3(0, 1) * S3(0, 1) > 0.0) || !(S3.determinant() > 0.0))
    params.fail("nu_theta_r", "the Poisson ratios make the compliance matrix indefinite (leading minors <= 0)");
  return std::make_shared<PolarOrthotropicHypoElastic>(p);
}

}  // namespace tephra
