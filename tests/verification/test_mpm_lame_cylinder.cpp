// A thick-walled cylinder under internal pressure (Lame), loaded by a
// <PhysicalBC><MPM><pressure> on a cylinder surface (mpm/loads/): a quarter of
// the cross-section a = 0.5 <= r <= b = 1 m (symmetry planes x = 0, y = 0),
// plane strain (one cell in z between symmetry planes), hypoelastic
// K = 6 MPa, G = 3 MPa, rho = 1000 (c = 100 m/s). The quarter holds a
// quarter of the loaded surface: <volume_fraction_inside_domain>0.25.
// The pressure ramps linearly to p over t_r = 20 b/c, slow against the
// radial wave transits, then holds, so the state is quasi-static; the
// remaining dynamic oscillation is of relative size ~ (b/c)/t_r.
//
// Exact (Lame, plane strain, small strain):
//   sigma_rr = A - B/r^2,  sigma_thth = A + B/r^2,
//   A = p a^2/(b^2 - a^2),  B = p a^2 b^2/(b^2 - a^2).
// Checked on the particles of the mid-wall band 0.6 <= r <= 0.9 (away from
// the loaded and free surfaces, whose staircase particle layers the 16x16
// grid resolves only to a cell): the mean of sigma_thth - (A + B/r^2) and of
// sigma_rr - (A - B/r^2) over the band, relative to p, within 5 %
// (observed: 0.02 % and 1.4 %; 1174 steps, 2 s).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

TEST(MpmLameCylinder, InternalPressureGivesLameStresses) {
  set_thread_count(1);
  const double h = 1.0 / 16, a = 0.5, b = 1.0, p = 1.0e3, c = 100.0;
  const double t_ramp = 20 * b / c, t_end = t_ramp + 2 * b / c;
  std::ostringstream s;
  s.precision(17);
  auto cyl = [&](double r) {
    std::ostringstream o;
    o.precision(17);
    o << "<cylinder><bottom>[0,0,0]</bottom><top>[0,0," << h << "]</top><radius>" << r << "</radius></cylinder>";
    return o.str();
  };
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>linear</interpolator><use_load_curves>true</use_load_curves></MPM>"
    << "<MaterialProperties><MPM><material><density>1000</density><thermal_conductivity>1</thermal_conductivity>"
    << "<specific_heat>1</specific_heat><constitutive_model type=\"hypo_elastic\"><K>6e6</K><G>3e6</G>"
    << "</constitutive_model><geom_object><difference>" << cyl(b) << cyl(a)
    << "</difference><res>[2,2,1]</res><velocity>[0,0,0]</velocity><temperature>300</temperature></geom_object>"
    << "</material></MPM></MaterialProperties>"
    << "<PhysicalBC><MPM><pressure><geom_object>" << cyl(a) << "</geom_object>"
    << "<volume_fraction_inside_domain>0.25</volume_fraction_inside_domain><load_curve><id>1</id>"
    << "<time_point><time>0</time><load>0</load></time_point><time_point><time>" << t_ramp << "</time><load>" << p
    << "</load></time_point></load_curve></pressure></MPM></PhysicalBC>"
    << "<Grid><BoundaryConditions>";
  for (const char* f : {"x-", "y-", "z-", "z+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"></BCType></Face>";
  s << "</BoundaryConditions><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1.125,1.125," << h
    << "]</upper><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box><spacing>[" << h << "," << h << ","
    << h << "]</spacing></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(s.str(), "lame.ups", ".");
  auto comp = make_mpm_component(*deck);
  comp->initialize();
  double t = 0;
  int step = 0;
  while (t < t_end) {
    const double dt = std::min(0.3 * comp->stable_timestep(), t_end - t);
    comp->advance(t, dt, ++step);
    t += dt;
  }
  const double A = p * a * a / (b * b - a * a), B = p * a * a * b * b / (b * b - a * a);
  const Particles& P = comp->materials()[0].particles;
  double d_rr = 0, d_tt = 0;
  int n = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec3& x = P.x[i];
    const double r = std::hypot(x[0], x[1]);
    if (r < 0.6 || r > 0.9) continue;
    const double cs = x[0] / r, sn = x[1] / r;
    const Mat3& S = P.stress[i];
    const double s_rr = cs * cs * S(0, 0) + 2 * cs * sn * S(0, 1) + sn * sn * S(1, 1);
    const double s_tt = sn * sn * S(0, 0) - 2 * cs * sn * S(0, 1) + cs * cs * S(1, 1);
    d_rr += s_rr - (A - B / (r * r));
    d_tt += s_tt - (A + B / (r * r));
    ++n;
  }
  d_rr /= n * p;
  d_tt /= n * p;
  std::printf("Lame cylinder (%d steps, %d particles in 0.6 <= r <= 0.9): mean (sigma_rr - exact)/p = %.4f, "
              "mean (sigma_thth - exact)/p = %.4f; sigma_thth(a) exact = %.3f p\n",
              step, n, d_rr, d_tt, (A + B / (a * a)) / p);
  EXPECT_GT(n, 0);
  EXPECT_LT(std::abs(d_rr), 0.05);
  EXPECT_LT(std::abs(d_tt), 0.05);
}

}  // namespace
}  // namespace tephra
