// Rigid-body rotation of a free elastic disk (inputs/mpm/rotating_disk.ups):
// objectivity of the explicit MPM step.
//
// The particles start with v = omega e_z x (x - c), zero stress, and the run
// goes to a quarter turn (theta = pi/2). What stress is legitimate:
//  * centrifugal: a spinning disk needs a centripetal force, which only the
//    stress can give; its scale is rho omega^2 R^2 (plane stress, spun-up
//    disk in equilibrium: max sigma = (3 + nu)/8 rho omega^2 R^2 = 0.41 of it;
//    started unstressed, the dynamic response overshoots by at most 2x,
//    so max |sigma| <= 0.83 rho omega^2 R^2).
//  * spurious, from the F update: for l = W (skew), first_order
//    F <- (I + dt W) F stretches by (I + dt W)^T (I + dt W) = I - dt^2 W^2 each
//    step, i.e. an in-plane strain (omega dt)^2 / 2 per step, theta omega dt / 2
//    after the quarter turn: O(dt), ~3e-4 here, i.e. ~ E * 3e-4 ~ 0.4 Pa.
//    The exact update exp(dt W) is a rotation: "round-off times the rotation"
//    means that the stress it makes is what n = theta/(omega dt) steps of
//    rounding (n eps ~ 1e-12 relative) give, i.e. nothing above the physics.
// Checks: with taylor_series (6 terms, error (omega dt)^7/7! per step) the
// max |sigma| stays below 0.83 rho omega^2 R^2 + round-off; with first_order
// the extra stress (first_order - taylor, max over particles) is O(dt):
// halving the step halves it (observed order 1 within 0.25).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

constexpr double kOmega = 0.05, kRadius = 0.3, kRho = 1000.0;

struct SpinResult {
  double max_stress = 0;  // max over particles of the largest |principal| stress at the quarter turn
  double max_stress_history = 0;  // ... over the whole run
  double angle = 0;       // rotation of the particle cloud measured from one rim particle
};

SpinResult spin(const std::string& algorithm, double multiplier) {
  auto deck = load_deck(test::source_dir() + "/inputs/mpm/rotating_disk.ups");
  for (DeckNode& c : deck->root.children)
    if (c.name == "MPM")
      for (DeckNode& f : c.children)
        if (f.name == "deformation_gradient") f.attributes = {{"algorithm", algorithm}};
  const double max_time = deck->root.require_child("Time").get_double("maxTime");
  auto comp = make_mpm_component(*deck);
  comp->initialize();
  Particles& p = comp->materials()[0].particles;
  const Vec3 centre(0.5, 0.5, 0.0);
  std::size_t rim = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 r = p.x[i] - centre;
    p.v[i] = Vec3(-kOmega * r[1], kOmega * r[0], 0.0);
    if (r.head<2>().norm() > (p.x[rim] - centre).head<2>().norm()) rim = i;
  }
  const Vec3 r0 = p.x[rim] - centre;
  SpinResult s;
  double t = 0;
  int step = 0;
  auto max_principal = [&] {
    double m = 0;
    for (const Mat3& sig : comp->materials()[0].particles.stress) m = std::max(m, sig.cwiseAbs().maxCoeff());
    return m;
  };
  while (t < max_time) {
    const double dt = std::min(multiplier * comp->stable_timestep(), max_time - t);
    comp->advance(t, dt, ++step);
    t += dt;
    s.max_stress_history = std::max(s.max_stress_history, max_principal());
  }
  s.max_stress = max_principal();
  const Vec3 r1 = comp->materials()[0].particles.x[rim] - centre;
  s.angle = std::atan2(r0[0] * r1[1] - r0[1] * r1[0], r0[0] * r1[0] + r0[1] * r1[1]);
  return s;
}

TEST(MpmRotatingDisk, NoStressBeyondCentrifugalWithExactRotationUpdate) {
  const double scale = kRho * kOmega * kOmega * kRadius * kRadius;  // 0.225 Pa
  const SpinResult taylor = spin("taylor_series", 0.2);
  const SpinResult first = spin("first_order", 0.2);
  const SpinResult first_half = spin("first_order", 0.1);
  const SpinResult taylor_half = spin("taylor_series", 0.1);
  const double extra = first.max_stress_history - taylor.max_stress_history;
  const double extra_half = first_half.max_stress_history - taylor_half.max_stress_history;
  const double order = std::log2(extra / extra_half);
  std::printf("rotating disk: rho w^2 R^2 = %.3f Pa; max|sigma| over the quarter turn: taylor %.4f (dt/2: %.4f), "
              "first_order %.4f (dt/2: %.4f) Pa; spurious first-order part %.4f -> %.4f, order %.2f; "
              "cloud rotated %.5f rad (pi/2 = %.5f)\n",
              scale, taylor.max_stress_history, taylor_half.max_stress_history, first.max_stress_history,
              first_half.max_stress_history, extra, extra_half, order, taylor.angle, M_PI / 2);
  EXPECT_LT(taylor.max_stress_history, 0.83 * scale);
  EXPECT_LT(taylor_half.max_stress_history, 0.83 * scale);
  EXPECT_GT(extra, 0.0);
  EXPECT_NEAR(order, 1.0, 0.25);
  EXPECT_NEAR(taylor.angle, M_PI / 2, 0.01);
}

}  // namespace
}  // namespace tephra
