// The rotating coordinate system (<MPM><rotating_coordinate_system>,
// mpm/loads/RotatingFrame.h; theory manual Alg. 3 with the branch erratum):
// b_p = g - omega x (omega x (x_p - x_rc)) - 2 omega x v_p.
//
// Exact solution. A body that moves with constant velocity u in the inertial
// frame (at rest for u = 0), frames coinciding at t = 0, has in the frame
// turning at omega about x_rc the trajectory
//   X(t) = x_rc + R(-|omega| t) (X0 + u t - x_rc),
// R(theta) the rotation by theta about the axis, and rotating-frame velocity
// V(0) = u - omega x (X0 - x_rc) at t = 0. The fictitious forces are linear
// in x and v and the internal forces of a block sum to zero, so the block's
// centre of mass follows exactly the point equation
//   dV/dt = -omega x (omega x (X - x_rc)) - 2 omega x V,
// and the MPM step (momentum-conserving P2G/FLIP, f_int summing to 0) gives
// for it the explicit scheme
//   V_{n+1} = V_n + dt a(X_n, V_n),  X_{n+1} = X_n + dt V_{n+1}
// to round-off. That scheme is first order: the centre of mass converges to
// the exact rotating-frame trajectory at order 1 in dt.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Geometry>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

const double kPi = std::numbers::pi;

TEST(MpmRotatingFrame, FictitiousAccelerationsAreCentrifugalAndCoriolis) {
  RotatingFrame f;
  f.center = Vec3(1, 2, 3);
  f.axis = Vec3::UnitZ();
  f.speed = 3.0;
  // r = (0.5, 0, 7) from the centre: centrifugal w^2 r_perp outward = 9 * 0.5 e_x; at rest no Coriolis.
  EXPECT_NEAR((f.fictitious_acceleration(Vec3(1.5, 2, 10), Vec3::Zero()) - Vec3(4.5, 0, 0)).norm(), 0.0, 1e-14);
  // On the axis, v = (0, 2, 5): -2 omega x v = -2 * 3 (e_z x 2 e_y) = 12 e_x; v along the axis adds nothing.
  EXPECT_NEAR((f.fictitious_acceleration(Vec3(1, 2, -4), Vec3(0, 2, 5)) - Vec3(12, 0, 0)).norm(), 0.0, 1e-14);
}

TEST(MpmRotatingFrame, DeckParsing) {
  auto frame = [](const std::string& body) {
    auto d = load_deck_from_string("<Uintah_specification><MPM><rotating_coordinate_system>" + body +
                                       "</rotating_coordinate_system></MPM></Uintah_specification>",
                                   "t.ups", ".");
    return parse_rotating_frame(d->root.require_child("MPM").require_child("rotating_coordinate_system"));
  };
  const std::string ok_tail = "<body_reference_point>[0,0,0]</body_reference_point>";
  const RotatingFrame f = frame("<rotation_center>[1,0,0]</rotation_center><rotation_axis>[0,0,2]</rotation_axis>"
                                "<rotation_speed_angular>5</rotation_speed_angular>" + ok_tail);
  EXPECT_EQ(f.axis, Vec3(0, 0, 1));  // normalised
  EXPECT_EQ(f.speed, 5.0);
  EXPECT_EQ(f.center, Vec3(1, 0, 0));
  EXPECT_THROW(frame("<rotation_center>[1,0,0]</rotation_center><rotation_axis>[0,0,0]</rotation_axis>"
                     "<rotation_speed_angular>5</rotation_speed_angular>" + ok_tail),
               DeckError);
  EXPECT_THROW(frame("<rotation_center>[1,0,0]</rotation_center><rotation_axis>[0,0,1]</rotation_axis>"
                     "<rotation_speed_angular>-5</rotation_speed_angular>" + ok_tail),
               DeckError);
  EXPECT_THROW(frame("<rotation_center>[1,0,0]</rotation_center><rotation_axis>[0,0,1]</rotation_axis>"
                     "<rotation_speed_angular>5</rotation_speed_angular>"),
               DeckError);  // body_reference_point is required (Vaango's schema)
}

struct FrameRun {
  double exact_error = 0;     // |X_cm - X_exact| at t_end [m]
  double discrete_error = 0;  // |X_cm - X_scheme| at t_end [m]
};

// A soft block (one cell, 2^3 particles) in a frame turning a quarter turn
// about the z axis through (0.5, 0.5, 0.5); inertial velocity u of its centre of mass.
FrameRun run_frame(int n) {
  const double w = 2 * kPi, t_end = 0.25, dt = t_end / n;
  const Vec3 center(0.5, 0.5, 0.5), u(0.05, 0.0, 0.02);
  RotatingFrame frame;
  frame.center = center;
  frame.axis = Vec3::UnitZ();
  frame.speed = w;
  const Vec3 lo(0.625, 0.5, 0.4375), hi(0.75, 0.625, 0.5625);
  const Vec3 X0 = (lo + hi) / 2;
  const Vec3 V0 = u - frame.omega().cross(Vec3(X0 - center));

  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3::Ones();
  s.grid.cells = IntVec3::Constant(8);
  s.grid.dx = Vec3::Constant(0.125);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  s.rotating_frame = frame;
  MpmMaterial m;
  m.density = 1000.0;
  m.specific_heat = 1.0;
  m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{833.3, 384.6});
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(lo, hi);
  src.res = IntVec3::Constant(2);
  src.velocity = V0;
  src.temperature = 300.0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  MpmComponent c(std::move(s));
  c.initialize();

  Vec3 X = X0, V = V0;  // the explicit scheme for the centre of mass
  for (int k = 0; k < n; ++k) {
    c.advance(k * dt, dt, k + 1);
    V += dt * frame.fictitious_acceleration(X, V);
    X += dt * V;
  }
  const Particles& p = c.materials()[0].particles;
  Vec3 mx = Vec3::Zero();
  double M = 0;
  for (std::size_t i = 0; i < p.size(); ++i) mx += p.mass[i] * p.x[i], M += p.mass[i];
  const Vec3 cm = mx / M;
  const Vec3 exact = center + Eigen::AngleAxisd(-w * t_end, frame.axis) * Vec3(X0 + u * t_end - center);
  return {(cm - exact).norm(), (cm - X).norm()};
}

TEST(MpmRotatingFrame, BlockFollowsTheInertialStraightLineSeenFromTheRotatingFrame) {
  const int n[3] = {50, 100, 200};
  FrameRun r[3];
  for (int k = 0; k < 3; ++k) r[k] = run_frame(n[k]);
  const double o1 = std::log2(r[0].exact_error / r[1].exact_error);
  const double o2 = std::log2(r[1].exact_error / r[2].exact_error);
  std::printf("rotating frame (quarter turn, 50/100/200 steps): |X_cm - X_exact| %.3e %.3e %.3e m, orders %.3f %.3f; "
              "|X_cm - X_scheme| %.1e %.1e %.1e m\n",
              r[0].exact_error, r[1].exact_error, r[2].exact_error, o1, o2, r[0].discrete_error, r[1].discrete_error,
              r[2].discrete_error);
  for (const FrameRun& x : r) EXPECT_LT(x.discrete_error, 1e-13);
  EXPECT_NEAR(o1, 1.0, 0.1);
  EXPECT_NEAR(o2, 1.0, 0.05);
}

}  // namespace
}  // namespace tephra
