// Rigid-body rotation of an elastic disk (inputs/mpm/rotating_disk.ups: a
// comp_neo_hook disk of radius 0.3 on the GIMP grid of disks.ups) through the
// kinematic chain of the explicit step (advance() phases 9-10): stencils of
// the deck's interpolator, l_p = sum v*_g grad S^T with the nodes moving
// rigidly, v*_g = omega e_z x (x_g - c), the deck's deformation-gradient
// update and the material's stress update, over a quarter turn.
//
// Why the nodes are driven rather than the particles: with v*_g = W x_g,
// l_p = W sum_g x_g grad S_gp^T = W exactly (linear completeness of every
// interpolator), so the test isolates the time integration of F and the
// model's objectivity. A free-spinning disk also carries (i) the physical
// centrifugal stress ~ rho omega^2 R^2 and (ii) a P2G error: v_g = W xbar_g
// with xbar_g the mass-weighted particle position, not x_g, near a free
// surface and once the particles leave their lattice, so l_p != W there
// (a property of USL-FLIP MPM, Vaango's too; docs/mpm-stability.md).
//
// Oracles ("round-off times the rotation"):
//  * exact-rotation update (taylor_series, 6 terms: per-step error
//    (omega dt)^7 / 7! ~ 2e-18 < eps): F stays a rotation up to the rounding
//    of n = theta/(omega dt) steps, |F^T F - I| <= 10 n eps, and the stress
//    of a hyperelastic model (sigma(F) = 0 for F orthogonal) stays below
//    10 n eps (K + 4G/3).
//  * first_order: (I + dt W)^T (I + dt W) = (1 + (omega dt)^2) I_inplane, so
//    after n steps (F^T F)_xx = (1 + (omega dt)^2)^n exactly (an in-plane
//    stretch theta omega dt / 2, O(dt)); the spurious stress is O(dt): halving
//    dt halves it (observed order 1 within 0.05).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/deck/DeckLoader.h"
#include "mpm/DeformationGradient.h"
#include "mpm/MpmComponent.h"
#include "mpm/MpmFlags.h"
#include "mpm/Transfers.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

constexpr double kOmega = 0.05;  // [rad/s]

struct Spin {
  double max_stress = 0;   // max_p max_ij |sigma_ij| at the quarter turn [Pa]
  double max_orth = 0;     // max_p |F^T F - I|
  double max_cxx_error = 0;  // max_p |(F^T F)_xx - (1 + (omega dt)^2)^n|
  int steps = 0;
  double modulus = 0;      // K + 4G/3
};

Spin spin(DeformationGradientAlgorithm alg, int terms, int steps) {
  auto deck = load_deck(test::source_dir() + "/inputs/mpm/rotating_disk.ups");
  const MpmFlags flags = parse_mpm_flags(deck->root.child("MPM"));
  auto comp = make_mpm_component(*deck);
  comp->initialize();
  MpmMaterial& m = comp->materials()[0];
  Particles& p = m.particles;
  NodeGrid& g = m.grid;
  const Vec3 centre(0.5, 0.5, 0.0);
  const double dt = (M_PI / 2) / kOmega / steps;
  const Mat3 W = (Mat3() << 0, -kOmega, 0, kOmega, 0, 0, 0, 0, 0).finished();
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) g.velocity_star[g.index(i, j, k)] = W * (g.position(i, j, k) - centre);
  Stencils s;
  std::vector<Mat3> L(p.size());
  std::vector<double> plastic(p.size()), heating(p.size());
  for (int n = 0; n < steps; ++n) {
    // The particles ride the exact rotation (positions are not under test).
    EXPECT_LT(compute_stencils(p, g, flags.interpolator, s), 0);
    velocity_gradients(s, g, L);
    const std::vector<Mat3> F_old = p.F;
    update_deformation_gradients(alg, terms, dt, L, p.F);
    SolidUpdateInput in;
    in.dt = dt;
    in.density0 = m.density;
    in.F_old = F_old;
    in.F_new = p.F;
    in.L = L;
    in.temperature = p.temperature;
    in.stress_old = p.stress;
    const SolidUpdateOutput out{p.stress, p.wave_speed, p.energy_density, plastic, heating, {}};
    EXPECT_EQ(m.model->update(in, out), -1);
    const Mat3 R = deformation_gradient_increment(DeformationGradientAlgorithm::TaylorSeries, dt * W, 12);
    for (Vec3& x : p.x) x = centre + R * (x - centre);
  }
  Spin r;
  r.steps = steps;
  r.modulus = m.model->bulk_modulus() + 4.0 * m.model->shear_modulus() / 3.0;
  const double cxx = std::pow(1.0 + std::pow(kOmega * dt, 2), steps);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Mat3 C = p.F[i].transpose() * p.F[i];
    r.max_stress = std::max(r.max_stress, p.stress[i].cwiseAbs().maxCoeff());
    r.max_orth = std::max(r.max_orth, (C - Mat3::Identity()).norm());
    r.max_cxx_error = std::max(r.max_cxx_error, std::abs(C(0, 0) - cxx));
  }
  return r;
}

TEST(MpmRotatingDisk, ExactRotationUpdateLeavesOnlyRoundOff) {
  const double eps = std::numeric_limits<double>::epsilon();
  for (int steps : {157, 314}) {  // omega dt = 0.01, 0.005
    const Spin t = spin(DeformationGradientAlgorithm::TaylorSeries, 6, steps);
    std::printf("rotating disk, taylor_series(6), %d steps: |F^T F - I| = %.2e, max|sigma| = %.2e Pa "
                "(bound 10 n eps (K+4G/3) = %.2e)\n",
                steps, t.max_orth, t.max_stress, 10 * steps * eps * t.modulus);
    EXPECT_LT(t.max_orth, 10 * steps * eps);
    EXPECT_LT(t.max_stress, 10 * steps * eps * t.modulus);
    const Spin c = spin(DeformationGradientAlgorithm::CayleyHamilton, 6, steps);
    EXPECT_LT(c.max_stress, 10 * steps * eps * c.modulus);
  }
}

TEST(MpmRotatingDisk, FirstOrderUpdateStretchesAtFirstOrderInDt) {
  const Spin a = spin(DeformationGradientAlgorithm::FirstOrder, 1, 157);
  const Spin b = spin(DeformationGradientAlgorithm::FirstOrder, 1, 314);
  const double order = std::log2(a.max_stress / b.max_stress);
  std::printf("rotating disk, first_order: max|sigma| = %.4e Pa (157 steps), %.4e Pa (314 steps), order %.3f; "
              "(F^T F)_xx - (1 + (w dt)^2)^n: %.1e, %.1e\n",
              a.max_stress, b.max_stress, order, a.max_cxx_error, b.max_cxx_error);
  EXPECT_LT(a.max_cxx_error, 1e-13);
  EXPECT_LT(b.max_cxx_error, 1e-13);
  EXPECT_NEAR(order, 1.0, 0.05);
}

}  // namespace
}  // namespace tephra
