// The per-axis stencil form (mpm/shape/Interpolator.h, AxisStencils.h)
// against the flat form of compute_stencils, for linear, gimp and 3rdorderBS.
// Claims:
//   * the entries are the same nodes in the same order, the weights the same
//     bits (S_x S_y S_z, the product of tensor_product), the gradients equal to
//     round-off (1/h applied per axis: |d| <= 1e-15 |grad|_max);
//   * so P2G (weights only) and G2P give the same bits with either form, and
//     the internal force and velocity gradients agree to round-off;
//   * a particle whose support leaves the grid makes compute_axis_stencils
//     return false (the caller falls back to the flat form).
#include <gtest/gtest.h>

#include <random>

#include "mpm/Transfers.h"
#include "mpm/shape/AxisStencils.h"

namespace tephra {
namespace {

struct Cloud {
  NodeGrid g;
  Particles p;
  explicit Cloud(int count = 500) {
    g.origin = Vec3(-1.0, 0.5, 0.0);
    g.h = Vec3(0.1, 0.2, 0.15);
    g.n = IntVec3(14, 12, 10);
    g.reset();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < count; ++i) {
      const Vec3 x = g.origin + Vec3((1 + 11 * u(rng)) * g.h[0], (1 + 9 * u(rng)) * g.h[1], (1 + 7 * u(rng)) * g.h[2]);
      p.add(x, Vec3(s(rng), s(rng), s(rng)), 0.5 + u(rng), 1e-3 * (0.5 + u(rng)), 300.0, 0.0, i,
            Mat3::Identity() * 0.5);
      Mat3 sig;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sig(a, b) = 1e3 * s(rng);
      p.stress.back() = 0.5 * (sig + sig.transpose());
      p.external_force.back() = Vec3(s(rng), s(rng), s(rng));
    }
    for (std::size_t n = 0; n < g.count(); ++n) {
      g.velocity_star[n] = Vec3(s(rng), s(rng), s(rng));
      g.acceleration[n] = Vec3(s(rng), s(rng), s(rng));
    }
  }
};

class AxisStencils : public ::testing::TestWithParam<InterpolatorKind> {};

TEST_P(AxisStencils, SameEntriesAsTheFlatForm) {
  const Cloud c;
  const InterpolatorSpec spec{GetParam(), 1e10};
  Stencils flat, axis;
  ASSERT_EQ(compute_stencils(c.p, c.g, spec, flat), -1);
  ASSERT_TRUE(compute_axis_stencils(c.p, c.g, spec, axis));
  ASSERT_EQ(axis.particles(), c.p.size());
  ASSERT_EQ(axis.width, flat.width);
  EXPECT_TRUE(axis.node.empty() && axis.w.empty() && axis.grad.empty());
  visit_stencils(axis, [&](const auto& view) {
    for (std::size_t i = 0; i < c.p.size(); ++i) {
      std::size_t k = i * std::size_t(flat.width);
      view.entries(i, [&](std::size_t node, double w, const Vec3& grad) {
        EXPECT_EQ(node, flat.node[k]);
        EXPECT_EQ(w, flat.w[k]);  // bit for bit
        EXPECT_LE((grad - flat.grad[k]).norm(), 1e-15 * (1.0 + flat.grad[k].norm()));
        ++k;
      });
      EXPECT_EQ(k, (i + 1) * std::size_t(flat.width));
    }
  });
}

TEST_P(AxisStencils, TransfersAgreeWithTheFlatForm) {
  const Cloud c;
  const InterpolatorSpec spec{GetParam(), 1e10};
  Stencils flat, axis;
  ASSERT_EQ(compute_stencils(c.p, c.g, spec, flat), -1);
  ASSERT_TRUE(compute_axis_stencils(c.p, c.g, spec, axis));
  NodeGrid a = c.g, b = c.g;
  a.reset();
  b.reset();
  particles_to_grid(c.p, flat, Vec3(0, -9.81, 0), a);
  particles_to_grid(c.p, axis, Vec3(0, -9.81, 0), b);
  compute_internal_force(c.p, flat, a);
  compute_internal_force(c.p, axis, b);
  double fmax = 0.0;
  for (std::size_t n = 0; n < a.count(); ++n) fmax = std::max(fmax, a.internal_force[n].norm());
  ASSERT_GT(fmax, 0.0);
  for (std::size_t n = 0; n < a.count(); ++n) {
    EXPECT_EQ(a.mass[n], b.mass[n]);
    EXPECT_EQ(a.volume[n], b.volume[n]);
    EXPECT_EQ(a.velocity[n], b.velocity[n]);
    EXPECT_EQ(a.external_force[n], b.external_force[n]);
    EXPECT_EQ(a.stress[n], b.stress[n]);
    EXPECT_LE((a.internal_force[n] - b.internal_force[n]).norm(), 1e-14 * fmax);
  }
  std::vector<Mat3> La, Lb;
  velocity_gradients(flat, c.g, La);
  velocity_gradients(axis, c.g, Lb);
  for (std::size_t i = 0; i < c.p.size(); ++i)
    EXPECT_LE((La[i] - Lb[i]).norm(), 1e-14 * (1.0 + La[i].norm()));
  Particles pa = c.p, pb = c.p;
  grid_to_particles(flat, c.g, 1e-3, pa);
  grid_to_particles(axis, c.g, 1e-3, pb);
  EXPECT_EQ(pa.x, pb.x);
  EXPECT_EQ(pa.v, pb.v);
  EXPECT_EQ(pa.displacement, pb.displacement);
}

TEST_P(AxisStencils, SupportOutsideTheGridIsRefused) {
  Cloud c(10);
  // Node 0's cell: the GIMP / B-spline support reaches node -1, the linear one does not.
  c.p.x[3] = c.g.origin + Vec3(0.2 * c.g.h[0], 5 * c.g.h[1], 5 * c.g.h[2]);
  Stencils s;
  const InterpolatorSpec spec{GetParam(), 1e10};
  EXPECT_EQ(compute_axis_stencils(c.p, c.g, spec, s), GetParam() == InterpolatorKind::Linear);
  c.p.x[3][1] = c.g.origin[1] - 0.1;  // outside the grid for every interpolator
  EXPECT_FALSE(compute_axis_stencils(c.p, c.g, spec, s));
}

INSTANTIATE_TEST_SUITE_P(Kinds, AxisStencils,
                         ::testing::Values(InterpolatorKind::Linear, InterpolatorKind::Gimp,
                                           InterpolatorKind::QuadraticBspline));

TEST(AxisStencilsOther, GeneralInterpolatorsStayFlat) {
  const Cloud c(10);
  Stencils s;
  EXPECT_FALSE(compute_axis_stencils(c.p, c.g, {InterpolatorKind::Cpdi, 1e10}, s));
  EXPECT_FALSE(compute_axis_stencils(c.p, c.g, {InterpolatorKind::CubicBspline, 1e10}, s));
}

}  // namespace
}  // namespace tephra
