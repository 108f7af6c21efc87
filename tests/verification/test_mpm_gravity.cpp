// Gravity as an MPM body force (<PhysicalConstants><gravity>; theory manual
// Alg. 3 without rotation: b_p = g, and Alg. 5: f_ext,g += sum m_p b_p S_gp).
//
// 1. Free fall. A stress-free block with velocity v0 under gravity g keeps a
//    uniform velocity field, which P2G and G2P pass exactly, so the explicit
//    step (Alg. 7 and 14: v_{n+1} = v_n + g dt, x_{n+1} = x_n + dt v_{n+1})
//    gives, summing the steps,
//      v_n = v0 + g t_n,   x_n = x0 + v0 t_n + g t_n (t_n + dt) / 2,
//    to round-off. This is symplectic Euler started from v(0) (Vaango's
//    start): the position differs from the exact x0 + v0 t + g t^2/2 by
//    g t dt / 2, first order in dt.
// 2. A column resting on a floor. An elastic column of height H (reference
//    coordinate Z from the floor), laterally confined by symmetry planes and
//    standing on the symmetry plane z = 0, under gravity g = -g e_z. Static
//    equilibrium d sigma_zz / dz = rho g with a traction-free top: the weight
//    of the material above a section over its (unchanged, uniaxial strain)
//    area, exactly, at finite strain too:
//      sigma_zz(Z) = -rho0 g (H - Z).
//    The dynamic run from rest oscillates about it; grid damping
//    (<artificial_damping_coeff> alpha = 2 omega_1, omega_1 = pi c / (2H) the
//    lowest mode) removes the oscillation, after t = 12 H / c the transient
//    is below 1e-6 rho g H. What remains is the discretisation error of the
//    static MPM solution (linear shape functions, 2 particles per cell).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

MpmMaterial neo_hookean_block(const Vec3& lo, const Vec3& hi, const Vec3& v0, double rho, double K, double G) {
  MpmMaterial m;
  m.density = rho;
  m.specific_heat = 1.0;
  m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{K, G});
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(lo, hi);
  src.res = IntVec3::Constant(2);
  src.velocity = v0;
  src.temperature = 300.0;
  m.sources.push_back(src);
  return m;
}

void unit_box_grid(MpmSetup& s, const Vec3& upper, const IntVec3& cells) {
  s.grid.lower = Vec3::Zero();
  s.grid.upper = upper;
  s.grid.cells = cells;
  s.grid.dx = upper.cwiseQuotient(cells.cast<double>());
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
}

TEST(MpmGravity, FreeFallIsSymplecticEulerToRoundOff) {
  const Vec3 g(0.0, -3.0, -9.81), v0(0.2, 0.5, 1.0);
  for (int n : {25, 50, 100}) {
    MpmSetup s;
    unit_box_grid(s, Vec3::Ones(), IntVec3::Constant(8));
    s.gravity = g;
    s.materials.push_back(neo_hookean_block(Vec3::Constant(0.375), Vec3::Constant(0.625), v0, 1000.0, 833.3, 384.6));
    MpmComponent c(std::move(s));
    c.initialize();
    const std::vector<Vec3> x0 = c.materials()[0].particles.x;
    const double t_end = 0.1, dt = t_end / n;
    for (int k = 0; k < n; ++k) c.advance(k * dt, dt, k + 1);
    const Particles& p = c.materials()[0].particles;
    double dev_x = 0, dev_v = 0, err = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 discrete = x0[i] + v0 * t_end + g * t_end * (t_end + dt) / 2;
      const Vec3 exact = x0[i] + v0 * t_end + g * t_end * t_end / 2;
      dev_x = std::max(dev_x, (p.x[i] - discrete).norm());
      dev_v = std::max(dev_v, (p.v[i] - (v0 + g * t_end)).norm());
      err = std::max(err, (p.x[i] - exact).norm());
      EXPECT_LT(p.stress[i].norm(), 1e-9);  // uniform motion: no strain
    }
    std::printf("free fall n = %d: |x - x_discrete| %.2e m, |v - (v0 + g t)| %.2e m/s, |x - x_exact| %.4e m "
                "(g t dt / 2 = %.4e m)\n",
                n, dev_x, dev_v, err, g.norm() * t_end * dt / 2);
    EXPECT_LT(dev_x, 1e-14);
    EXPECT_LT(dev_v, 1e-13);
    // The first-order offset from the continuous trajectory is exactly g t dt / 2.
    EXPECT_NEAR(err, g.norm() * t_end * dt / 2, 1e-14);
  }
}

