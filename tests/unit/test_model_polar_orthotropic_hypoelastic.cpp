// polar_orthotropic_hypoelastic (models/solid/PolarOrthotropicHypoElastic.h):
// points of a ring about the z axis; the material frame (e_r, e_theta, e_z) comes
// from each point's initial position (the point context). Closed forms: Hooke's
// law with the engineering constants in the local frame,
//   eps_r = s_r/E_r - nu_tr s_t/E_t - nu_zr s_z/E_z,  eps_t = -nu_tr s_r/E_t + s_t/E_t - nu_zt s_z/E_z,
//   eps_z = -nu_zr s_r/E_z - nu_zt s_t/E_z + s_z/E_z,  gamma_ij = s_ij/G_ij.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/solid/PolarOrthotropicHypoElastic.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
using V3 = Eigen::Vector3d;
const double kEr = 10e9, kEt = 40e9, kEz = 20e9, kNtr = 0.3, kNzr = 0.25, kNzt = 0.2, kGtz = 6e9, kGzr = 4e9,
             kGrt = 5e9, kRho0 = 2000;

test::MapModelParameters params() {
  test::MapModelParameters p({{"E_r", kEr}, {"E_theta", kEt}, {"E_z", kEz}, {"nu_theta_r", kNtr}, {"nu_z_r", kNzr},
                              {"nu_z_theta", kNzt}, {"G_theta_z", kGtz}, {"G_z_r", kGzr}, {"G_r_theta", kGrt}});
  p.strings["symmetry_axis_top"] = "[1, 2, 5]";  // axis along e_z through (1, 2, .)
  p.strings["symmetry_axis_bottom"] = "[1, 2, -1]";
  return p;
}

// One step F = I + E (small) at a point of the ring of radius 0.3 at angle phi; returns the local stress.
M3 local_stress(const ConstitutiveModel& m, double phi, const M3& eps_local, V3& er, V3& et) {
  er = V3(std::cos(phi), std::sin(phi), 0), et = V3(-std::sin(phi), std::cos(phi), 0);
  M3 Q;
  Q.row(0) = er.transpose(), Q.row(1) = et.transpose(), Q.row(2) = V3::UnitZ().transpose();
  test::PointState s(m);
  s.x = V3(1, 2, 0.7) + 0.3 * er;
  EXPECT_EQ(test::step_point(m, kRho0, s, M3::Identity(), 0.0), -1);
  EXPECT_NEAR(s.history[0][0], 0.3, 1e-14);  // r
  EXPECT_NEAR(s.history[2][0], 1.7, 1e-14);  // z from the bottom point
  const M3 F = M3::Identity() + Q.transpose() * eps_local * Q;  // symmetric: no rotation, U = F
  EXPECT_EQ(test::step_point(m, kRho0, s, F, 1e-6), -1);
  return Q * s.stress * Q.transpose();
}

TEST(ModelPolarOrthotropicHypoElastic, RingRadialHoopAxialAndShearStiffnessFromEngineeringConstants) {
  const ConstitutiveModelP m = create_constitutive_model("polar_orthotropic_hypoelastic", params());
  ASSERT_TRUE(m);
  const double e = 1e-7;  // one small step: the midpoint-U increment equals eps to O(e^2) = 1e-14
  for (double phi : {0.0, 0.7, 2.0, -2.5, std::numbers::pi / 2}) {
    V3 er, et;
    for (int dir = 0; dir < 3; ++dir) {
      M3 eps = M3::Zero();
      eps(dir, dir) = e;
      const M3 s = local_stress(*m, phi, eps, er, et);
      // Normal strains from the compliance relations (closed form in the header comment).
      const double epr = s(0, 0) / kEr - kNtr * s(1, 1) / kEt - kNzr * s(2, 2) / kEz;
      const double ept = -kNtr * s(0, 0) / kEt + s(1, 1) / kEt - kNzt * s(2, 2) / kEz;
      const double epz = -kNzr * s(0, 0) / kEz - kNzt * s(1, 1) / kEz + s(2, 2) / kEz;
      EXPECT_NEAR(epr, eps(0, 0), 1e-6 * e) << "phi " << phi << " dir " << dir;
      EXPECT_NEAR(ept, eps(1, 1), 1e-6 * e);
      EXPECT_NEAR(epz, eps(2, 2), 1e-6 * e);
      EXPECT_NEAR(s(0, 1), 0.0, 1e-6 * kEt * e);
    }
    // Hoop strain is 4x stiffer than radial here: sigma_tt(eps_t) / sigma_rr(eps_r) = C_tt / C_rr.
    M3 eps_r = M3::Zero(), eps_t = M3::Zero();
    eps_r(0, 0) = e, eps_t(1, 1) = e;
    const double Crr = local_stress(*m, phi, eps_r, er, et)(0, 0), Ctt = local_stress(*m, phi, eps_t, er, et)(1, 1);
    const auto* pm = static_cast<const PolarOrthotropicHypoElastic*>(m.get());
    EXPECT_NEAR(Crr, pm->stiffness()(0, 0) * e, 1e-6 * Crr);
    EXPECT_NEAR(Ctt, pm->stiffness()(1, 1) * e, 1e-6 * Ctt);
    EXPECT_GT(Ctt, 3 * Crr);
    // Shears: sigma_ij = G_ij gamma_ij, gamma = 2 eps.
    const std::pair<int, int> ij[3] = {{1, 2}, {2, 0}, {0, 1}};
    const double G[3] = {kGtz, kGzr, kGrt};
    for (int k = 0; k < 3; ++k) {
      M3 eps = M3::Zero();
      eps(ij[k].first, ij[k].second) = eps(ij[k].second, ij[k].first) = e;
      const M3 s = local_stress(*m, phi, eps, er, et);
      EXPECT_NEAR(s(ij[k].first, ij[k].second), G[k] * 2 * e, 1e-6 * G[k] * e);
    }
  }
}

