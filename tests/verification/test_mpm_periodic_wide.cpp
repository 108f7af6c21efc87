// Periodic MPM with the wide stencils (gimp, 3rdorderBS, cpgimp, cpdi, cpti;
// ghost node layers, mpm/PeriodicGrid.h). For each interpolator:
//  1. Larger-domain reference: a bar periodic in x of length L = 1 m
//     (8 cells) against a bar of 41 L, not periodic in x, holding 41 copies
//     of the same initial state (the periodic extension). The initial
//     velocity v = (U + V0 sin(2 pi x / L), V0 cos(2 pi x / L), 0) (U = 40 m/s
//     drift: particles cross the periodic face; V0 = 1 m/s wave), between
//     symmetry walls y = 0, 2h, which zero v_y on their nodes: the ghost nodes
//     beyond the periodic face must follow (copy_from_canonical); symmetry
//     BCs written on the periodic x faces must be ignored. The long bar's free ends are 20 L =
//     160 cells from its middle copy; per step a particle's state depends on
//     particles at most 4 r cells away (P2G, G2P, then the MUSL P2G and the
//     l_p gather, each reaching r = the stencil's reach from a particle: 1.5
//     cells for gimp / 3rdorderBS, 2 for cpdi / cpgimp at these strains), so
//     for 20 steps (<= 160 / 8) the middle copy cannot see the ends: it must
//     equal the periodic run to round-off (positions modulo L, velocities,
//     stresses). A missing ghost fold changes the first step's node sums at
//     the face by O(1). Also: the x momentum of the periodic run constant to
//     round-off (no x BC, no body force: P2G, the alias fold and G2P conserve it).
//  2. Standing wave (the longest mode of a periodic bar, period T = L / c,
//     c = sqrt((K + 4G/3)/rho) = 100 m/s): the measured period converges to
//     L / c at second order in h (16 -> 32 cells, order 2 +- 0.3) and its
//     Richardson extrapolation equals L / c within 0.05 % (the semi-discrete
//     error of a consistent second-order discretisation is O((kh)^2)).
//  The 3-D block translating through a fully periodic box runs for every
//  interpolator in test_mpm_periodic.cpp (MpmPeriodicBlock).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

constexpr double kPi = std::numbers::pi;

std::string deck_text(const std::string& interp, const std::string& grid, const std::string& box,
                      const std::string& res, const std::string& v) {
  std::ostringstream s;
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator></MPM>"
    << "<MaterialProperties><MPM><material><density>1000</density><thermal_conductivity>1</thermal_conductivity>"
    << "<specific_heat>1</specific_heat><constitutive_model type=\"hypo_elastic\"><K>6e6</K><G>3e6</G>"
    << "</constitutive_model><geom_object>" << box << "<res>" << res << "</res><velocity>" << v
    << "</velocity><temperature>300</temperature></geom_object></material></MPM></MaterialProperties>"
    << "<Grid>" << grid << "</Grid></Uintah_specification>";
  return s.str();
}

