// Axisymmetric MPM with linear, gimp, cpdi, cpti, cpgimp, 3rdorderBS and 4thorderBS (mpm/Axisymmetric.h,
// mpm/shape/ShapeAxisymmetric.h): the first radial vibration mode of a solid
// cylinder 0 <= r <= a whose outer surface cannot move radially (symmetry
// face at r = a), in plane strain (symmetry faces in z).
//
// Linear elasticity, u = u_r(r, t) e_r: (lambda + 2 mu)(u_r'' + u_r'/r - u_r/r^2)
// = rho u_r,tt, whose regular standing waves are u_r = U J1(k r) sin(omega t),
// omega = k c, c = sqrt((K + 4G/3)/rho). u_r(a) = 0 picks k a = j_{1,1} =
// 3.8317059702075123 (first zero of J1). The hoop terms (v_r / r in the rate,
// sigma_thth / r in the force) are what make J1 the mode: without them the
// equation is the planar one and the mode would be sin(pi r / a) at a
// different frequency (pi instead of 3.83).
//
// The run starts from u = 0 and the leapfrog velocity v(-dt/2) = U omega
// J1(kR) cos(omega dt / 2) (the scheme's velocity is v at half steps;
// docs/mpm-convergence.md "Time against space"), with a constant dt that
// lands on t = T/4 (the largest displacement). Error: the particles' rms
// |u_r - U J1(kR)| / U at t = T/4 (R = x - u, the reference radius).
// Measured (this test prints them; docs/mpm-convergence.md "Axisymmetric MPM").
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

constexpr double kJ11 = 3.8317059702075123;  // first positive zero of J1

