// ExpandingRing manufactured solution (Vaango MMS.cc initExpandingRing /
// extForceExpandingRing; formulas below derived here in reference polar
// coordinates, checked against finite differences of P in
// tests/unit/test_mpm_mms_expanding_ring.cpp).
//
// A ring ri = 0.4 <= R <= ro = 0.6 (in the x-y plane, plane strain in z)
// breathes radially:
//   u(X, t) = s(t) g(R) (X, Y, 0),   s(t) = A sin(omega t),   A = 0.1,
//   omega = C pi / (2 rb),  rb = (ri + ro)/2,  C = sqrt(E/rho0),
//   g(R) = c3 R^2 + c2 R + c1,
//   c1 = -6 ri / (ro (ro - 3 ri)),  c2 = 3 (ro + ri) / (ro^2 (ro - 3 ri)),
//   c3 = -2 / (ro^2 (ro - 3 ri))   (Vaango's constants),
// so that (R g)' = 3 c3 R^2 + 2 c2 R + c1 vanishes at R = ri and R = ro.
// Stretches: lambda_r = 1 + s (R g)', lambda_t = 1 + s g, lambda_z = 1;
//   F = lambda_t I_2 + (lambda_r - lambda_t) e_R e_R + e_z e_z.
// cnh_mms: P = mu (F - F^{-T}) + lambda ln J F^{-T}, diagonal in (e_R, e_T, e_z):
//   P_r = mu (lr - 1/lr) + lambda ln J / lr,  P_t = mu (lt - 1/lt) + lambda ln J / lt.
// The radial balance rho0 d2u/dt2 = Div P + rho0 b gives
//   b = b_R (X, Y, 0)/R,
//   b_R = -omega^2 s g R - [dP_r/dR + (P_r - P_t)/R] / rho0,
//   dP_r/dR = [mu (1 + 1/lr^2) - lambda ln J / lr^2] lr' + (lambda / lr)(lr'/lr + lt'/lt),
//   lr' = s (6 c3 R + 2 c2),  lt' = s (2 c3 R + c2).
// Free faces: at R = ri, ro lambda_r = 1, so P_r = lambda ln(lambda_t): the
// faces are traction free only for lambda = 0, which is Vaango's material
// (E = 1e7, mu = E/2, so nu = 0 and K = 2 mu / 3). Tephra takes K, mu, rho0
// from the deck (E = 9 K mu / (3 K + mu), as for the other solutions).
#include <cmath>
#include <numbers>

#include "mpm/mms/ManufacturedSolution.h"

namespace tephra {

namespace {

constexpr double kPi = std::numbers::pi;

class ExpandingRing final : public ManufacturedSolution {
 public:
  ExpandingRing(const CnhMmsParams& m, double rho0) : m_(m), rho0_(rho0) {
    const double E = 9.0 * m.bulk_modulus * m.shear_modulus / (3.0 * m.bulk_modulus + m.shear_modulus);
    const double C = std::sqrt(E / rho0);
    omega_ = C * kPi / (2.0 * kRb);
  }
  std::string name() const override { return "ExpandingRing"; }

  double s(double t) const { return kA * std::sin(omega_ * t); }
  static double g(double R) { return (kC3 * R + kC2) * R + kC1; }
  static double dg(double R) { return 2.0 * kC3 * R + kC2; }
  static double d_Rg(double R) { return (3.0 * kC3 * R + 2.0 * kC2) * R + kC1; }  // (R g)'

  Vec3 displacement(const Vec3& X, double t) const override {
    return s(t) * g(std::hypot(X[0], X[1])) * Vec3(X[0], X[1], 0.0);
  }
  Vec3 velocity(const Vec3& X, double t) const override {
    return kA * omega_ * std::cos(omega_ * t) * g(std::hypot(X[0], X[1])) * Vec3(X[0], X[1], 0.0);
  }
  Mat3 deformation_gradient(const Vec3& X, double t) const override {
    const double R = std::hypot(X[0], X[1]), st = s(t);
    const double lt = 1.0 + st * g(R), lr = 1.0 + st * d_Rg(R);
    const Vec3 eR = R > 0.0 ? Vec3(X[0] / R, X[1] / R, 0.0) : Vec3::Zero();
    Mat3 F = Mat3::Identity();
    F(0, 0) = F(1, 1) = lt;
    F += (lr - lt) * eR * eR.transpose();
    return F;
  }
  Vec3 body_force(const Vec3& X, double t) const override {
    const double R = std::hypot(X[0], X[1]), st = s(t);
    const double mu = m_.shear_modulus, lambda = m_.lambda();
    const double lt = 1.0 + st * g(R), lr = 1.0 + st * d_Rg(R);
    const double dlt = st * dg(R), dlr = st * (6.0 * kC3 * R + 2.0 * kC2);
    const double lnJ = std::log(lr * lt);
    const double Pr = mu * (lr - 1.0 / lr) + lambda * lnJ / lr;
    const double Pt = mu * (lt - 1.0 / lt) + lambda * lnJ / lt;
    const double dPr = (mu * (1.0 + 1.0 / (lr * lr)) - lambda * lnJ / (lr * lr)) * dlr +
                       (lambda / lr) * (dlr / lr + dlt / lt);
    const double bR = -omega_ * omega_ * st * g(R) * R - (dPr + (Pr - Pt) / R) / rho0_;
    return bR / R * Vec3(X[0], X[1], 0.0);
  }

 private:
  static constexpr double kA = 0.1, kRi = 0.4, kRo = 0.6, kRb = 0.5 * (kRi + kRo);
  static constexpr double kC1 = -6.0 * kRi / (kRo * (kRo - 3.0 * kRi));
  static constexpr double kC2 = 3.0 * (kRo + kRi) / (kRo * kRo * (kRo - 3.0 * kRi));
  static constexpr double kC3 = -2.0 / (kRo * kRo * (kRo - 3.0 * kRi));
  CnhMmsParams m_;
  double rho0_, omega_ = 0.0;
};

}  // namespace

std::unique_ptr<ManufacturedSolution> make_expanding_ring_mms(const CnhMmsParams& model, double rho0) {
  return std::make_unique<ExpandingRing>(model, rho0);
}

}  // namespace tephra
