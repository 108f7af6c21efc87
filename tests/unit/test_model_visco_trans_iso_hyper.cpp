// visco_trans_iso_hyper (models/solid/ViscoTransIsoHyper.h): trans_iso_hyper
// plus Prony terms on the deviatoric stress (Puso & Weiss 1998; Simo 1987 recursion)
//   sigma = sigma_e + (1/J) F (sum_i y_i H_i) F^T,
//   H_i(t) = int_0^t exp(-(t-s)/t_i) dS_e/ds ds,  S_e = J F^{-1} dev(sigma_e) F^{-T}.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "models/solid/TransIsoHyper.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kRho0 = 1100.0;

test::MapModelParameters base(const std::string& dir) {
  test::MapModelParameters p({{"bulk_modulus", 8.0e7}, {"c1", 1.0e6}, {"c2", 0.5e6}, {"c3", 2.0e5}, {"c4", 5.0},
                              {"c5", 5.0e7}, {"fiber_stretch", 1.2}, {"max_fiber_strain", 2.0},
                              {"max_matrix_strain", 2.0}});
  p.strings["direction_of_symm"] = dir;
  return p;
}
TransIsoHyperParams elastic_params(const std::string& dir) { return read_trans_iso_hyper_params(base(dir), "t"); }

M3 shear(double g) {
  M3 F = M3::Identity();
  F(0, 1) = g;
  return F;
}
M3 dev(const M3& s) { return s - s.trace() / 3 * M3::Identity(); }

TEST(ModelViscoTransIsoHyper, WithoutPronyTermsIsTransIsoHyper) {
  test::MapModelParameters p = base("[1, 1, 0]");
  const ConstitutiveModelP v = create_constitutive_model("visco_trans_iso_hyper", p);
  const ConstitutiveModelP e = create_constitutive_model("trans_iso_hyper", p);
  ASSERT_TRUE(v && e);
  EXPECT_EQ(v->history().size(), 1u);  // SeDev only
  auto path = [](double a) { M3 F = shear(0.4 * a); F(2, 2) = 1 + 0.1 * a; return F; };
  const test::PointState sv = test::drive_path(*v, kRho0, path, 7), se = test::drive_path(*e, kRho0, path, 7);
  EXPECT_EQ(sv.stress, se.stress);
  EXPECT_EQ(sv.energy_density, se.energy_density);
}

TEST(ModelViscoTransIsoHyper, StepAndHoldRelaxesExponentially) {
  // F jumps to simple shear g0 within the first step [0, dt] and is held. The
  // recursion loads H at the step's midpoint: H_1 = exp(-dt/(2 tau)) S_e, and
  // relaxes exactly afterwards, so for t_n = n dt
  //   sigma(t_n) = sigma_e + sum_i y_i exp(-(t_n - dt/2)/tau_i) dev(sigma_e)
  // (F S_e F^T / J = dev sigma_e): the relaxation function 1 + sum y_i e^{-t/tau_i}
  // of a jump at t = dt/2. Two terms (y = 0.5, tau = 0.1 s; y = 0.25, tau = 1 s).
  test::MapModelParameters p = base("[1, 1, 0]");
  p.values["y1"] = 0.5, p.values["t1"] = 0.1, p.values["y3"] = 0.25, p.values["t3"] = 1.0;
  const ConstitutiveModelP m = create_constitutive_model("visco_trans_iso_hyper", p);
  ASSERT_EQ(m->history().size(), 3u);
  const M3 F = shear(0.1);
  const SolidPointResult e = trans_iso_hyper_point(F, kRho0, elastic_params("[1, 1, 0]"));
  const double dt = 0.01;
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  for (int n = 1; n <= 300; ++n) {
    ASSERT_EQ(test::step_point(*m, kRho0, s, F, dt), -1);
    const double t = n * dt, g = 1 + 0.5 * std::exp(-(t - dt / 2) / 0.1) + 0.25 * std::exp(-(t - dt / 2) / 1.0);
    const M3 expect = e.stress + (g - 1) * dev(e.stress);
    EXPECT_LE((s.stress - expect).norm(), 1e-12 * e.stress.norm()) << "t = " << t;
  }
  // After 3 s the fast term is gone (e^{-29.95}) and the slow one is e^{-2.995}.
  EXPECT_NEAR(s.stress(0, 1), e.stress(0, 1) * (1 + 0.25 * std::exp(-2.995)), 1e-9 * e.stress(0, 1));
  // Instantaneous shear modulus (1 + 0.75) G.
  EXPECT_DOUBLE_EQ(m->shear_modulus(), 1.75 * 2 * (1.0e6 + 0.5e6));
}