// A bar [x0, x1] x [0, h]^2 seeded with 2 x 1 x 1 particles per cell, on a grid
// [g0, g1] x [0, h]^2 periodic in y and z (one cell), and in x if `periodic_x`.
// With `walls_y`: two cells in y between symmetry faces y-, y+ (extra cells
// in y), and symmetry BCs written on the x faces too (ignored when x is
// periodic: a periodic face is not a boundary).
std::unique_ptr<MpmComponent> bar(const std::string& interp, double h, double x0, double x1, double g0, double g1,
                                  bool periodic_x, bool walls_y = false) {
  const double hy = walls_y ? 2 * h : h;
  std::ostringstream grid, box;
  if (walls_y) {
    grid << "<BoundaryConditions>";
    for (const char* side : {"x-", "x+", "y-", "y+"})
      grid << "<Face side=\"" << side << "\"><BCType id=\"all\" label=\"Symmetric\" var=\"symmetry\"/></Face>";
    grid << "</BoundaryConditions>";
  }
  grid << "<Level><Box label=\"1\"><lower>[" << g0 << ",0,0]</lower><upper>[" << g1 << "," << hy << "," << h
       << "]</upper><extraCells>[" << (periodic_x ? 0 : 1) << "," << (walls_y ? 1 : 0)
       << ",0]</extraCells><patches>[1,1,1]</patches></Box>"
       << "<spacing>[" << h << "," << h << "," << h << "]</spacing><periodic>[" << (periodic_x ? 1 : 0) << ","
       << (walls_y ? 0 : 1) << ",1]</periodic></Level>";
  box << "<box label=\"bar\"><min>[" << x0 << ",0,0]</min><max>[" << x1 << "," << hy << "," << h << "]</max></box>";
  auto deck = load_deck_from_string(deck_text(interp, grid.str(), box.str(), "[2,1,1]", "[0,0,0]"), "bar.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  return c;
}

class PeriodicWide : public ::testing::TestWithParam<const char*> {};

TEST_P(PeriodicWide, EqualsTheLargerDomainOverTheInteriorWindow) {
  set_thread_count(1);
  const std::string interp = GetParam();
  const double L = 1.0, h = L / 8, U = 40.0, V0 = 1.0;
  auto per = bar(interp, h, 0.0, L, 0.0, L, true, true);
  auto big = bar(interp, h, -20 * L, 21 * L, -21 * L, 22 * L, false, true);
  // The same initial velocity at every copy: sin of the position within its copy.
  auto init = [&](MpmComponent& c) {
    Particles& p = c.materials()[0].particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double local = p.x[i][0] - std::floor(p.x[i][0] / L) * L;
      p.v[i] = Vec3(U + V0 * std::sin(2 * kPi * local / L), V0 * std::cos(2 * kPi * local / L), 0);
    }
  };
  init(*per);
  init(*big);
  // The middle copy's particles of the long bar, matched to the periodic run's by initial x.
  const Particles& pp = per->materials()[0].particles;
  const Particles& pb = big->materials()[0].particles;
  std::vector<std::size_t> match(pp.size(), pb.size());
  for (std::size_t i = 0; i < pp.size(); ++i)
    for (std::size_t j = 0; j < pb.size(); ++j)
      if (std::abs(pb.x[j][0] - pp.x[i][0]) < 1e-9 && std::abs(pb.x[j][1] - pp.x[i][1]) < 1e-9) match[i] = j;
  for (std::size_t i = 0; i < pp.size(); ++i) ASSERT_LT(match[i], pb.size()) << "particle " << i << " unmatched";
  auto momentum = [&] {
    Vec3 m = Vec3::Zero();
    for (std::size_t i = 0; i < pp.size(); ++i) m += pp.mass[i] * pp.v[i];
    return m;
  };
  const Vec3 momentum0 = momentum();
  const double dt = 0.4 * h / (100.0 + U + V0);  // fixed, the same in both runs
  const int window = 20;                         // 20 L / (4 r = 8 cells per step), see the header
  double dx = 0, dv = 0, ds = 0, smax = 0;
  for (int step = 1; step <= window; ++step) {
    const double t = (step - 1) * dt;
    per->advance(t, dt, step);
    big->advance(t, dt, step);
    for (std::size_t i = 0; i < pp.size(); ++i) {
      const std::size_t j = match[i];
      double d = pb.x[j][0] - pp.x[i][0];
      d -= std::round(d / L) * L;  // the periodic copy re-entered at the other face
      dx = std::max(dx, std::abs(d));
      dv = std::max(dv, (pb.v[j] - pp.v[i]).norm());
      ds = std::max(ds, (pb.stress[j] - pp.stress[i]).norm());
      smax = std::max(smax, pp.stress[i].norm());
    }
  }
  int wrapped = 0;
  for (std::size_t i = 0; i < pp.size(); ++i) wrapped += pp.x[i][0] - pp.displacement[i][0] < 0.0;  // X = x - u below the face
  const double dp = std::abs(momentum()[0] - momentum0[0]);  // x: periodic, no force (the y walls take y momentum)
  std::printf("periodic %s vs 41 L bar, %d steps: max |dx| %.3g m, |dv| %.3g m/s, |dsigma| %.3g Pa (max |sigma| "
              "%.3g Pa); %d particles re-entered; x momentum change %.3g of %.3g\n",
              interp.c_str(), window, dx, dv, ds, smax, wrapped, dp, momentum0[0]);
  EXPECT_GT(wrapped, 0);        // the window covers particles crossing the periodic face
  EXPECT_GT(smax, 1e3);         // the wave is loaded (rho c V0 = 1e5 Pa scale)
  EXPECT_LT(dx, 1e-13);         // round-off of x ~ 1 m
  EXPECT_LT(dv, 1e-11);         // round-off of v ~ 40 m/s
  EXPECT_LT(ds, 1e-9 * smax);   // round-off of the stress
  EXPECT_LT(dp, 1e-13 * momentum0[0]);
}

