// Grid damping <artificial_damping_coeff> alpha (mpm/GridDamping.h, theory
// manual eq. 1.65 per unit node mass): a stress-free block translating with
// v_0 keeps a uniform velocity field, which P2G and G2P pass exactly, so the
// explicit step gives v_n = (1 - alpha dt)^n v_0 (to round-off) and, as
// dt -> 0, the exact decay v(t) = v_0 exp(-alpha t) at first order in dt
// (error ~ v_0 alpha^2 t dt / 2 e^{-alpha t}).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

MpmSetup damped_block(double alpha) {
  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3::Ones();
  s.grid.cells = IntVec3::Constant(8);
  s.grid.dx = Vec3::Constant(0.125);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  s.flags.artificial_damping_coeff = alpha;
  MpmMaterial m;
  m.density = 1000.0;
  m.specific_heat = 1.0;
  m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{833.3, 384.6});
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(Vec3::Constant(0.25), Vec3::Constant(0.5));
  src.res = IntVec3::Constant(2);
  src.velocity = Vec3(1.0, 0.5, -0.25);
  src.temperature = 300.0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  return s;
}

// |v(t_end) - v_0 exp(-alpha t_end)| / |v_0| of the worst particle after n equal steps,
// and the largest deviation from the discrete solution (1 - alpha dt)^n v_0.
std::pair<double, double> decay_error(int n) {
  const double alpha = 50.0, t_end = 0.02, dt = t_end / n;
  const Vec3 v0(1.0, 0.5, -0.25);
  MpmComponent c(damped_block(alpha));
  c.initialize();
  for (int k = 0; k < n; ++k) c.advance(k * dt, dt, k + 1);
  const Vec3 exact = v0 * std::exp(-alpha * t_end);
  const Vec3 discrete = v0 * std::pow(1.0 - alpha * dt, n);
  double err = 0, dev = 0;
  for (const Vec3& v : c.materials()[0].particles.v) {
    err = std::max(err, (v - exact).norm() / v0.norm());
    dev = std::max(dev, (v - discrete).norm() / v0.norm());
  }
  return {err, dev};
}

TEST(MpmDamping, FreeBlockVelocityDecaysExponentiallyAtFirstOrderInDt) {
  const int n[3] = {20, 40, 80};
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const auto [e, dev] = decay_error(n[k]);
    err[k] = e;
    EXPECT_LT(dev, 1e-13) << "n = " << n[k];  // the discrete solution (1 - alpha dt)^n v_0
  }
  const double o1 = std::log2(err[0] / err[1]), o2 = std::log2(err[1] / err[2]);
  std::printf("damping: error %.3e %.3e %.3e, observed order %.3f %.3f\n", err[0], err[1], err[2], o1, o2);
  EXPECT_NEAR(o1, 1.0, 0.1);
  EXPECT_NEAR(o2, 1.0, 0.05);
  // Leading error term alpha^2 t dt / 2 e^{-alpha t} = 50^2 0.02 (0.02/80) / 2 e^-1 = 2.3e-3.
  EXPECT_NEAR(err[2], 2500.0 * 0.02 * (0.02 / 80) / 2 * std::exp(-1.0), 1e-4);
}

TEST(MpmDamping, ZeroCoefficientLeavesTheFreeBlockUndamped) {
  MpmComponent c(damped_block(0.0));
  c.initialize();
  for (int k = 0; k < 10; ++k) c.advance(k * 1e-3, 1e-3, k + 1);
  for (const Vec3& v : c.materials()[0].particles.v) EXPECT_NEAR((v - Vec3(1.0, 0.5, -0.25)).norm(), 0.0, 1e-14);
}

}  // namespace
}  // namespace tephra
