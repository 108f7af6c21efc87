// Simple_Burn point functions (mpmice/SimpleBurn.h) against closed forms.
// Not yet wired into the coupled step (docs/mpmice.md).
#include <gtest/gtest.h>

#include <cmath>

#include "mpmice/SimpleBurn.h"

namespace tephra {
namespace {

// A solid filling the low-x half of the cell's corners: corners with x bit 0
// hold m, those with x bit 1 hold 0. Normal +x (out of the solid), surface
// area = the x face dy dz, (max - min)/max = 1: not a surface cell (the
// criterion is < 1); with 0.3 m on the high side, (1 - 0.3) = 0.7: surface.
TEST(SimpleBurn, PlaneSurfaceNormalToX) {
  const Vec3 dx(0.5, 0.25, 0.2);
  double wm[8];
  for (int n = 0; n < 8; ++n) wm[n] = (n & 1) ? 0.3 : 1.0;
  EXPECT_TRUE(simple_burn_surface_cell(wm, 1e-100));
  const Vec3 nrm = simple_burn_surface_normal(wm, dx);
  EXPECT_NEAR(nrm[0], 1.0, 1e-15);
  EXPECT_NEAR(nrm[1], 0.0, 1e-15);  // round-off of the corner sums
  EXPECT_NEAR(nrm[2], 0.0, 1e-15);
  EXPECT_NEAR(simple_burn_surface_area(nrm, dx), 0.25 * 0.2, 1e-15);
  for (int n = 0; n < 8; ++n) wm[n] = (n & 1) ? 0.0 : 1.0;
  EXPECT_FALSE(simple_burn_surface_cell(wm, 1e-100));  // (max - min)/max = 1
  for (int n = 0; n < 8; ++n) wm[n] = 1.0;
  EXPECT_FALSE(simple_burn_surface_cell(wm, 1e-100));  // uniform: inside
  EXPECT_EQ(simple_burn_surface_area(simple_burn_surface_normal(wm, dx), dx), 0.0);
}

// Diagonal surface on a cube cell h: n = (1,1,1)/sqrt(3), A = h^3/(h sqrt 3)
// x (sqrt 3)^(1/3) = h^2 3^(-1/2 + 1/6) = h^2 3^(-1/3).
TEST(SimpleBurn, DiagonalSurfaceArea) {
  const double h = 0.5;
  const Vec3 n = Vec3(1, 1, 1) / std::sqrt(3.0);
  EXPECT_NEAR(simple_burn_surface_area(n, Vec3(h, h, h)), h * h * std::pow(3.0, -1.0 / 3.0), 1e-15);
  // The normal from corner values decreasing along x + y + z.
  double wm[8];
  for (int n8 = 0; n8 < 8; ++n8) wm[n8] = 3.0 - ((n8 & 1) + ((n8 >> 1) & 1) + ((n8 >> 2) & 1));
  const Vec3 g = simple_burn_surface_normal(wm, Vec3(h, h, h));
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(g[d], 1 / std::sqrt(3.0), 1e-15);
}

// dm = dt A BurnCoeff (p/p_ref)^0.778 above both thresholds (massX.ups:
// ThresholdTemp 299 K, ThresholdPressure 500 Pa, BurnCoeff 1, refPressure 1),
// zero at or below either, capped at the solid mass.
TEST(SimpleBurn, RateLaw) {
  SimpleBurnParams p;
  p.threshold_temperature = 299;
  p.threshold_pressure = 500;
  p.burn_coeff = 1;
  p.ref_pressure = 1;
  const double dt = 1e-4, A = 0.25;
  const double expect = dt * A * std::pow(101325.0, 0.778);  // 1.949e-1 kg
  EXPECT_NEAR(simple_burn_mass(p, dt, A, 101325.0, 300.0, 10.0), expect, 1e-14 * expect);
  EXPECT_EQ(simple_burn_mass(p, dt, A, 101325.0, 299.0, 10.0), 0.0);
  EXPECT_EQ(simple_burn_mass(p, dt, A, 500.0, 300.0, 10.0), 0.0);
  EXPECT_EQ(simple_burn_mass(p, dt, A, 101325.0, 300.0, 0.1), 0.1);
}

}  // namespace
}  // namespace tephra
