// Threaded MPM kernels (mpm/Transfers.cpp, mpm/shape/ComputeStencils.cpp,
// models/solid/PointLoop.h) against plain serial loops written here.
// Claims (Transfers.cpp, ScatterOrder.h, PointLoop.h):
//   * P2G and internal force (one thread) equal bit for bit the serial sums
//     taken over the particles stably sorted by the colour of their block,
//     colour = (floor(y0 / w) mod 2) + 2 (floor(z0 / w) mod 2), y0, z0 the
//     lowest node rows of the stencil, w = (footprint rows) - 1 (2 for gimp);
//   * with two and three threads the node sums are the SAME BITS as with one;
//   * without a scatter order (stencils filled by hand) the scatter is the
//     serial particle-order sum;
//   * stencils, velocity gradients, G2P and model updates write per particle,
//     so they are bit-for-bit the same for 1 and 2 threads.
// The cloud has 6000 particles, above the 4096 below which loops run serially.
#include <gtest/gtest.h>

#include <random>

#include "core/grid/Loop.h"
#include "models/solid/HypoElastic.h"
#include "mpm/Transfers.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

struct Cloud {
  NodeGrid g;
  Particles p;
  Cloud() {
    g.origin = Vec3(-1.0, 0.5, 0.0);
    g.h = Vec3(0.1, 0.2, 0.15);
    g.n = IntVec3(14, 12, 10);
    g.reset();
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < 6000; ++i) {
      // Inside the nodes 1 .. n-2 so every GIMP support (half-length 1/4 cell) stays on the grid.
      const Vec3 x = g.origin + Vec3((1 + 11 * u(rng)) * g.h[0], (1 + 9 * u(rng)) * g.h[1], (1 + 7 * u(rng)) * g.h[2]);
      p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3 * (0.5 + u(rng)), 300.0, 0.0, i,
            Mat3::Identity() * 0.5);
      Mat3 sig;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sig(a, b) = 1e3 * s(rng);
      p.stress.back() = 0.5 * (sig + sig.transpose());
      p.external_force.back() = Vec3(s(rng), s(rng), s(rng));
    }
  }
};

// Restores the thread count of the process after a test.
// The node arrays after stencils + P2G + internal force with `threads` threads.
NodeGrid project(Cloud c, int threads, Stencils& st) {
  ThreadCountScope t(threads);
  EXPECT_EQ(compute_stencils(c.p, c.g, {InterpolatorKind::Gimp, 1e10}, st), -1);
  particles_to_grid(c.p, st, Vec3(0.0, -9.81, 0.0), c.g);
  compute_internal_force(c.p, st, c.g);
  return c.g;
}

// Serial reference P2G over the particles in the given order.
NodeGrid serial_reference(const Cloud& c, const Stencils& st, const std::vector<std::size_t>& order) {
  NodeGrid g = c.g;
  const std::size_t W = st.width;
  for (std::size_t i : order)
    for (std::size_t k = i * W; k < (i + 1) * W; ++k) {
      const std::size_t n = st.node[k];
      g.mass[n] += c.p.mass[i] * st.w[k];
      g.volume[n] += c.p.volume[i] * st.w[k];
      g.velocity[n] += (c.p.mass[i] * c.p.v[i]) * st.w[k];
      g.external_force[n] += (c.p.external_force[i] + c.p.mass[i] * Vec3(0.0, -9.81, 0.0)) * st.w[k];
      g.stress[n] += (c.p.volume[i] * c.p.stress[i]) * st.w[k];
      g.internal_force[n] -= (c.p.volume[i] * c.p.stress[i]) * st.grad[k];
    }
  for (std::size_t n = 0; n < g.count(); ++n) {
    if (g.mass[n] > 0.0) g.velocity[n] /= g.mass[n];
    if (g.volume[n] > 0.0) g.stress[n] /= g.volume[n];
  }
  return g;
}

// The particles stably sorted by the colour of their block (ScatterOrder.h),
// computed here from the definition: the GIMP footprint is 3 node rows, w = 2.
std::vector<std::size_t> colour_order(const Cloud& c, const Stencils& st) {
  const std::size_t W = st.width, nx = c.g.n[0], ny = c.g.n[1];
  std::vector<std::size_t> order;
  for (int colour = 0; colour < 4; ++colour)
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      std::size_t y0 = ny, z0 = std::size_t(c.g.n[2]);
      for (std::size_t k = i * W; k < (i + 1) * W; ++k) {
        y0 = std::min(y0, (st.node[k] / nx) % ny);
        z0 = std::min(z0, st.node[k] / (nx * ny));
      }
      if (int((y0 / 2) % 2 + 2 * ((z0 / 2) % 2)) == colour) order.push_back(i);
    }
  return order;
}

TEST(MpmThreads, OneThreadScatterIsTheSerialSumInColourOrderBitForBit) {
  Cloud c;
  Stencils st;
  const NodeGrid g1 = project(c, 1, st);
  ASSERT_TRUE(st.order.built_for(c.p.size()));
  EXPECT_EQ(st.order.width_y, 2);
  EXPECT_EQ(st.order.width_z, 2);
  const std::vector<std::size_t> order = colour_order(c, st);
  ASSERT_EQ(order.size(), c.p.size());
  const NodeGrid ref = serial_reference(c, st, order);
  EXPECT_EQ(g1.mass, ref.mass);
  EXPECT_EQ(g1.volume, ref.volume);
  EXPECT_EQ(g1.velocity, ref.velocity);
  EXPECT_EQ(g1.external_force, ref.external_force);
  EXPECT_EQ(g1.stress, ref.stress);
  EXPECT_EQ(g1.internal_force, ref.internal_force);
  // The particle order differs from the colour order, so that the test can fail.
  std::vector<std::size_t> natural(c.p.size());
  for (std::size_t i = 0; i < natural.size(); ++i) natural[i] = i;
  EXPECT_NE(order, natural);
}