TEST(ModelPolarOrthotropicHypoElastic, UniformGlobalStrainGivesAngleDependentStress) {
  // The same global strain F = I + e e_x (x) e_x: at phi = 0 it is radial (sigma_xx = C_rr e),
  // at phi = pi/2 it is hoop (sigma_xx = C_tt e): the ring's anisotropy, from x_p alone.
  const ConstitutiveModelP m = create_constitutive_model("polar_orthotropic_hypoelastic", params());
  const auto* pm = static_cast<const PolarOrthotropicHypoElastic*>(m.get());
  const double e = 1e-7;
  M3 F = M3::Identity();
  F(0, 0) += e;
  for (const auto& [phi, C] : {std::pair{0.0, pm->stiffness()(0, 0)}, std::pair{std::numbers::pi / 2, pm->stiffness()(1, 1)},
                               std::pair{std::numbers::pi, pm->stiffness()(0, 0)}, std::pair{-std::numbers::pi / 2, pm->stiffness()(1, 1)}}) {
    test::PointState s(*m);
    s.x = V3(1 + 0.3 * std::cos(phi), 2 + 0.3 * std::sin(phi), 0.0);
    ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
    ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-6), -1);
    EXPECT_NEAR(s.stress(0, 0), C * e, 1e-6 * C * e) << "phi = " << phi;
    EXPECT_NEAR(s.stress(0, 1), 0.0, 1e-6 * C * e);
  }
}

TEST(ModelPolarOrthotropicHypoElastic, FrameIsMaterialAndParameters) {
  // The frame is fixed at initialization: moving the point afterwards changes nothing.
  const ConstitutiveModelP m = create_constitutive_model("polar_orthotropic_hypoelastic", params());
  EXPECT_TRUE(m->needs_position());
  test::PointState s(*m), t(*m);
  s.x = t.x = V3(1.3, 2, 0);
  ASSERT_EQ(test::step_point(*m, kRho0, s, M3::Identity(), 0.0), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, t, M3::Identity(), 0.0), -1);
  t.x = V3(1, 2.3, 0);  // moved by a quarter turn
  M3 F = M3::Identity();
  F(0, 0) += 1e-6;
  ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-6), -1);
  ASSERT_EQ(test::step_point(*m, kRho0, t, F, 1e-6), -1);
  EXPECT_EQ(s.stress, t.stress);
  test::MapModelParameters p = params();
  p.strings["symmetry_axis_top"] = "[1, 2, -1]";  // = bottom
  EXPECT_THROW(create_constitutive_model("polar_orthotropic_hypoelastic", p), std::invalid_argument);
  test::MapModelParameters q = params();
  q.values["nu_theta_r"] = 3.0;  // indefinite compliance
  EXPECT_THROW(create_constitutive_model("polar_orthotropic_hypoelastic", q), std::invalid_argument);
  test::MapModelParameters r = params();
  r.values.erase("G_z_r");
  EXPECT_THROW(create_constitutive_model("polar_orthotropic_hypoelastic", r), std::invalid_argument);
}

}  // namespace
}  // namespace tephra
