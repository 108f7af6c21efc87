// particle_stable_timestep (mpm/StableTimestep.h) evaluates Vaango's CFL rule
//   dt = min_{p,d} h_d / (c_p + |v_p,d|)
// as min_d fl(h_d / max_p (c_p + |v_p,d|)). Identity checked here: the result
// has the bits of the quotient-by-quotient minimum (the loop of the
// definition, particle_stable_timestep_by_quotients) because correctly
// rounded division is monotone in the divisor. Random speeds over many
// binades (so that neighbouring divisors round to the same quotient), unequal
// h_d, NaN / zero / infinite / negative wave speeds, no particles; 1, 2 and
// 3 threads (the max reduction is order independent).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/grid/Loop.h"
#include "mpm/StableTimestep.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

Particles random_particles(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), e(-3.0, 3.0), s(-1.0, 1.0);
  Particles p;
  for (int i = 0; i < n; ++i) {
    p.add(Vec3::Zero(), Vec3(s(rng), s(rng), s(rng)) * std::pow(10.0, e(rng)), 1.0, 1.0, 300.0, 0.0, i);
    p.wave_speed.back() = std::pow(10.0, e(rng));
  }
  return p;
}

void expect_bits_of_quotients(const Particles& p, const Vec3& h) {
  const double ref = particle_stable_timestep_by_quotients(p, h);
  for (int threads : {1, 2, 3}) {
    ThreadCountScope t(threads);
    const double dt = particle_stable_timestep(p, h);
    // EXPECT_EQ on doubles is exact; the inf cases compare equal as well.
    EXPECT_EQ(dt, ref) << "threads " << threads;
    EXPECT_EQ(std::signbit(dt), std::signbit(ref));
  }
}

TEST(MpmStableTimestep, IsTheMinimumOfTheQuotientsBitForBit) {
  const Vec3 h(1.25e-3, 1.2500000000000002e-3, 0.7e-3);  // unequal h_d, two one ulp apart
  for (unsigned seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    Particles p = random_particles(seed % 2 ? 9000 : 50, seed);  // threaded and serial
    expect_bits_of_quotients(p, h);
    // The minimising particle's divisor nudged by one ulp either way: the
    // comparison is at the rounding of the quotient.
    std::size_t arg = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (h[0] / (p.wave_speed[i] + std::abs(p.v[i][0])) < best)
        best = h[0] / (p.wave_speed[i] + std::abs(p.v[i][0])), arg = i;
    for (double dir : {1.0, -1.0}) {
      Particles q = p;
      q.wave_speed[arg] = std::nextafter(q.wave_speed[arg], dir * 1e300);
      expect_bits_of_quotients(q, h);
    }
  }
}

TEST(MpmStableTimestep, SpecialSpeeds) {
  const Vec3 h(0.1, 0.2, 0.3);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(particle_stable_timestep(Particles{}, h), inf);  // no particles
  Particles p = random_particles(5000, 99);
  // NaN wave speeds are skipped by the definition's std::min: the same here.
  for (std::size_t i = 0; i < p.size(); i += 7) p.wave_speed[i] = nan;
  expect_bits_of_quotients(p, h);
  ASSERT_TRUE(std::isfinite(particle_stable_timestep_by_quotients(p, h)));
  // All NaN: +inf in both.
  Particles all_nan = p;
  for (double& c : all_nan.wave_speed) c = nan;
  expect_bits_of_quotients(all_nan, h);
  EXPECT_EQ(particle_stable_timestep(all_nan, h), inf);
  // At rest with c = 0: h / +0 = +inf in both.
  Particles rest = p;
  for (double& c : rest.wave_speed) c = 0.0;
  for (Vec3& v : rest.v) v.setZero();
  expect_bits_of_quotients(rest, h);
  EXPECT_EQ(particle_stable_timestep(rest, h), inf);
  // An infinite speed: dt = +0 in both.
  Particles fast = p;
  fast.wave_speed[3] = inf;
  expect_bits_of_quotients(fast, h);
  EXPECT_EQ(particle_stable_timestep(fast, h), 0.0);
  // A negative wave speed (no model gives one): the definition's negative quotient.
  Particles neg = p;
  neg.wave_speed[10] = -1e6;
  expect_bits_of_quotients(neg, h);
  EXPECT_LT(particle_stable_timestep(neg, h), 0.0);
}

}  // namespace
}  // namespace tephra