struct ColumnError {
  double max = 0;    // max over the particles of |sigma_zz + rho g (H - Z)| / (rho g H)
  double z_max = 0;  // reference height Z / H of that particle
  double rms = 0;    // root mean square of the same
  double speed = 0;  // largest particle speed left [m/s]
};

ColumnError column_error(int cells) {
  const double H = 1.0, rho = 1000.0, g = 10.0, K = 1e6, G = 0.5e6;
  const double h = H / cells;
  MpmSetup s;
  unit_box_grid(s, Vec3(h, h, H + 2 * h), IntVec3(1, 1, cells + 2));
  s.gravity = Vec3(0, 0, -g);
  const double c_wave = std::sqrt((K + 4 * G / 3) / rho);
  const double omega1 = std::numbers::pi * c_wave / (2 * H);
  s.flags.artificial_damping_coeff = 2 * omega1;
  s.materials.push_back(neo_hookean_block(Vec3::Zero(), Vec3(h, h, H), Vec3::Zero(), rho, K, G));
  for (int f = 0; f < 5; ++f) s.materials[0].bcs.face[f].kind = FaceVelocityBC::Kind::Symmetry;  // x-, x+, y-, y+, z-
  MpmComponent c(std::move(s));
  c.initialize();
  const double t_end = 12 * H / c_wave;
  double t = 0;
  int step = 0;
  while (t < t_end) {
    const double dt = std::min(0.5 * c.stable_timestep(), t_end - t);
    c.advance(t, dt, ++step);
    t += dt;
  }
  const Particles& p = c.materials()[0].particles;
  ColumnError r;
  double sum2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double Z = p.x[i][2] - p.displacement[i][2];
    const double e = std::abs(p.stress[i](2, 2) + rho * g * (H - Z)) / (rho * g * H);
    if (e > r.max) r.max = e, r.z_max = Z / H;
    sum2 += e * e;
    r.speed = std::max(r.speed, p.v[i].norm());
  }
  r.rms = std::sqrt(sum2 / double(p.size()));
  return r;
}

// The residual motion can carry a stress of order rho c |v|; the run is
// static when that is below 1e-4 rho g H, i.e. |v| < 1e-4 g H / c
// (= 2.45e-5 m/s here). Tolerance on the static error: 2 % of rho g H at
// 40 cells, and the error must fall with h.
TEST(MpmGravity, ColumnOnAFloorSettlesToTheLithostaticStress) {
  const int cells[3] = {10, 20, 40};
  ColumnError e[3];
  for (int k = 0; k < 3; ++k) e[k] = column_error(cells[k]);
  std::printf("column under gravity, 10/20/40 cells: max |sigma_zz + rho g (H - Z)| / (rho g H) = %.3e %.3e %.3e "
              "(orders %.2f %.2f; at Z/H = %.3f %.3f %.3f), rms %.3e %.3e %.3e (orders %.2f %.2f); residual speed "
              "%.1e %.1e %.1e m/s\n",
              e[0].max, e[1].max, e[2].max, std::log2(e[0].max / e[1].max), std::log2(e[1].max / e[2].max),
              e[0].z_max, e[1].z_max, e[2].z_max, e[0].rms, e[1].rms, e[2].rms, std::log2(e[0].rms / e[1].rms),
              std::log2(e[1].rms / e[2].rms), e[0].speed, e[1].speed, e[2].speed);
  const double c_wave = std::sqrt((1e6 + 4 * 0.5e6 / 3) / 1000.0);
  for (int k = 0; k < 3; ++k) EXPECT_LT(e[k].speed, 1e-4 * 10.0 * 1.0 / c_wave);
  EXPECT_LT(e[2].max, 0.02);
  EXPECT_LT(e[1].max, e[0].max);
  EXPECT_LT(e[2].max, e[1].max);
  EXPECT_LT(e[1].rms, e[0].rms);
  EXPECT_LT(e[2].rms, e[1].rms);
}

}  // namespace
}  // namespace tephra
