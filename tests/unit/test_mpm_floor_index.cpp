// floor_index / floor_value (mpm/shape/FloorIndex.h) against std::floor, and
// the shape axes that use them against the std::floor forms they replace
// (ShapeLinear.h, ShapeGimp.h, ShapeBspline.h): the same bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "mpm/shape/FloorIndex.h"
#include "mpm/shape/ShapeBspline.h"
#include "mpm/shape/ShapeGimp.h"
#include "mpm/shape/ShapeLinear.h"

namespace tephra {
namespace {

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Negative and positive integers, -0 and +0, the doubles next to integers,
// halves, the ends of the int range, and random values over several decades.
std::vector<double> inputs() {
  std::vector<double> v{0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0, 87.0, -87.0, 1e-300, -1e-300,
                        std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                        2147483647.0, 2147483646.5, -2147483647.5, -2147483647.0, -2147483648.0};
  for (int i = -100; i <= 100; ++i) {
    const double x = i;
    v.push_back(std::nextafter(x, -1e9));
    v.push_back(std::nextafter(x, 1e9));
    v.push_back(x + 0.5);
  }
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 20000; ++k) v.push_back(u(rng) * std::pow(10.0, k % 9));  // |x| up to 1e8
  return v;
}

TEST(FloorIndex, EqualsStdFloorAtIntegersNegativesZerosAndRandomValues) {
  int negative_non_integers = 0;
  for (double x : inputs()) {
    const double f = std::floor(x);
    ASSERT_EQ(floor_index(x), static_cast<int>(f)) << "x = " << x;
    // Bit for bit, the sign of zero included (floor(-0) = -0).
    ASSERT_EQ(bits(floor_value(x, floor_index(x))), bits(f)) << "x = " << x;
    if (x < 0 && f != x) ++negative_non_integers;
  }
  EXPECT_GT(negative_non_integers, 5000);  // the corrected case is exercised
  EXPECT_EQ(bits(floor_value(-0.0, floor_index(-0.0))), bits(-0.0));
  EXPECT_EQ(floor_index(-0.25), -1);
  EXPECT_EQ(floor_index(-3.0), -3);
  EXPECT_EQ(floor_index(2.999999999999), 2);
}

// The axes as they were written before (std::floor), to compare bit for bit.
ShapeAxis linear_axis_std_floor(double xi) {
  ShapeAxis a;
  const double c = std::floor(xi);
  const double r = xi - c;
  a.first = static_cast<int>(c);
  a.count = 2;
  a.S[0] = 1.0 - r;
  a.S[1] = r;
  a.dS[0] = -1.0;
  a.dS[1] = 1.0;
  return a;
}

void expect_same_axis(const ShapeAxis& a, const ShapeAxis& b, double xi) {
  ASSERT_EQ(a.first, b.first) << "xi = " << xi;
  ASSERT_EQ(a.count, b.count) << "xi = " << xi;
  for (int k = 0; k < 4; ++k) {
    ASSERT_EQ(bits(a.S[k]), bits(b.S[k])) << "xi = " << xi << " k = " << k;
    ASSERT_EQ(bits(a.dS[k]), bits(b.dS[k])) << "xi = " << xi << " k = " << k;
  }
}

TEST(FloorIndex, ShapeAxesHaveTheBitsOfTheStdFloorForms) {
  std::vector<double> xs = inputs();
  std::vector<double> grid_range;
  for (double x : xs)
    if (std::abs(x) < 1e6) grid_range.push_back(x);
  for (double xi : grid_range) {
    expect_same_axis(linear_axis(xi), linear_axis_std_floor(xi), xi);
    // GIMP and the quadratic B-spline: the first node (int)floor(xi + 1/2) - 1;
    // the factors follow from the ints, so equal firsts give equal factors.
    const ShapeAxis g = gimp_axis(xi, 0.25), b = quadratic_bspline_axis(xi);
    ASSERT_EQ(g.first, static_cast<int>(std::floor(xi + 0.5)) - 1) << xi;
    ASSERT_EQ(b.first, static_cast<int>(std::floor(xi + 0.5)) - 1) << xi;
    // cpGIMP's support floor(xi - l) .. floor(xi + l) + 1 (up to four nodes).
    for (double l : {0.25, 0.5, 0.75, 1.0}) {
      const ShapeAxis c = gimp_axis_any(xi, l);
      const int first = static_cast<int>(std::floor(xi - l)), last = static_cast<int>(std::floor(xi + l)) + 1;
      ASSERT_EQ(c.first, first) << xi;
      ASSERT_EQ(c.count, std::min(4, last - first + 1)) << xi << " l = " << l;
    }
  }
  // The -0 case: floor(-0) = -0, so the std::floor form has S[1] = -0 - (-0) = +0.
  const ShapeAxis z = linear_axis(-0.0);
  EXPECT_EQ(bits(z.S[1]), bits(0.0));
  EXPECT_EQ(bits(z.S[0]), bits(1.0));
}

}  // namespace
}  // namespace tephra
