// ice/Diffusion.h: the face-flux divergence of the Newtonian viscous stress
// and of the conductive heat flux is exact for quadratic fields (second-order
// central stencils), so each case compares with the closed form of div tau or
// div(k grad T) of a quadratic field, including non-uniform volume fraction
// (the theta-weighted coefficients) where the closed form is still quadratic.
#include <gtest/gtest.h>

#include "ice/Diffusion.h"
#include "ice/IceFields.h"

using namespace tephra;

namespace {

Grid grid6() {
  Grid g;
  g.cells = IntVec3(6, 5, 4);
  g.extra_cells = IntVec3(1, 1, 1);
  g.dx = Vec3(0.1, 0.2, 0.3);
  g.lower = Vec3(0, 0, 0);
  Patch p;
  p.id = 0;
  p.lo = IntVec3(0, 0, 0);
  p.hi = g.cells;
  g.patches.push_back(p);
  g.set_patch_extra_cells();
  g.index_patches();
  return g;
}

Vec3 centre(const Grid& g, const IntVec3& c) {
  return g.lower + Vec3((c[0] + 0.5) * g.dx[0], (c[1] + 0.5) * g.dx[1], (c[2] + 0.5) * g.dx[2]);
}

template <class F, class Field>
void fill(const Grid& g, Field& f, F&& fn) {
  const IndexRange r = g.patches[0].cells_with_extra();
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      for (int i = r.lo[0]; i < r.hi[0]; ++i) f(i, j, k) = fn(centre(g, IntVec3(i, j, k)));
}

template <class F>
void expect_force(const Vec3& expected, F&& velocity) {
  const Grid g = grid6();
  CellVectors u(g, 2), force(g, 2);
  CellScalars theta(g, 2);
  fill(g, u[0], velocity);
  fill(g, theta[0], [](const Vec3&) { return 1.0; });
  force.fill(Vec3::Zero());
  const double mu = 1.7e-3;
  add_viscous_force(g, g.patches[0], u[0], theta[0], mu, force[0]);
  const IndexRange r = g.patches[0].cells();
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      for (int i = r.lo[0]; i < r.hi[0]; ++i)
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(force[0](i, j, k)[a], mu * expected[a], 1e-12) << i << j << k << a;
}

}  // namespace

// u = (y^2, x^2, 0): div u = 0, tau_xy = mu (2y + 2x), div tau = mu (2, 2, 0).
TEST(IceDiffusion, ShearFlowStressDivergence) {
  expect_force(Vec3(2, 2, 0), [](const Vec3& x) { return Vec3(x[1] * x[1], x[0] * x[0], 0); });
}

// u = (x^2, 0, 0): div u = 2x, tau_xx = 2 mu 2x - (2/3) mu 2x = (8/3) mu x,
// div tau = ((8/3) mu, 0, 0) (Stokes' hypothesis enters through the 2/3).
TEST(IceDiffusion, DilatationalStressDivergence) {
  expect_force(Vec3(8.0 / 3.0, 0, 0), [](const Vec3& x) { return Vec3(x[0] * x[0], 0, 0); });
}

// u = (x z, 0, x^2): div u = z; tau_xx = (4/3) mu z, tau_xz = mu (x + 2x),
// tau_zz = -(2/3) mu z; div tau = (d tau_xx/dx + d tau_xz/dz, 0, d tau_zx/dx + d tau_zz/dz)
// = mu (0 + 0, 0, 3 - 2/3) = mu (0, 0, 7/3).
TEST(IceDiffusion, MixedGradientStressDivergence) {
  expect_force(Vec3(0, 0, 7.0 / 3.0), [](const Vec3& x) { return Vec3(x[0] * x[2], 0, x[0] * x[0]); });
}

// T = x^2 + 2 y^2 + 3 z^2, theta = 1: div(k grad T) = k (2 + 4 + 6) = 12 k.
TEST(IceDiffusion, ConductionOfQuadraticTemperature) {
  const Grid g = grid6();
  CellScalars T(g, 2), theta(g, 2), heat(g, 2);
  fill(g, T[0], [](const Vec3& x) { return x[0] * x[0] + 2 * x[1] * x[1] + 3 * x[2] * x[2]; });
  fill(g, theta[0], [](const Vec3&) { return 1.0; });
  heat.fill(0.0);
  add_heat_conduction(g, g.patches[0], T[0], theta[0], 0.026, heat[0]);
  const IndexRange r = g.patches[0].cells();
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      for (int i = r.lo[0]; i < r.hi[0]; ++i) EXPECT_NEAR(heat[0](i, j, k), 12 * 0.026, 1e-12);
}

// Linear T in x with a volume fraction jump between cells: the harmonic face
// conductivity makes the flux continuous, so a conserving steady profile
// (T piecewise linear with slopes inversely proportional to theta k) has zero
// divergence. theta = 1 for x < 0.3, 0.25 beyond; T' = 1 and 4.
TEST(IceDiffusion, HarmonicFaceConductivityConservesFlux) {
  const Grid g = grid6();
  CellScalars T(g, 2), theta(g, 2), heat(g, 2);
  fill(g, theta[0], [](const Vec3& x) { return x[0] < 0.3 ? 1.0 : 0.25; });
  fill(g, T[0], [](const Vec3& x) { return x[0] < 0.3 ? x[0] : 0.25 + 4 * (x[0] - 0.25) - 0.15; });
  // Check the construction: the face at x = 0.3 between cells 2 (x=0.25) and 3 (x=0.35):
  // flux = k_f (T3 - T2)/dx with k_f = 2*1*0.25/1.25 = 0.4; T3 - T2 = 0.25 + 0.4 - 0.15 - 0.25 = 0.25,
  // 0.4 * 0.25/0.1 = 1 = the flux 1 * 1 on the left.
  heat.fill(0.0);
  add_heat_conduction(g, g.patches[0], T[0], theta[0], 1.0, heat[0]);
  const IndexRange r = g.patches[0].cells();
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      for (int i = r.lo[0]; i < r.hi[0]; ++i) EXPECT_NEAR(heat[0](i, j, k), 0.0, 1e-11) << i;
}
