// Radial solid motion in axisymmetric MPMICE against a closed form (issue 6;
// docs/mpmice.md "Session 27: radial solid motion").
//
// Scene: inputs/mpmice/breathing_tube_axisym.ups, an infinitely long elastic
// tube (comp_neo_hook_plastic far below yield: K = 1.17e9, G = 4.38e8 Pa,
// rho = 8900 kg/m^3; a = 45 mm, b = 50 mm) in air, 1.1 MPa inside, 1 atm
// outside, released at t = 0; x = r, y = z with symmetry faces in z (plane
// strain), 1 mm cells (5 across the wall), GIMP, 2 x 2 particles per cell.
// The pressure reaches the tube only through the MPMICE coupling, and the
// tube's radial motion moves the solid's projected volume through the cells.
//
// Closed form (a thin tube set free under a step pressure oscillates as
// 1 - cos w t about its static displacement): the static mean radial
// displacement of the wall's particles is the plane-strain Lame solution
// u(r) = A r + B/r with
//   A = (1 + nu)(1 - 2 nu)(p_i a^2 - p_o b^2) / (E (b^2 - a^2)),
//   B = (1 + nu) a^2 b^2 (p_i - p_o) / (E (b^2 - a^2)),
// averaged over the particles: 3.3104e-4 m; the inner air's stiffness,
// quasi-static adiabatic (p_i (1 - 2 gamma u_a / a)), lowers it to 3.2348e-4.
// The air is not quasi-static (its crossing time a/c = 130 us against the
// period), so the peak 2 u_s lies between the two: [6.4696e-4, 6.6208e-4].
// Period: w^2 = E / ((1 - nu^2) rho R^2) at the mid radius R = 47.5 mm
// (thin shell, plane strain): 776.6 us, 786.7 us with the air's stiffness.
// Measured (1 mm): peak 6.5915e-4 m at 386.8 us; at 0.5 mm cells 6.5929e-4
// at 387.2 us (the discretisation error is 2e-4 of the peak: the
// difference to the closed forms is theirs, thin shell and air model).
// Asserted: the peak within the bracket widened by 1 %, its time within 2 %
// of the half period 388.3 us, the displacement back below 2 % of the peak
// at 780 us, and the particles' and the air's per-radian mass conserved.
// The linear hat (the deck with <interpolator>linear) stops at step 308
// (exit 4): its node-side projection share jumps when particles cross nodes
// (mpmice/AxisymmetricShare.h); not covered here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/CoupledRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

TEST(MpmIceBreathingTube, RadialMotionFollowsTheElasticClosedForm) {
  set_thread_count(1);
  test::CoupledRun r = test::make_coupled_run(test::source_dir() + "/inputs/mpmice/breathing_tube_axisym.ups");
  const Grid& g = r.c->ice().grid();
  const Particles& p = r.c->mpm().materials()[0].particles;
  std::vector<double> r0;
  for (const Vec3& x : p.x) r0.push_back(x[0]);
  auto mean_u = [&]() {
    double s = 0;
    for (std::size_t i = 0; i < p.size(); ++i) s += p.x[i][0] - r0[i];
    return s / double(p.size());
  };
  auto air_mass = [&]() {  // per radian: rho r_c dx dy
    double m = 0;
    for_each_cell_serial(g.patches[0].cells(), [&](int i, int j, int k) {
      m += r.c->ice().fields()[1].rho_CC[0](i, j, k) * g.cell_center(i, j, k)[0] * g.dx[0] * g.dx[1];
    });
    return m;
  };
  double solid0 = 0;
  for (double m : p.mass) solid0 += m;
  const double air0 = air_mass();
  double peak = 0, t_peak = 0, u_780 = 0;
  while (r.time < 8.0e-4 - 1e-12) {
    test::run_to(r, std::min(8.0e-4, r.time + 1e-6), 1 << 30);
    const double u = mean_u();
    if (u > peak) peak = u, t_peak = r.time;
    if (r.time <= 7.8e-4) u_780 = u;
  }
  double solid = 0;
  for (double m : p.mass) solid += m;
  const double air = air_mass();
  std::printf("[mpmice breathing tube] %d steps: peak mean radial displacement %.5e m at %.1f us "
              "(closed form [6.4696e-4, 6.6208e-4] at 388.3-393.4 us); u(780 us) %.3e; "
              "particle mass drift %.1e, air per-radian mass drift %.1e\n",
              r.steps, peak, t_peak * 1e6, u_780, std::abs(solid / solid0 - 1), std::abs(air / air0 - 1));
  EXPECT_GT(peak, 6.4696e-4 * 0.99);
  EXPECT_LT(peak, 6.6208e-4 * 1.01);
  EXPECT_NEAR(t_peak, 388.3e-6, 0.02 * 388.3e-6);
  EXPECT_LT(std::abs(u_780), 0.02 * peak);
  EXPECT_LT(std::abs(solid / solid0 - 1), 1e-14);
  EXPECT_LT(std::abs(air / air0 - 1), 1e-12);
}

}  // namespace
}  // namespace tephra
