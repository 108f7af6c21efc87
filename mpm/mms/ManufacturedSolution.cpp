#include "mpm/mms/ManufacturedSolution.h"
#include "mpm/mms/MmsInitialSize.h"

#include <cmath>
#include <numbers>

#include <Eigen/LU>

#include "mpm/Particles.h"

namespace tephra {

namespace {

constexpr double kPi = std::numbers::pi;

// E = 9 K mu / (3 K + mu): the Young's modulus that sets c = sqrt(E/rho0).
double youngs_modulus(const CnhMmsParams& m) {
  return 9.0 * m.bulk_modulus * m.shear_modulus / (3.0 * m.bulk_modulus + m.shear_modulus);
}

class AxisAligned final : public ManufacturedSolution {
 public:
  AxisAligned(const CnhMmsParams& m, double rho0, double amplitude)
      : amplitude_(amplitude), m_(m), rho0_(rho0), c_(std::sqrt(youngs_modulus(m) / rho0)) {}
  std::string name() const override { return "AxisAligned"; }

  // sin(c pi t + phi_i), phi = (0, 2 pi/3, 4 pi/3)
  double phase(int i, double t) const { return std::sin(c_ * kPi * t + i * 2.0 * kPi / 3.0); }

  Vec3 displacement(const Vec3& X, double t) const override {
    Vec3 u;
    for (int i = 0; i < 3; ++i) u[i] = amplitude_ * std::sin(kPi * X[i]) * phase(i, t);
    return u;
  }
  Vec3 velocity(const Vec3& X, double t) const override {
    Vec3 v;
    for (int i = 0; i < 3; ++i)
      v[i] = amplitude_ * c_ * kPi * std::sin(kPi * X[i]) * std::cos(c_ * kPi * t + i * 2.0 * kPi / 3.0);
    return v;
  }
  Mat3 deformation_gradient(const Vec3& X, double t) const override {
    Mat3 F = Mat3::Zero();
    for (int i = 0; i < 3; ++i) F(i, i) = 1.0 + amplitude_ * kPi * std::cos(kPi * X[i]) * phase(i, t);
    return F;
  }
  Vec3 body_force(const Vec3& X, double t) const override {
    const Vec3 u = displacement(X, t);
    const Mat3 F = deformation_gradient(X, t);
    const double lnJ = std::log(F(0, 0) * F(1, 1) * F(2, 2));
    const double mu = m_.shear_modulus, lambda = m_.lambda();
    Vec3 b;
    for (int i = 0; i < 3; ++i)
      b[i] = kPi * kPi * u[i] *
             (mu / rho0_ - c_ * c_ - (lambda * (lnJ - 1.0) - mu) / (rho0_ * F(i, i) * F(i, i)));
    return b;
  }

 private:
  const double amplitude_;  // A [m]: Vaango's 0.05 (make_mms); other values only from tests
  CnhMmsParams m_;
  double rho0_, c_;
};

class GeneralizedVortex final : public ManufacturedSolution {
 public:
  GeneralizedVortex(const CnhMmsParams& m, double rho0)
      : m_(m), rho0_(rho0), c_(std::sqrt(youngs_modulus(m) / rho0)) {}
  std::string name() const override { return "GeneralizedVortex"; }

  // h(R) = ((4R-3)(4R-5))^2 and its derivatives.
  static double h(double R) { const double q = (4 * R - 3) * (4 * R - 5); return q * q; }
  static double dh(double R) { const double s = R - 1; return 64.0 * s * (16.0 * s * s - 1.0); }
  static double d2h(double R) { const double s = R - 1; return 64.0 * (48.0 * s * s - 1.0); }
  double alpha(double R, double t) const { return kA * std::sin(c_ * kPi * t) * h(R); }
  static Mat3 rotation(double a) {
    Mat3 Q = Mat3::Identity();
    Q(0, 0) = std::cos(a); Q(0, 1) = -std::sin(a);
    Q(1, 0) = std::sin(a); Q(1, 1) = std::cos(a);
    return Q;
  }

