// Manufactured solutions (mpm/mms/): the body force must satisfy the balance
// of momentum for the exact motion,  b = d2u/dt2 - (1/rho0) Div P(F),
// checked here with central differences of the exact u (in t) and of the
// cnh_mms P(F(X, t)) (in X), independent of the closed forms in the code.
// Also F = I + Grad u and v = du/dt by differences.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include <Eigen/LU>

#include "mpm/Particles.h"
#include "mpm/mms/ManufacturedSolution.h"
#include "mpm/mms/MmsInitialSize.h"

namespace tephra {
namespace {

// term_tol: a tolerance relative to |d2u/dt2| + |Div P|/rho0, for solutions
// whose b is a small difference of large terms (the ring: both ~1e4, b ~ 10,
// while the difference truncation, O(ht^2 u'''') + O(hx^2 P'''), is ~1e-4).
void check_balance(const ManufacturedSolution& mms, const CnhMmsParams& model, double rho0, const Vec3& X,
                   double t, double tscale, double term_tol = 0.0) {
  const double hx = 1e-4, ht = 1e-4 * tscale;
  // d2u/dt2 (error O(ht^2)), Div P (error O(hx^2)).
  const Vec3 acc = (mms.displacement(X, t + ht) - 2.0 * mms.displacement(X, t) + mms.displacement(X, t - ht)) /
                   (ht * ht);
  Vec3 div = Vec3::Zero();
  for (int j = 0; j < 3; ++j) {
    Vec3 e = Vec3::Zero();
    e[j] = hx;
    const Mat3 Pp = cnh_mms_first_piola(mms.deformation_gradient(X + e, t), model);
    const Mat3 Pm = cnh_mms_first_piola(mms.deformation_gradient(X - e, t), model);
    div += (Pp.col(j) - Pm.col(j)) / (2 * hx);
  }
  const Vec3 expected = acc - div / rho0;
  const Vec3 b = mms.body_force(X, t);
  EXPECT_NEAR((b - expected).norm(), 0.0, 1e-5 * (1.0 + expected.norm()) + term_tol * (acc.norm() + div.norm() / rho0))
      << "X = " << X.transpose() << " t = " << t;
  // v = du/dt, F = I + Grad u
  const Vec3 v = (mms.displacement(X, t + ht) - mms.displacement(X, t - ht)) / (2 * ht);
  EXPECT_NEAR((mms.velocity(X, t) - v).norm(), 0.0, 1e-6 * (1.0 + v.norm()));
  Mat3 F = Mat3::Identity();
  for (int j = 0; j < 3; ++j) {
    Vec3 e = Vec3::Zero();
    e[j] = hx;
    F.col(j) += (mms.displacement(X + e, t) - mms.displacement(X - e, t)) / (2 * hx);
  }
  // Truncation O(hx^2 u'''): u''' reaches ~1e2 for the vortex (h''' = 6144 ).
  EXPECT_NEAR((mms.deformation_gradient(X, t) - F).norm(), 0.0, 1e-5);
}

TEST(MpmMms, AxisAlignedBodyForceBalancesMomentum) {
  const CnhMmsParams model{8333.0, 3846.0};  // AA.ups
  auto mms = make_axis_aligned_mms(model, 1.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 50; ++i) check_balance(*mms, model, 1.0, Vec3(u(rng), u(rng), u(rng)), 0.02 * u(rng), 0.01);
  // u = 0 on the faces X_i in {0, 1} (the symmetry planes of the deck).
  EXPECT_NEAR(mms->displacement(Vec3(0.0, 0.3, 1.0), 0.004)[0], 0.0, 1e-17);
  EXPECT_NEAR(mms->displacement(Vec3(0.2, 0.3, 1.0), 0.004)[2], 0.0, 1e-17);
}

TEST(MpmMms, GeneralizedVortexBodyForceBalancesMomentum) {
  const CnhMmsParams model{2000.0, 384.615};
  auto mms = make_generalized_vortex_mms(model, 1000.0);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const double R = 0.75 + 0.5 * u(rng), th = 6.283 * u(rng);
    check_balance(*mms, model, 1000.0, Vec3(R * std::cos(th), R * std::sin(th), 0.1 * u(rng)), 2.0 * u(rng), 1.0);
  }
  // Isochoric: det F = 1.
  EXPECT_NEAR(mms->deformation_gradient(Vec3(0.9, 0.4, 0.0), 0.3).determinant(), 1.0, 1e-13);
}

// Vaango's ring: E = 1e7, mu = E/2 (nu = 0, so K = 2 mu/3 and lambda = 0),
// rho0 = 1000; C = 100 m/s, omega = C pi / (2 rb) = 100 pi (period 0.02 s).
TEST(MpmMms, ExpandingRingBodyForceBalancesMomentum) {
  const CnhMmsParams model{2.0 * 5e6 / 3.0, 5e6};
  auto mms = make_expanding_ring_mms(model, 1000.0);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const double R = 0.4 + 0.2 * u(rng), th = 6.283 * u(rng);
    check_balance(*mms, model, 1000.0, Vec3(R * std::cos(th), R * std::sin(th), 0.1 * u(rng)), 0.02 * u(rng), 0.01,
                  1e-8);
  }
  // With lambda != 0 too (the balance holds for any K; only the free faces need lambda = 0).
  const CnhMmsParams stiff{8e6, 5e6};
  auto mms2 = make_expanding_ring_mms(stiff, 1000.0);
  for (int i = 0; i < 20; ++i) {
    const double R = 0.4 + 0.2 * u(rng), th = 6.283 * u(rng);
    check_balance(*mms2, stiff, 1000.0, Vec3(R * std::cos(th), R * std::sin(th), 0.0), 0.02 * u(rng), 0.01, 1e-8);
  }
  // Traction-free faces: P e_R = 0 at R = ri = 0.4 and ro = 0.6 (lambda_r = 1 there).
  for (double R : {0.4, 0.6}) {
    const Vec3 X(R * std::cos(0.7), R * std::sin(0.7), 0.0), eR(std::cos(0.7), std::sin(0.7), 0.0);
    const Mat3 P = cnh_mms_first_piola(mms->deformation_gradient(X, 0.005), model);
    EXPECT_NEAR((P * eR).norm(), 0.0, 1e-9 * model.shear_modulus) << "R = " << R;
  }
  // At rest at t = 0 (u = 0, F = I) with v = A omega g(R) (X, Y, 0).
  EXPECT_EQ(mms->displacement(Vec3(0.5, 0.0, 0.0), 0.0), Vec3::Zero());
  const double g05 = (-2.0 / (0.36 * -0.6)) * 0.25 + (3.0 / (0.36 * -0.6)) * 0.5 + (-2.4 / (0.6 * -0.6));
  EXPECT_NEAR(mms->velocity(Vec3(0.5, 0.0, 0.0), 0.0)[0], 0.1 * 100.0 * std::numbers::pi * g05 * 0.5, 1e-10);
}