// rows: cells in the axial (y) direction; the solution does not depend on y.
std::string mode_deck(const std::string& interpolator, int cells, int rows) {
  const double h = 1.0 / cells;
  std::ostringstream s;
  s.precision(17);
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interpolator << "</interpolator><axisymmetric>true</axisymmetric></MPM>"
    << "<MaterialProperties><MPM><material><density>1000</density><thermal_conductivity>1</thermal_conductivity>"
    << "<specific_heat>1</specific_heat><constitutive_model type=\"hypo_elastic\"><K>6e6</K><G>3e6</G>"
    << "</constitutive_model><geom_object><box label=\"rod\"><min>[0,0,0]</min><max>[1.0," << rows * h << "," << h
    << "]</max></box><res>[2,2,1]</res><velocity>[0,0,0]</velocity><temperature>300</temperature>"
    << "</geom_object></material></MPM></MaterialProperties>"
    << "<Grid><BoundaryConditions>";
  for (const char* f : {"x-", "x+", "y-", "y+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"></BCType></Face>";
  s << "</BoundaryConditions><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1.0," << rows * h << "," << h
    << "]</upper><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box><spacing>[" << h << "," << h << ","
    << h << "]</spacing></Level></Grid></Uintah_specification>";
  return s.str();
}

// rms of (u_r - exact) / U (and u_z / U) over the particles at t = T/4: all,
// those within 2 cells of the axis (R < 2h), and the others.
struct ModeError {
  double all = 0, axis = 0, rest = 0;
};

ModeError mode_error(const std::string& interpolator, int cells) {
  set_thread_count(1);
  // 4thorderBS: its boundary-modified splines need >= 3 cells per direction (mpm/shape/ShapeBsplineCubic.h).
  const int rows = interpolator == "4thorderBS" ? 4 : 2;
  auto deck = load_deck_from_string(mode_deck(interpolator, cells, rows), "axi_mode.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  Particles& p = c->materials()[0].particles;
  const double cp = 100.0, k = kJ11, omega = k * cp, U = 1e-5;  // c = sqrt((6e6 + 4e6)/1000)
  const double t_end = 0.25 * 2 * M_PI / omega;
  const int n = int(std::ceil(t_end / (0.3 * c->stable_timestep())));
  const double dt = t_end / n;
  for (std::size_t i = 0; i < p.size(); ++i)
    p.v[i] = Vec3(U * omega * std::cyl_bessel_j(1.0, k * p.x[i][0]) * std::cos(0.5 * omega * dt), 0, 0);
  double t = 0;
  for (int step = 1; step <= n; ++step, t += dt) c->advance(t, dt, step);
  double sum[2] = {0, 0};
  long count[2] = {0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double R = p.x[i][0] - p.displacement[i][0];
    const double e = (p.displacement[i][0] - U * std::cyl_bessel_j(1.0, k * R)) / U;
    const int band = R < 2.0 / cells ? 0 : 1;
    sum[band] += e * e + std::pow(p.displacement[i][1] / U, 2);
    ++count[band];
  }
  ModeError out;
  out.all = std::sqrt((sum[0] + sum[1]) / (count[0] + count[1]));
  out.axis = std::sqrt(sum[0] / count[0]);
  out.rest = std::sqrt(sum[1] / count[1]);
  return out;
}

class AxisymmetricMode : public ::testing::TestWithParam<const char*> {};

// Linear, cpdi, cpti (the axiCpdi form) and cpgimp (planar weights, T = S/r_p):
// second order in h everywhere (order >= 1.8 from 16 to 32 cells; measured
// 1.979, 1.980, 1.980, 1.980) and the 32-cell error below 2e-3 of U (a
// planar, hoop-free scheme would have an O(1) error: its mode is a sine).
// gimp (Vaango's AxiGIMP weights, volume averages with dV = r dr dz): second
// order away from the axis, FIRST order within 2 cells of it. Cause (shown by
// the planar GIMP weights with the hoop factor S / r_p, which give 1.980 here,
// a measurement not kept in the tree): the r-weighted weights interpolate a
// linear field to the domain's volume centroid r_p + l^2 / (3 r_p), not to
// r_p, so G2P moves the first particles (r_p = l, 3l, ...) with a velocity
// off by O((l / r_p)^2) = O(1) whatever h. The test asserts this behaviour:
// order >= 1.8 off the axis band, 0.7..1.3 in it (measured 0.93, 16 -> 32).
TEST_P(AxisymmetricMode, FirstRadialModeConverges) {
  const std::string interp = GetParam();
  const ModeError e16 = mode_error(interp, 16), e32 = mode_error(interp, 32);
  const double order = std::log2(e16.all / e32.all), order_axis = std::log2(e16.axis / e32.axis),
               order_rest = std::log2(e16.rest / e32.rest);
  std::printf("%s axisymmetric J1 mode at T/4, rms error / U at 16 and 32 cells: all %.4e %.4e (order %.3f), "
              "R < 2h %.4e %.4e (order %.3f), R >= 2h %.4e %.4e (order %.3f)\n",
              interp.c_str(), e16.all, e32.all, order, e16.axis, e32.axis, order_axis, e16.rest, e32.rest, order_rest);
  EXPECT_LT(e32.all, 2e-3);
  EXPECT_GE(order_rest, 1.8);
  if (interp == "gimp") {
    EXPECT_GT(order_axis, 0.7);
    EXPECT_LT(order_axis, 1.3);
  } else {
    EXPECT_GE(order, 1.8);
    EXPECT_GE(order_axis, 1.8);
  }
}

INSTANTIATE_TEST_SUITE_P(AllInterpolators, AxisymmetricMode,
                         ::testing::Values("linear", "gimp", "cpdi", "cpti", "cpgimp"));

// 3rdorderBS (uniform quadratic B-spline, planar weights, T = S / r_p). Its
// support (1.5 cells) reaches the extra-cell nodes beyond the symmetry faces
// r = 0, r = a and the axial faces. Two fixes made it converge (before:
// 7.4296e-3 -> 3.6525e-3, order 1.02): (1) the symmetry fold of those nodes
// (mpm/SymmetryFold.h, now also for axisymmetric runs, r and z faces): without
// it the node one cell inside r = a misses the wall's reaction, the error off
// the axis band was first order; (2) the grid BCs set the face nodes' normal
// velocity of every symmetry face before mirroring any extra node
// (mpm/GridBoundaryConditions.cpp): before, the extra node (r = -h, z = 0)
// copied the free axial velocity of (r = h, z = 0) before the z face zeroed
// it, and the first particle column at the axis drifted axially by 3.7e-3 U
// at every h. Measured (rms error / U at T/4; 8/16/32/64/128 cells): all
// 1.1084e-2, 3.3983e-3, 8.8458e-4, 2.3783e-4, 6.5749e-5 (orders 1.71, 1.94,
// 1.89, 1.85); R >= 2h orders 1.69, 1.77, 1.91, 1.93; R < 2h (the two cells at
// the axis) 6.1882e-3, 1.6076e-3, 5.9941e-4, 2.7102e-4 from 16 cells (orders
// 1.94, 1.42, 1.15: an error of about 3 % of the first particles'
// displacement remains at the axis, not explained; docs/mpm-convergence.md).
// With the BCs also applied after the node-wise MUSL/USL choice (session 16,
// MpmComponent::advance), 32 -> 64: all 8.8646e-4 -> 2.3819e-4 (1.896), R >= 2h
// 8.1429e-4 -> 2.1642e-4 (1.912), R < 2h 1.6208e-3 -> 6.0285e-4 (1.427).
// Asserted from 32 to 64 cells: all and R >= 2h >= 1.8, the axis band
// between 1.2 and 1.7: if it reaches 2, the docs change.
TEST(AxisymmetricModeBspline, QuadraticBsplineSecondOrderOffTheAxis) {
  const ModeError e32 = mode_error("3rdorderBS", 32), e64 = mode_error("3rdorderBS", 64);
  const double order = std::log2(e32.all / e64.all), order_axis = std::log2(e32.axis / e64.axis),
               order_rest = std::log2(e32.rest / e64.rest);
  std::printf("3rdorderBS J1 mode, 32 -> 64 cells: all %.4e %.4e (order %.3f), R < 2h %.4e %.4e (order %.3f), "
              "R >= 2h %.4e %.4e (order %.3f)\n",
              e32.all, e64.all, order, e32.axis, e64.axis, order_axis, e32.rest, e64.rest, order_rest);
  EXPECT_LT(e32.all, 1e-3);
  EXPECT_GE(order, 1.8);
  EXPECT_GE(order_rest, 1.8);
  EXPECT_GT(order_axis, 1.2);
  EXPECT_LT(order_axis, 1.7);
}

// 4thorderBS (Vaango's cubic B-spline with the boundary-modified splines at
// the two node layers of each face, no extra-cell node; the deck is 4 cells
// tall, as those splines need >= 3 cells per direction): FIRST order, as on
// AxisAligned (1.20, 1.08). Its weights are not linearly complete within 3
// cells of a face (sum S_i x_i = 0.302 h at x = h/2 from a face instead of
// 0.5 h, docs/mpm-convergence.md "cpti and 4thorderBS"), here at r = 0 and r = a.
// Measured (8/16/32/64/128 cells): 2.2330e-2, 1.0734e-2, 4.2164e-3, 1.9263e-3,
// 9.2859e-4 (orders 1.06, 1.35, 1.13, 1.05). Asserted from 32 to 64 cells:
// order between 0.9 and 1.4 (1.13).
TEST(AxisymmetricModeBspline, CubicBsplineFirstOrder) {
  const ModeError e32 = mode_error("4thorderBS", 32), e64 = mode_error("4thorderBS", 64);
  const double order = std::log2(e32.all / e64.all);
  std::printf("4thorderBS J1 mode, 32 -> 64 cells: all %.4e %.4e (order %.3f), R < 2h %.4e %.4e, R >= 2h %.4e %.4e\n",
              e32.all, e64.all, order, e32.axis, e64.axis, e32.rest, e64.rest);
  EXPECT_GT(order, 0.9);
  EXPECT_LT(order, 1.4);
}

}  // namespace
}  // namespace tephra