  Vec3 displacement(const Vec3& X, double t) const override {
    const double R = std::hypot(X[0], X[1]);
    return rotation(alpha(R, t)) * X - X;
  }
  Vec3 velocity(const Vec3& X, double t) const override {
    // dx/dt = alpha_dot e_z x x
    const double R = std::hypot(X[0], X[1]);
    const Vec3 x = rotation(alpha(R, t)) * X;
    const double adot = kA * c_ * kPi * std::cos(c_ * kPi * t) * h(R);
    return Vec3(-adot * x[1], adot * x[0], 0.0);
  }
  Mat3 deformation_gradient(const Vec3& X, double t) const override {
    // F = Q + (Q e_z x X) (x) Grad alpha,  Grad alpha = A sin(c pi t) h'(R) (X, Y, 0)/R
    const double R = std::hypot(X[0], X[1]);
    const Mat3 Q = rotation(alpha(R, t));
    const Vec3 grad_alpha = kA * std::sin(c_ * kPi * t) * dh(R) / R * Vec3(X[0], X[1], 0.0);
    return Q + (Q * Vec3(-X[1], X[0], 0.0)) * grad_alpha.transpose();
  }
  Vec3 body_force(const Vec3& X, double t) const override {
    // With gamma = R alpha' (the shear of each circle), J = 1 and
    // sigma = mu (B - I) = mu [gamma^2 e_phi e_phi + gamma (e_r e_phi + e_phi e_r)]:
    //   (div sigma)_r = -mu gamma^2 / R,  (div sigma)_phi = mu (gamma' + 2 gamma / R);
    //   acceleration a_r = -R alpha_dot^2, a_phi = R alpha_ddot;
    //   b = a - div sigma / rho0:
    //   b_r   = -R (A c pi cos)^2 h^2 + (mu/rho0) R (A sin)^2 h'^2
    //   b_phi = -A sin [ R (c pi)^2 h + (mu/rho0) (3 h' + R h'') ]
    // (Vaango's extForceGeneralizedVortex writes the same with
    // 3 h' + R h'' = 64 (96 R^3 - 240 R^2 + 188 R - 45).)
    const double R = std::hypot(X[0], X[1]);
    const double s = std::sin(c_ * kPi * t), co = std::cos(c_ * kPi * t);
    const double mu = m_.shear_modulus;
    const double br = -R * std::pow(kA * c_ * kPi * co, 2) * h(R) * h(R) +
                      (mu / rho0_) * R * std::pow(kA * s * dh(R), 2);
    const double bphi = -kA * s * (R * c_ * c_ * kPi * kPi * h(R) + (mu / rho0_) * (3.0 * dh(R) + R * d2h(R)));
    const double beta = std::atan2(X[1], X[0]) + alpha(R, t);
    return Vec3(std::cos(beta) * br - std::sin(beta) * bphi, std::sin(beta) * br + std::cos(beta) * bphi, 0.0);
  }

 private:
  static constexpr double kA = 1.0;
  CnhMmsParams m_;
  double rho0_, c_;
};

}  // namespace

std::unique_ptr<ManufacturedSolution> make_axis_aligned_mms(const CnhMmsParams& model, double rho0,
                                                            double amplitude) {
  return std::make_unique<AxisAligned>(model, rho0, amplitude);
}
std::unique_ptr<ManufacturedSolution> make_generalized_vortex_mms(const CnhMmsParams& model, double rho0) {
  return std::make_unique<GeneralizedVortex>(model, rho0);
}

const std::vector<std::string>& vaango_mms_names() {
  static const std::vector<std::string> n = {"AxisAligned", "AxisAligned3L", "GeneralizedVortex", "ExpandingRing",
                                             "UniaxialStrainHarmonic", "UniaxialStrainHomogeneousLinear",
                                             "UniaxialStrainHomogeneousQuadratic"};
  return n;
}
const std::vector<std::string>& implemented_mms_names() {
  static const std::vector<std::string> n = {"AxisAligned", "GeneralizedVortex", "ExpandingRing"};
  return n;
}

std::unique_ptr<ManufacturedSolution> make_mms(const std::string& name, const CnhMmsParams& model, double rho0) {
  if (name == "AxisAligned") return make_axis_aligned_mms(model, rho0);
  if (name == "GeneralizedVortex") return make_generalized_vortex_mms(model, rho0);
  if (name == "ExpandingRing") return make_expanding_ring_mms(model, rho0);
  return nullptr;
}

void initialize_mms_particles(const ManufacturedSolution& mms, Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 X = p.x[i];
    const Vec3 u = mms.displacement(X, 0.0);
    p.x[i] = X + u;
    p.displacement[i] = u;
    p.v[i] = mms.velocity(X, 0.0);
    p.F[i] = mms.deformation_gradient(X, 0.0);
    p.volume[i] = p.F[i].determinant() * p.volume0[i];
  }
}

bool mms_deformed_initial_size(const ManufacturedSolution& mms) { return mms.name() == "AxisAligned"; }

bool set_mms_deformed_initial_size(const ManufacturedSolution& mms, Particles& p, double max_size) {
  if (!mms_deformed_initial_size(mms)) return false;
  // F(X, 0) at the reference position X = x - u (initialize_mms_particles has run).
  auto deformed = [&](std::size_t i) {
    const Mat3 F = mms.deformation_gradient(p.x[i] - p.displacement[i], 0.0);
    Mat3 s = Mat3::Zero();
    for (int d = 0; d < 3; ++d) s(d, d) = p.psize[i](d, d) * F(d, d);
    return s;
  };
  for (std::size_t i = 0; i < p.size(); ++i)
    if (deformed(i).diagonal().maxCoeff() > max_size) return false;
  for (std::size_t i = 0; i < p.size(); ++i) p.psize[i] = deformed(i);
  return true;
}

void set_mms_velocity(const ManufacturedSolution& mms, double t, Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = mms.velocity(p.x[i] - p.displacement[i], t);
}

void apply_mms_body_force(const ManufacturedSolution& mms, double t, Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) p.external_force[i] = p.mass[i] * mms.body_force(p.x[i] - p.displacement[i], t);
}

std::array<double, 2> mms_displacement_error_sums(const ManufacturedSolution& mms, const Particles& p, double t) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 X = p.x[i] - p.displacement[i];
    num += p.volume0[i] * (p.displacement[i] - mms.displacement(X, t)).squaredNorm();
    den += p.volume0[i];
  }
  return {num, den};
}

double mms_displacement_error_l2(const ManufacturedSolution& mms, const Particles& p, double t) {
  const auto [num, den] = mms_displacement_error_sums(mms, p, t);
  return den > 0.0 ? std::sqrt(num / den) : 0.0;
}

}  // namespace tephra