// Period of the longest standing wave in a periodic bar of `cells` cells (as
// test_mpm_periodic's linear case): mode amplitude a(t) = sum m v_x sin(k X),
// T from its zero crossings at T/4 and 3T/4.
double standing_wave_period(const std::string& interp, int cells) {
  const double L = 1.0, h = L / cells;
  auto c = bar(interp, h, 0.0, L, 0.0, L, true);
  const double k = 2 * kPi / L, V0 = 1e-3;
  Particles& p0 = c->materials()[0].particles;
  for (std::size_t i = 0; i < p0.size(); ++i) p0.v[i] = Vec3(V0 * std::sin(k * p0.x[i][0]), 0, 0);
  auto amplitude = [&] {
    const Particles& p = c->materials()[0].particles;
    double a = 0;
    for (std::size_t i = 0; i < p.size(); ++i) a += p.mass[i] * p.v[i][0] * std::sin(k * (p.x[i][0] - p.displacement[i][0]));
    return a;
  };
  const double T_exact = L / 100.0;
  std::vector<double> crossings;
  double t = 0, a_prev = amplitude();
  int step = 0;
  while (crossings.size() < 2 && t < 2 * T_exact) {
    const double dt = 0.1 * c->stable_timestep();
    c->advance(t, dt, ++step);
    const double a = amplitude();
    if ((a < 0) != (a_prev < 0)) crossings.push_back(t + dt * a_prev / (a_prev - a));
    a_prev = a;
    t += dt;
  }
  EXPECT_EQ(crossings.size(), 2u);
  return crossings.size() == 2 ? 2 * (crossings[1] - crossings[0]) : 0.0;
}

TEST_P(PeriodicWide, StandingWavePeriodConvergesToLOverCAtSecondOrder) {
  set_thread_count(1);
  const std::string interp = GetParam();
  const double T_exact = 0.01;
  const double e16 = standing_wave_period(interp, 16) / T_exact - 1;
  const double e32 = standing_wave_period(interp, 32) / T_exact - 1;
  const double order = std::log2(std::abs(e16 / e32));
  const double extrapolated = (4 * e32 - e16) / 3;
  std::printf("periodic %s bar: T/T_exact - 1 = %.3e (16 cells), %.3e (32 cells), order %.2f, Richardson %.3e\n",
              interp.c_str(), e16, e32, order, extrapolated);
  EXPECT_NEAR(order, 2.0, 0.3);
  EXPECT_LT(std::abs(extrapolated), 5e-4);
}

INSTANTIATE_TEST_SUITE_P(Interpolators, PeriodicWide,
                         ::testing::Values("gimp", "3rdorderBS", "cpgimp", "cpdi", "cpti"),
                         [](const auto& info) {
                           std::string n = info.param;
                           return n == "3rdorderBS" ? std::string("QuadraticBspline") : n;
                         });

}  // namespace
}  // namespace tephra