// Vaango's initAxisAligned sets p.size = diag(size_dd F_dd(X, 0)) (the
// deformed domain at t = 0), F_dd = 1 + A pi cos(pi X_d) sin(phi_d), A = 0.05,
// phi = (0, 2 pi/3, 4 pi/3); set_mms_deformed_initial_size does the same when
// every deformed size stays <= max_size, and leaves the sizes otherwise.
TEST(MpmMms, AxisAlignedInitialSizeIsTheDeformedDomain) {
  const CnhMmsParams model{8333.0, 3846.0};
  auto mms = make_axis_aligned_mms(model, 1.0);
  const double A = 0.05, pi = std::numbers::pi;
  auto seeded = [](double size) {
    Particles p;
    const Mat3 sz = size * Mat3::Identity();
    long long id = 0;
    for (double X : {0.03125, 0.40625, 0.96875})
      for (double Y : {0.03125, 0.53125})
        for (double Z : {0.09375, 0.71875}) p.add(Vec3(X, Y, Z), Vec3::Zero(), 1.0, 1.0, 300.0, 0.0, id++, sz);
    return p;
  };
  Particles p = seeded(0.5);  // 2 particles per cell direction
  initialize_mms_particles(*mms, p);
  ASSERT_TRUE(set_mms_deformed_initial_size(*mms, p, 1.0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 X = p.x[i] - p.displacement[i];
    for (int d = 0; d < 3; ++d) {
      const double Fdd = 1.0 + A * pi * std::cos(pi * X[d]) * std::sin(d * 2.0 * pi / 3.0);
      EXPECT_NEAR(p.psize[i](d, d), 0.5 * Fdd, 1e-15) << i << " " << d;
      for (int e = 0; e < 3; ++e)
        if (e != d) EXPECT_EQ(p.psize[i](d, e), 0.0);
    }
  }
  // One particle per cell: 1 + A pi |sin(2 pi/3)| = 1.136 > 1 at Y near 0, beyond max_size 1.
  Particles q = seeded(1.0);
  initialize_mms_particles(*mms, q);
  EXPECT_FALSE(set_mms_deformed_initial_size(*mms, q, 1.0));
  for (const Mat3& s : q.psize) EXPECT_EQ(s, Mat3::Identity());
  EXPECT_TRUE(set_mms_deformed_initial_size(*mms, q, 2.0));
  // The other solutions keep the seeded size (Vaango's initGeneralizedVortex, initExpandingRing: pSize = size).
  auto ring = make_expanding_ring_mms(CnhMmsParams{8e6, 5e6}, 1000.0);
  Particles r = seeded(0.5);
  EXPECT_FALSE(set_mms_deformed_initial_size(*ring, r, 1.0));
  for (const Mat3& s : r.psize) EXPECT_EQ(s, 0.5 * Mat3::Identity());
}

}  // namespace
}  // namespace tephra