TEST(MpmThreads, ScatterIsTheSameBitsForAnyThreadCount) {
  Cloud c;
  Stencils s1, s2, s3;
  const NodeGrid g1 = project(c, 1, s1);
  const NodeGrid g2 = project(c, 2, s2);
  const NodeGrid g3 = project(c, 3, s3);
  // Stencils are per particle: identical for any thread count.
  EXPECT_EQ(s1.node, s2.node);
  EXPECT_EQ(s1.w, s2.w);
  EXPECT_EQ(s1.grad, s2.grad);
  EXPECT_EQ(s1.order.index, s2.order.index);
  for (const NodeGrid* g : {&g2, &g3}) {
    EXPECT_EQ(g1.mass, g->mass);
    EXPECT_EQ(g1.volume, g->volume);
    EXPECT_EQ(g1.velocity, g->velocity);
    EXPECT_EQ(g1.external_force, g->external_force);
    EXPECT_EQ(g1.stress, g->stress);
    EXPECT_EQ(g1.internal_force, g->internal_force);
  }
}

TEST(MpmThreads, WithoutAnOrderTheScatterIsTheParticleOrderSum) {
  Cloud c;
  Stencils st;
  project(c, 1, st);
  st.order = ScatterOrder{};  // as stencils filled by hand
  std::vector<std::size_t> natural(c.p.size());
  for (std::size_t i = 0; i < natural.size(); ++i) natural[i] = i;
  const NodeGrid ref = serial_reference(c, st, natural);
  ThreadCountScope t(2);
  NodeGrid g = c.g;
  particles_to_grid(c.p, st, Vec3(0.0, -9.81, 0.0), g);
  compute_internal_force(c.p, st, g);
  EXPECT_EQ(g.mass, ref.mass);
  EXPECT_EQ(g.velocity, ref.velocity);
  EXPECT_EQ(g.stress, ref.stress);
  EXPECT_EQ(g.internal_force, ref.internal_force);
}

TEST(MpmThreads, GathersAndModelUpdateDoNotDependOnThreadCount) {
  Cloud c;
  Stencils st;
  NodeGrid g = project(c, 1, st);
  integrate_grid_velocity(g, 1e-4);
  std::vector<Mat3> L1, L2;
  Particles p1 = c.p, p2 = c.p;
  {
    ThreadCountScope t(1);
    velocity_gradients(st, g, L1);
    grid_to_particles(st, g, 1e-4, p1);
  }
  {
    ThreadCountScope t(2);
    velocity_gradients(st, g, L2);
    grid_to_particles(st, g, 1e-4, p2);
  }
  EXPECT_EQ(L1, L2);
  EXPECT_EQ(p1.x, p2.x);
  EXPECT_EQ(p1.v, p2.v);
  // Serial reference of l_p = sum_g v*_g (grad S_gp)^T for one particle.
  Mat3 l = Mat3::Zero();
  for (int k = 0; k < st.width; ++k) l += g.velocity_star[st.node[k]] * st.grad[k].transpose();
  EXPECT_EQ(L1[0], l);

  // Model point loop: F_{n+1} = (I + dt L) F_n, hypo-elastic update with 1 and 2 threads.
  HypoElastic model(HypoElasticParams{3.0e5, 1.0e6});
  std::vector<Mat3> F_old(c.p.size(), Mat3::Identity()), F_new(c.p.size());
  for (std::size_t i = 0; i < F_new.size(); ++i) F_new[i] = Mat3::Identity() + 1e-2 * L1[i] / (L1[i].norm() + 1.0);
  std::vector<double> T(c.p.size(), 300.0);
  auto run = [&](int threads, std::vector<Mat3>& sig, std::vector<double>& cw) {
    ThreadCountScope t(threads);
    std::vector<double> W(c.p.size()), pw(c.p.size()), heat(c.p.size());
    sig = c.p.stress;
    cw.assign(c.p.size(), 0.0);
    SolidUpdateInput in;
    in.dt = 1e-4;
    in.density0 = 1000.0;
    in.F_old = F_old;
    in.F_new = F_new;
    in.L = L1;
    in.temperature = T;
    in.stress_old = c.p.stress;
    const SolidUpdateOutput out{sig, cw, W, pw, heat, {}};
    return model.update(in, out);
  };
  std::vector<Mat3> sig1, sig2;
  std::vector<double> c1, c2;
  EXPECT_EQ(run(1, sig1, c1), -1);
  EXPECT_EQ(run(2, sig2, c2), -1);
  EXPECT_EQ(sig1, sig2);
  EXPECT_EQ(c1, c2);
  // The lowest inadmissible index is reported, as by a serial loop.
  F_new[5000] = -Mat3::Identity();
  F_new[2000] = -Mat3::Identity();  // one in each half (each thread's range)
  EXPECT_EQ(run(2, sig2, c2), 2000);
  EXPECT_EQ(run(1, sig1, c1), 2000);
}

}  // namespace
}  // namespace tephra