// The hereditary integral by parts, H(t) = S_e(t) - (1/tau) int_0^t e^{-(t-s)/tau} S_e(s) ds
// (S_e(0) = 0), by composite Simpson with 4000 intervals (error ~ 1e-13 relative).
M3 hereditary(const std::function<M3(double)>& Se, double t, double tau) {
  const int n = 4000;
  const double h = t / n;
  M3 sum = M3::Zero();
  for (int k = 0; k <= n; ++k) {
    const double s = k * h, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    sum += w * std::exp(-(t - s) / tau) * Se(s);
  }
  return Se(t) - (h / 3) * sum / tau;
}

TEST(ModelViscoTransIsoHyper, RampMatchesHereditaryIntegralToSecondOrder) {
  // Simple shear ramp g(t) = 0.3 t/T (T = 1 s) with stretched fibres along (1,1,0)/sqrt 2
  // (exponential and linear fibre branches), then hold to t = 2 s; one term y = 1, tau = 0.2 s.
  // Reference: sigma_e + (1/J) F y H(t) F^T with H from the quadrature above.
  const std::string dir = "[1, 1, 0]";
  const TransIsoHyperParams ep = elastic_params(dir);
  auto F_of = [](double t) { return shear(0.3 * std::min(t, 1.0)); };
  auto Se = [&](double t) {
    const M3 F = F_of(t);
    const M3 sd = dev(trans_iso_hyper_point(F, kRho0, ep).stress);
    return M3(F.determinant() * F.inverse() * sd * F.inverse().transpose());
  };
  const double tau = 0.2, y = 1.0;
  test::MapModelParameters p = base(dir);
  p.values["y1"] = y, p.values["t1"] = tau;
  const ConstitutiveModelP m = create_constitutive_model("visco_trans_iso_hyper", p);
  double err[2];
  for (int r = 0; r < 2; ++r) {
    const int n = r == 0 ? 40 : 80;  // steps per second
    test::PointState s(*m);
    ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    err[r] = 0;
    double scale = 0;
    for (int k = 1; k <= 2 * n; ++k) {
      const double t = double(k) / n;
      ASSERT_EQ(test::step_point(*m, kRho0, s, F_of(t), 1.0 / n), -1);
      if (k % (n / 4) != 0) continue;  // compare at t = 0.25, 0.5, ..., 2
      const M3 F = F_of(t);
      const M3 ref = trans_iso_hyper_point(F, kRho0, ep).stress + y * F * hereditary(Se, t, tau) * F.transpose() / F.determinant();
      err[r] = std::max(err[r], (s.stress - ref).norm());
      scale = std::max(scale, ref.norm());
    }
    err[r] /= scale;
  }
  RecordProperty("err_40", testing::PrintToString(err[0]));
  RecordProperty("err_80", testing::PrintToString(err[1]));
  EXPECT_LT(err[1], 1e-4);  // measured 3.1e-5
  EXPECT_NEAR(err[0] / err[1], 4.0, 0.8) << err[0] << " " << err[1];  // second order in dt
}

TEST(ModelViscoTransIsoHyper, RigidRotationOfAHeldStateRotatesTheStress) {
  // S_e(QF) = S_e(F): a rotation step leaves the hereditary integrals to relax as a hold step.
  test::MapModelParameters p = base("[0.6, 0.8, 0]");
  p.values["y1"] = 0.7, p.values["t1"] = 0.05;
  const ConstitutiveModelP m = create_constitutive_model("visco_trans_iso_hyper", p);
  const M3 F = shear(0.2);
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, s, F, 0.01), -1);
  test::PointState held = s, rotated = s;
  const M3 Q = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  ASSERT_EQ(test::step_point(*m, kRho0, held, F, 0.01), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, rotated, M3(Q * F), 0.01), -1);
  EXPECT_LE((rotated.stress - Q * held.stress * Q.transpose()).norm(), 1e-10 * held.stress.norm());
}

TEST(ModelViscoTransIsoHyper, Parameters) {
  test::MapModelParameters p = base("[1, 0, 0]");
  p.values["y2"] = 0.3;  // no t2
  EXPECT_THROW(create_constitutive_model("visco_trans_iso_hyper", p), std::invalid_argument);
  p.values["t2"] = -1;
  EXPECT_THROW(create_constitutive_model("visco_trans_iso_hyper", p), std::invalid_argument);
  p.values["t2"] = 2;
  p.values["y4"] = -0.1;
  EXPECT_THROW(create_constitutive_model("visco_trans_iso_hyper", p), std::invalid_argument);
  p.values["y4"] = 0;
  const ConstitutiveModelP m = create_constitutive_model("visco_trans_iso_hyper", p);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->history().size(), 2u);
  EXPECT_EQ(m->history()[1].name, "Hvisco1");
  p.values["failure_option"] = 1;
  EXPECT_THROW(create_constitutive_model("visco_trans_iso_hyper", p), std::logic_error);
}

}  // namespace
}  // namespace tephra
