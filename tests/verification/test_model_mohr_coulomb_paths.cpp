// Mohr-Coulomb (classic, VT ch. 19) in triaxial compression, strain controlled in the
// axial direction with the lateral stress held at -sigma_conf (secant solve per step,
// one-point driver tests/support/SolidModelDriver.h). Perfect plasticity, so after yield
// the axial stress stays on the closed-form strength (inventory oracle 15, eq. 19.5):
//   sigma_a = 2 c cos(phi)/(1 - sin(phi)) + sigma_conf (1 + sin(phi))/(1 - sin(phi))
// and the stress no longer changes, so every further strain increment is plastic:
// along the compression edge the flow n_13 + n_23 (eq. 19.28-19.29) gives the dilatancy
//   tr(de)/de_axial = -2 sin(psi)/(1 - sin(psi))
// (no volume change for psi = 0; associated psi = phi dilates most). Also through the
// real MPM step with a deck (PrescribedDriver) against the point driver.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/grid/Loop.h"
#include "models/geo/MohrCoulomb.h"
#include "tests/support/PrescribedDriver.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
using test::PointState;
using test::step_point;

const double kRho0 = 2000.0, kC = 1.0e6, kPhi = 30.0;

ConstitutiveModelP mohr_coulomb(double psi) {
  test::MapModelParameters p;
  p.strings["model_type"] = "classic";
  p.add_block("model_parameters", "",
              {{"shear_modulus", 3.0e9}, {"bulk_modulus", 8.0e9}, {"cohesion", kC},
               {"angle_internal_friction", kPhi}, {"angle_dilation", psi}});
  p.add_block("integration_parameters", "");
  return create_constitutive_model("mohr_coulomb", p);
}

struct TriaxialResult {
  double axial_stress = 0, worst_strength = 0, worst_dilatancy = 0;
  int plateau_steps = 0;
};

TriaxialResult triaxial(double psi, double conf) {
  const ConstitutiveModelP m = mohr_coulomb(psi);
  const double sphi = std::sin(kPhi * M_PI / 180), spsi = std::sin(psi * M_PI / 180);
  const double strength = 2 * kC * std::cos(kPhi * M_PI / 180) / (1 - sphi) + conf * (1 + sphi) / (1 - sphi);
  const double dilatancy = -2 * spsi / (1 - spsi);
  PointState s(*m);
  s.stress = -conf * M3::Identity();  // consolidated isotropically (hypoelastic: stress is the state)
  TriaxialResult out;
  const int n = 400;
  double lr = 0.0, la_old = 0.0, lr_old = 0.0;
  for (int k = 1; k <= n; ++k) {
    const double la = -0.01 * k / n;
    auto run = [&](double x, PointState& t) {
      t = s;
      EXPECT_EQ(step_point(*m, kRho0, t, M3(Eigen::Vector3d(std::exp(x), std::exp(x), std::exp(la)).asDiagonal()), 1e-3),
                -1);
      return t.stress(0, 0) + conf;
    };
    PointState t0 = s, t1 = s;
    double x0 = lr, x1 = lr + 1e-7;
    double r0 = run(x0, t0), r1 = run(x1, t1);
    for (int it = 0; it < 30 && std::abs(r1) > 1e-12 * (strength + conf); ++it) {
      const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
      x0 = x1, r0 = r1, x1 = x2;
      r1 = run(x1, t1);
    }
    lr = x1;
    const bool was_plastic = std::abs(-s.stress(2, 2) - strength) < 1e-9 * strength;
    s = t1;
    const double sa = -s.stress(2, 2);
    EXPECT_LE(sa, strength * (1 + 1e-10));  // never above the strength (lateral solve to 1e-12)
    if (was_plastic) {  // on the plateau for the whole step
      ++out.plateau_steps;
      out.worst_strength = std::max(out.worst_strength, std::abs(sa / strength - 1));
      // the model's strain increment (midpoint rule on the stretch, diagonal): de_ii = 2 (l1 - l0)/(l1 + l0)
      auto d = [](double l1, double l0) { return 2 * (std::exp(l1) - std::exp(l0)) / (std::exp(l1) + std::exp(l0)); };
      const double tr = 2 * d(lr, lr_old) + d(la, la_old);
      out.worst_dilatancy = std::max(out.worst_dilatancy, std::abs(tr / d(la, la_old) - dilatancy));
    }
    la_old = la;
    lr_old = lr;
  }
  out.axial_stress = -s.stress(2, 2);
  std::printf("psi %.0f conf %.1e: sigma_a = %.9e (closed form %.9e), plateau steps %d, strength err %.2e, "
              "dilatancy err %.2e (ratio %.6f)\n",
              psi, conf, out.axial_stress, strength, out.plateau_steps, out.worst_strength, out.worst_dilatancy,
              dilatancy);
  return out;
}

TEST(MohrCoulombPaths, TriaxialStrengthAndDilatancyAreTheClosedForms) {
  for (double conf : {0.0, 5.0e6})
    for (double psi : {0.0, 10.0, 30.0}) {
      const TriaxialResult r = triaxial(psi, conf);
      EXPECT_GT(r.plateau_steps, 200);
      EXPECT_LT(r.worst_strength, 1e-9);
      EXPECT_LT(r.worst_dilatancy, 1e-8);
    }
}

TEST(MohrCoulombPaths, DeckThroughTheMpmStepEqualsThePointDriver) {
  set_thread_count(1);
  const std::string xml =
      "<constitutive_model type=\"mohr_coulomb\"><model_type>classic</model_type>"
      "<model_parameters><shear_modulus>3.0e9</shear_modulus><bulk_modulus>8.0e9</bulk_modulus>"
      "<cohesion>1.0e6</cohesion><angle_internal_friction>30</angle_internal_friction>"
      "<angle_dilation>10</angle_dilation></model_parameters>"
      "<integration_parameters><yield_tolerance>1e-6</yield_tolerance>"
      "<solution_algorithm>modified_euler</solution_algorithm></integration_parameters>"
      "</constitutive_model>";
  // axial compression with lateral extension (elastic stress ratio 4 > (1 + sin phi)/(1 - sin phi) = 3: plastic)
  const M3 F1 = Eigen::Vector3d(1.002, 1.002, 0.99).asDiagonal();
  const int n = 100;
  const auto h = test::drive_prescribed(
      xml, {PrescribedRow{0.0, M3::Identity(), 0.0, Vec3::UnitZ()}, PrescribedRow{1e-3, F1, 0.0, Vec3::UnitZ()}},
      {.steps = n, .density = kRho0});
  const ConstitutiveModelP m = mohr_coulomb(10.0);
  const PointState s = test::drive_path(*m, kRho0, [&](double a) { return M3(M3::Identity() + a * (F1 - M3::Identity())); }, n);
  EXPECT_LE((h.stress.back() - s.stress).norm(), 1e-9 * s.stress.norm());
  // the path ends on the compression edge (equal lateral stresses): f_13 = 0
  const Eigen::Vector3d pr(-h.stress.back()(0, 0), -h.stress.back()(1, 1), -h.stress.back()(2, 2));
  const double sphi = std::sin(kPhi * M_PI / 180);
  EXPECT_NEAR(pr(2) * (1 - sphi) - pr(0) * (1 + sphi), 2 * kC * std::cos(kPhi * M_PI / 180), 1e-9 * pr(2));
  EXPECT_GT(h.plastic_work.back(), 0.0);
}

}  // namespace
}  // namespace tephra
