// P2G / G2P kernels (mpm/Transfers.h) on a hand-built node grid with random
// particles: the discrete conservation identities of explicit MPM.
//   sum_g m_g = sum_p m_p                      (partition of unity)
//   sum_g m_g v_g = sum_p m_p v_p              (partition of unity)
//   sum_g f_int,g = -sum_p V_p sigma_p sum_g grad S_gp = 0
//   sum_p m_p v_p^{n+1} = sum_p m_p v_p^n + dt sum_g (f_int,g + f_ext,g)
//     (G2P of a_g with weights S: sum_p m_p S_gp a_g = m_g a_g = f_g)
#include <gtest/gtest.h>

#include <random>

#include "mpm/Transfers.h"

namespace tephra {
namespace {

struct RandomCloud {
  NodeGrid g;
  Particles p;
  RandomCloud() {
    g.origin = Vec3(-1.0, 0.5, 0.0);
    g.h = Vec3(0.1, 0.2, 0.15);
    g.n = IntVec3(9, 7, 5);
    g.reset();
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < 400; ++i) {
      const Vec3 x = g.origin + Vec3(8 * g.h[0] * u(rng), 6 * g.h[1] * u(rng), 4 * g.h[2] * u(rng));
      p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3 * (0.5 + u(rng)), 300.0, 0.0, i);
      Mat3 sig;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sig(a, b) = 1e3 * s(rng);
      p.stress.back() = 0.5 * (sig + sig.transpose());
    }
  }
};

double total_mass(const Particles& p) {
  double m = 0;
  for (double x : p.mass) m += x;
  return m;
}
Vec3 total_momentum(const Particles& p) {
  Vec3 m = Vec3::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) m += p.mass[i] * p.v[i];
  return m;
}

TEST(MpmTransfers, P2GConservesMassAndMomentum) {
  RandomCloud s;
  Stencils st;
  ASSERT_EQ(compute_stencils(s.p, s.g, InterpolatorSpec{}, st), -1);
  particles_to_grid(s.p, st, Vec3::Zero(), s.g);
  double mg = 0;
  Vec3 pg = Vec3::Zero();
  for (std::size_t i = 0; i < s.g.count(); ++i) {
    mg += s.g.mass[i];
    pg += s.g.mass[i] * s.g.velocity[i];
  }
  const double mp = total_mass(s.p);
  const Vec3 pp = total_momentum(s.p);
  EXPECT_NEAR(mg, mp, 1e-14 * mp);
  // Round-off scale: sum m|v| over 400 particles.
  EXPECT_NEAR((pg - pp).norm(), 0.0, 1e-13 * mp);
}

TEST(MpmTransfers, InternalForceSumsToZero) {
  RandomCloud s;
  Stencils st;
  ASSERT_EQ(compute_stencils(s.p, s.g, InterpolatorSpec{}, st), -1);
  compute_internal_force(s.p, st, s.g);
  Vec3 f = Vec3::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < s.g.count(); ++i) {
    f += s.g.internal_force[i];
    scale += s.g.internal_force[i].norm();
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_NEAR(f.norm(), 0.0, 1e-14 * scale);
}

TEST(MpmTransfers, FullStepChangesMomentumByTheNetExternalForce) {
  // With gravity b, f_ext,g = sum m_p b S: the total momentum changes by dt b sum m_p.
  RandomCloud s;
  const Vec3 b(0.0, -9.81, 1.0);
  const double dt = 1e-4;
  const Vec3 p0 = total_momentum(s.p);
  const double mp = total_mass(s.p);
  Stencils st;
  ASSERT_EQ(compute_stencils(s.p, s.g, InterpolatorSpec{}, st), -1);
  particles_to_grid(s.p, st, b, s.g);
  compute_internal_force(s.p, st, s.g);
  integrate_grid_velocity(s.g, dt);
  acceleration_from_velocities(s.g, dt);
  grid_to_particles(st, s.g, dt, s.p);
  const Vec3 expected = p0 + dt * mp * b;
  // The internal forces are ~1e3 * V / h ~ 10 per node; a_g dt ~ 1e-2 per
  // particle; cancellation leaves round-off ~1e-15 of sum m |v| ~ 1e2.
  EXPECT_NEAR((total_momentum(s.p) - expected).norm(), 0.0, 1e-12 * mp);
  EXPECT_GT((total_momentum(s.p) - p0).norm(), 0.5 * dt * mp * b.norm());  // gravity did act
}

TEST(MpmTransfers, StencilRejectsParticlesOutsideTheGrid) {
  RandomCloud s;
  Stencils st;
  s.p.x[17] = s.g.origin + Vec3(-1e-9, 0.1, 0.1);
  EXPECT_EQ(compute_stencils(s.p, s.g, InterpolatorSpec{}, st), 17);
  s.p.x[17] = s.g.position(8, 3, 3);  // on the last node plane: its support would need node 9
  EXPECT_EQ(compute_stencils(s.p, s.g, InterpolatorSpec{}, st), 17);
  s.p.x[17] = Vec3(std::nan(""), 0.0, 0.0);
  EXPECT_EQ(compute_stencils(s.p, s.g, InterpolatorSpec{}, st), 17);
}

}  // namespace
}  // namespace tephra
