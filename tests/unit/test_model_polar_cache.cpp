// The polar cache of hypo_elastic (models/solid/PolarCache.h): update() with
// the cache columns gives the bits of the point function without them
// (hypo_elastic_point decomposes F_n and F_{n+1} afresh) over several steps,
// also when the driver changed F between steps (a stale cache entry: F
// replaced by Q F, one coefficient moved by one ulp, +0 turned into -0).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Geometry>

#include "models/solid/HypoElastic.h"
#include "models/solid/PolarCache.h"

namespace tephra {
namespace {

TEST(PolarCache, UpdateWithTheCacheHasTheBitsOfFreshDecompositionsOverStepsAndStaleEntries) {
  const HypoElasticParams par{375939.8496240601, 980392.1568627450, 0.0};
  const HypoElastic model(par);
  const std::vector<HistoryVariable> hist = model.history();
  ASSERT_EQ(hist.size(), 2u);
  const int n = 5000;  // > 4096: the threaded point loop
  std::vector<std::vector<double>> columns;
  for (const HistoryVariable& h : hist) {
    std::vector<double> c;
    for (int i = 0; i < n; ++i) c.insert(c.end(), h.initial.begin(), h.initial.end());
    columns.push_back(std::move(c));
  }
  std::vector<std::span<double>> history(columns.begin(), columns.end());
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Matrix3d> F(n, Eigen::Matrix3d::Identity()), F_new(n), L(n), stress(n, Eigen::Matrix3d::Zero());
  std::vector<double> T(n, 300.0), c(n), W(n), pw(n), heat(n);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  int hits_possible = 0;
  for (int step = 0; step < 6; ++step) {
    // The driver changes F of some points between updates (stale entries).
    if (step == 3)
      for (int i = 0; i < n; i += 7) {
        if (i % 3 == 0) F[i] = (Q * F[i]).eval();
        else if (i % 3 == 1) F[i](1, 2) = std::nextafter(F[i](1, 2), 2.0);
        else F[i](0, 1) = F[i](0, 1) == 0.0 ? -0.0 : F[i](0, 1);
      }
    if (step == 4)  // exact zeros with both signs in F_n: +0 in the cache key, -0 in F
      for (int i = 1; i < n; i += 11) F[i](2, 0) = 0.0;
    for (int i = 0; i < n; ++i) {
      const double size = std::pow(10.0, -6.0 + 4.0 * (i % 5) / 4.0);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) L[i](a, b) = size * u(rng);
      if (step == 4 && i % 11 == 1) L[i].row(2).setZero();  // keeps F_{n+1}(2,0) = +-0
      F_new[i] = (Eigen::Matrix3d::Identity() + L[i]) * F[i];
    }
    if (step == 5)
      for (int i = 1; i < n; i += 11) F[i](2, 0) = -0.0;  // F_n's -0 against the cached +0 of step 4
    std::vector<Eigen::Matrix3d> stress_old = stress;
    for (int i = 0; i < n; ++i) hits_possible += PolarCache::same_bits(columns[0].data() + 9 * i, F[i].data());
    SolidUpdateInput in;
    in.dt = 1e-5;
    in.density0 = 8000.0;
    in.F_old = F;
    in.F_new = F_new;
    in.L = L;
    in.temperature = T;
    in.stress_old = stress_old;
    const SolidUpdateOutput out{stress, c, W, pw, heat, history};
    ASSERT_EQ(model.update(in, out), -1);
    for (int i = 0; i < n; ++i) {
      const SolidPointResult ref = hypo_elastic_point(F[i], F_new[i], stress_old[i], 8000.0, par);
      ASSERT_EQ(stress[i], ref.stress) << "step " << step << " point " << i;
      ASSERT_EQ(c[i], ref.wave_speed) << i;
      ASSERT_EQ(W[i], ref.energy_density) << i;
      // The cache now holds F_{n+1} and its Newton R.
      ASSERT_TRUE(PolarCache::same_bits(columns[0].data() + 9 * i, F_new[i].data())) << i;
    }
    F = F_new;
  }
  // Every point of every step but the stale ones read its R_n from the cache.
  EXPECT_GT(hits_possible, 6 * n - 2 * n);
}

TEST(PolarCache, SameBitsTellsMinusZeroFromPlusZero) {
  double a[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, b[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_TRUE(PolarCache::same_bits(a, b));
  b[3] = -0.0;
  EXPECT_FALSE(PolarCache::same_bits(a, b));
  b[3] = 0.0;
  b[8] = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(PolarCache::same_bits(a, b));
}

}  // namespace
}  // namespace tephra
