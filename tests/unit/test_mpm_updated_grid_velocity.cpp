// The velocity gradient's grid velocity at under-filled nodes (mpm/UpdatedGridVelocity.h).
//
// 1. v_g^{n+1} = sum_p m_p S_gp (v_p + dt sum_h a_h S_hp) / m_g, by hand for two
//    particles on two nodes, and the periodic alias sum.
// 2. The fill limit 2 C^2 / (4 + C^2) is where the one-node USL amplification matrix
//      [v; s]' = [[1, -r x], [x, 1 - x^2]] [v; s],   r = phi, x^2 = C^2 / phi
//    (lumped mass m phi, stiffness giving omega^2 = c^2 / (h^2 phi), the next P2G
//    carrying the fraction r = sum m S^2 / sum m S = phi of the acceleration) reaches
//    spectral radius 1: below it USL grows, above it does not; the MUSL matrix
//    [[1, -r x], [x, 1 - r x^2]] has det 1 and stays bounded for C <= 2 at any phi.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "mpm/UpdatedGridVelocity.h"

namespace tephra {
namespace {

double spectral_radius(double a, double b, double c, double d) {
  const double tr = a + d, det = a * d - b * c;
  const std::complex<double> root = std::sqrt(std::complex<double>(tr * tr - 4.0 * det));
  return std::max(std::abs(0.5 * (tr + root)), std::abs(0.5 * (tr - root)));
}

double usl_radius(double phi, double courant) {
  const double x = courant / std::sqrt(phi);
  return spectral_radius(1.0, -phi * x, x, 1.0 - x * x);
}

double musl_radius(double phi, double courant) {
  const double x = courant / std::sqrt(phi);
  return spectral_radius(1.0, -phi * x, x, 1.0 - phi * x * x);
}

TEST(MpmUpdatedGridVelocity, IsTheP2GOfTheFlipUpdatedVelocities) {
  NodeGrid g;
  g.n = IntVec3(2, 1, 1);
  g.reset();
  g.mass = {0.25 * 2.0 + 0.5 * 1.0, 0.75 * 2.0 + 0.5 * 1.0};  // sum m S
  g.acceleration = {Vec3(10, 0, 0), Vec3(0, 20, 0)};
  Particles p;
  p.add(Vec3::Zero(), Vec3(1, 0, 0), 2.0, 1.0, 300, 0, 1);
  p.add(Vec3::Zero(), Vec3(0, 0, 3), 1.0, 1.0, 300, 0, 2);
  Stencils s;
  s.width = 2;
  s.node = {0, 1, 0, 1};
  s.w = {0.25, 0.75, 0.5, 0.5};
  s.grad.assign(4, Vec3::Zero());
  const double dt = 0.1;
  // v_1^{n+1} = (1,0,0) + 0.1 (0.25 (10,0,0) + 0.75 (0,20,0)) = (1.25, 1.5, 0)
  // v_2^{n+1} = (0,0,3) + 0.1 (0.5 (10,0,0) + 0.5 (0,20,0)) = (0.5, 1, 3)
  const Vec3 v1(1.25, 1.5, 0), v2(0.5, 1, 3);
  std::vector<Vec3> out;
  updated_particle_grid_velocity(p, s, g, dt, nullptr, out);
  EXPECT_LE((out[0] - (0.25 * 2 * v1 + 0.5 * 1 * v2) / g.mass[0]).norm(), 1e-15);
  EXPECT_LE((out[1] - (0.75 * 2 * v1 + 0.5 * 1 * v2) / g.mass[1]).norm(), 1e-15);
  // Periodic: both nodes one alias set; its mass is the folded sum, as after P2G.
  const std::vector<std::size_t> canonical = {0, 0};
  const double m = g.mass[0] + g.mass[1];
  g.mass = {m, m};
  updated_particle_grid_velocity(p, s, g, dt, &canonical, out);
  EXPECT_LE((out[0] - (2 * v1 + v2) / 3.0).norm(), 1e-15);
  EXPECT_EQ(out[0], out[1]);
}

TEST(MpmUpdatedGridVelocity, FillLimitIsTheUslStabilityBoundOfTheNode) {
  for (double C : {0.3, 0.6, 0.763, 1.0}) {
    const double phi = usl_fill_limit(C);
    EXPECT_NEAR(usl_radius(phi, C), 1.0, 1e-12) << "C = " << C;
    EXPECT_GT(usl_radius(0.9 * phi, C), 1.0 + 1e-3) << "C = " << C;
    EXPECT_LE(usl_radius(1.1 * phi, C), 1.0 + 1e-12) << "C = " << C;
    for (double f : {1e-4, 0.01, 1.0 / 18, 1.0 / 6, 1.0}) EXPECT_LE(musl_radius(f, C), 1.0 + 1e-12);
  }
  // Deck A5 (docs/mpm-stability.md): the outer particle layer at S = 1/6 bounds USL at
  // C = sqrt(4 S / (2 - S)) = sqrt(4/11) = 0.603; at the deck's C = 0.763 the USL
  // amplification is 2.3 per step.
  EXPECT_NEAR(usl_fill_limit(std::sqrt(4.0 / 11.0)), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(usl_radius(1.0 / 6.0, 0.763), 2.3, 0.05);
}

TEST(MpmUpdatedGridVelocity, WellFilledNodesKeepVStar) {
  NodeGrid g;
  g.n = IntVec3(3, 1, 1);
  g.reset();
  g.volume = {1.0, 0.2, 0.05};  // V_cell = 1
  const std::vector<Vec3> v_star = {Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0)};
  std::vector<Vec3> v(3, Vec3::Zero());
  keep_stable_usl_nodes(g, usl_fill_limit(0.763), 1.0, v_star, v);  // limit 0.254
  EXPECT_EQ(v[0], v_star[0]);
  EXPECT_EQ(v[1], Vec3::Zero());
  EXPECT_EQ(v[2], Vec3::Zero());
}

}  // namespace
}  // namespace tephra
