// Axisymmetric pressure loads (<cylinder><axisymmetric_side> and
// <axisymmetric_end>, mpm/loads/ParticleLoads.h): per-radian forces as
// Vaango's PressureBC (side: p R L / N per particle; end: p X_r dr_p).
//
// 1. Thick-walled cylinder a = 0.5 <= r <= b = 1 m under internal pressure,
//    plane strain (symmetry faces in the axial direction), axisymmetric
//    (x = r, y = z), hypoelastic K = 6 MPa, G = 3 MPa, rho = 1000 (c = 100
//    m/s), pressure ramped over 20 b/c then held (quasi-static, as
//    test_mpm_lame_cylinder.cpp does in 3-D). Exact (Lame, plane strain):
//      sigma_rr = A - B/r^2, sigma_thth = A + B/r^2, sigma_zz = 2 nu A,
//      A = p a^2/(b^2 - a^2), B = p a^2 b^2/(b^2 - a^2), nu = (3K - 2G)/(2(3K + G)).
//    Mean deviation over the mid-wall band 0.6 <= r <= 0.9 within 3 % of p.
// 2. A solid rod 0 <= r <= R = 0.5, 0 <= z <= L = 1 (symmetry face z = 0,
//    free lateral surface), pressure ramped on its end z = L: uniaxial stress
//    sigma_zz = -p, sigma_rr = sigma_thth = 0 in the middle of the rod
//    (averaged over one period of the rod's ringing after the ramp; within
//    3 % of p); and the end load sums to p R^2 / 2, the area of the
//    one-radian wedge of the end (exact at t where no particle has moved:
//    sum over the particle columns of X_r dr = R^2/2 by the midpoint rule,
//    exact for the linear integrand r).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

constexpr double kK = 6e6, kG = 3e6, kRho = 1000, kC = 100;

std::string axi_deck(const std::string& interp, const std::string& body, const std::string& load, const Vec3& upper,
                     double h, const std::vector<const char*>& symmetric_faces) {
  std::ostringstream s;
  s.precision(17);
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator><axisymmetric>true</axisymmetric>"
    << "<use_load_curves>true</use_load_curves></MPM>"
    << "<MaterialProperties><MPM><material><density>" << kRho << "</density>"
    << "<thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
    << "<constitutive_model type=\"hypo_elastic\"><K>" << kK << "</K><G>" << kG << "</G></constitutive_model>"
    << "<geom_object>" << body << "<res>[2,2,1]</res><velocity>[0,0,0]</velocity><temperature>300</temperature>"
    << "</geom_object></material></MPM></MaterialProperties>"
    << "<PhysicalBC><MPM>" << load << "</MPM></PhysicalBC><Grid><BoundaryConditions>";
  for (const char* f : symmetric_faces)
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"></BCType></Face>";
  s << "</BoundaryConditions><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[" << upper[0] << "," << upper[1]
    << "," << upper[2] << "]</upper><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box><spacing>[" << h
    << "," << h << "," << h << "]</spacing></Level></Grid></Uintah_specification>";
  return s.str();
}

std::string ramp(double t_ramp, double p) {
  std::ostringstream o;
  o.precision(17);
  o << "<load_curve><id>1</id><time_point><time>0</time><load>0</load></time_point><time_point><time>" << t_ramp
    << "</time><load>" << p << "</load></time_point></load_curve>";
  return o.str();
}

void run_to(MpmComponent& c, double t_end) {
  double t = 0;
  int step = 0;
  while (t < t_end) {
    const double dt = std::min(0.3 * c.stable_timestep(), t_end - t);
    c.advance(t, dt, ++step);
    t += dt;
  }
}

class AxisymmetricLoads : public ::testing::TestWithParam<const char*> {};

TEST_P(AxisymmetricLoads, LameCylinderUnderInternalPressure) {
  set_thread_count(1);
  const double h = 1.0 / 16, a = 0.5, b = 1.0, p = 1.0e3, t_ramp = 20 * b / kC;
  std::ostringstream body, load;
  body.precision(17);
  load.precision(17);
  body << "<box label=\"wall\"><min>[" << a << ",0,0]</min><max>[" << b << "," << 2 * h << "," << h << "]</max></box>";
  load << "<pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0," << 2 * h << ",0]</top><radius>" << a
       << "</radius><axisymmetric_side>true</axisymmetric_side></cylinder></geom_object>" << ramp(t_ramp, p)
       << "</pressure>";
  auto deck = load_deck_from_string(
      axi_deck(GetParam(), body.str(), load.str(), Vec3(1.125, 2 * h, h), h, {"x-", "y-", "y+"}), "axi_lame.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  run_to(*c, t_ramp + 2 * b / kC);
  const double A = p * a * a / (b * b - a * a), B = p * a * a * b * b / (b * b - a * a);
  const double nu = (3 * kK - 2 * kG) / (2 * (3 * kK + kG));
  const Particles& P = c->materials()[0].particles;
  double d_rr = 0, d_tt = 0, d_zz = 0;
  int n = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double r = P.x[i][0];
    if (r < 0.6 || r > 0.9) continue;
    d_rr += P.stress[i](0, 0) - (A - B / (r * r));
    d_tt += P.stress[i](2, 2) - (A + B / (r * r));
    d_zz += P.stress[i](1, 1) - 2 * nu * A;
    ++n;
  }
  d_rr /= n * p, d_tt /= n * p, d_zz /= n * p;
  std::printf("%s axisymmetric Lame cylinder (%d particles in 0.6 <= r <= 0.9): mean (sigma - exact)/p: rr %.4f, "
              "thth %.4f, zz %.4f\n",
              GetParam(), n, d_rr, d_tt, d_zz);
  EXPECT_GT(n, 0);
  EXPECT_LT(std::abs(d_rr), 0.03);
  EXPECT_LT(std::abs(d_tt), 0.03);
  EXPECT_LT(std::abs(d_zz), 0.03);
}

TEST_P(AxisymmetricLoads, RodEndPressureGivesUniaxialStress) {
  set_thread_count(1);
  const double h = 1.0 / 16, R = 0.5, L = 1.0, p = 1.0e3, t_ramp = 20 * L / kC;
  std::ostringstream body, load;
  body.precision(17);
  load.precision(17);
  body << "<box label=\"rod\"><min>[0,0,0]</min><max>[" << R << "," << L << "," << h << "]</max></box>";
  // The end z = L: a thin cylinder from z = L + h/4 down to z = L - h/4
  // (the normal top - bottom points into the rod: compression for p > 0).
  load << "<pressure><geom_object><cylinder><bottom>[0," << L + h / 4 << ",0]</bottom><top>[0," << L - h / 4
       << ",0]</top><radius>" << R << "</radius><axisymmetric_end>true</axisymmetric_end></cylinder></geom_object>"
       << "<res>[2,2,1]</res>" << ramp(t_ramp, p) << "</pressure>";
  auto deck = load_deck_from_string(
      axi_deck(GetParam(), body.str(), load.str(), Vec3(0.75, 1.25, h), h, {"x-", "y-"}), "axi_rod.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  // The end load: one step of a fresh run started at t = t_ramp, where the
  // curve gives p (the loads are evaluated at the step's start time).
  {
    auto probe = make_mpm_component(*deck);
    probe->initialize();
    probe->advance(t_ramp, 1e-9, 1);
    const Particles& P = probe->materials()[0].particles;
    double fy = 0;
    for (std::size_t i = 0; i < P.size(); ++i) fy += P.external_force[i][1];
    std::printf("%s axisymmetric end load at p = %g Pa: sum f_y = %.12e N/rad, -p R^2/2 = %.12e\n", GetParam(), p, fy,
                -p * R * R / 2);
    EXPECT_NEAR(fy, -p * R * R / 2, 1e-9 * p * R * R);
  }
  // The ramp leaves the rod ringing in its fundamental (fixed-free) mode,
  // period T = 4 L / c_bar, c_bar = sqrt(E / rho), E = 9KG/(3K + G), with a
  // relative amplitude ~ 1/(omega t_ramp / 2) ~ 7 %: the stresses are
  // averaged over one period after the ramp (the oscillation's mean is 0).
  run_to(*c, t_ramp);
  const double E = 9 * kK * kG / (3 * kK + kG), period = 4 * L / std::sqrt(E / kRho);
  const Particles& P = c->materials()[0].particles;
  double d_zz = 0, d_rr = 0, d_tt = 0;
  int n = 0;
  double t = t_ramp;
  int step = 0;
  const double dt = 0.3 * c->stable_timestep();
  const int steps = int(std::ceil(period / dt));
  for (int k = 0; k < steps; ++k, t += period / steps) {
    c->advance(t, period / steps, ++step);
    for (std::size_t i = 0; i < P.size(); ++i) {
      const double z = P.x[i][1] - P.displacement[i][1], r = P.x[i][0] - P.displacement[i][0];
      if (z < 0.3 || z > 0.7 || r > 0.4) continue;
      d_zz += P.stress[i](1, 1) + p;
      d_rr += P.stress[i](0, 0);
      d_tt += P.stress[i](2, 2);
      ++n;
    }
  }
  d_zz /= n * p, d_rr /= n * p, d_tt /= n * p;
  std::printf("%s axisymmetric rod, end pressure (%d particle-steps in 0.3 <= z <= 0.7, r <= 0.4, one period): mean sigma/p: "
              "zz + 1 = %.4f, rr = %.4f, thth = %.4f\n",
              GetParam(), n, d_zz, d_rr, d_tt);
  EXPECT_GT(n, 0);
  EXPECT_LT(std::abs(d_zz), 0.03);
  EXPECT_LT(std::abs(d_rr), 0.03);
  EXPECT_LT(std::abs(d_tt), 0.03);
}

INSTANTIATE_TEST_SUITE_P(LinearGimpCpdi, AxisymmetricLoads, ::testing::Values("linear", "gimp", "cpdi"));

// Deck checks: an axisymmetric surface needs <axisymmetric>true (DeckError);
// a box pressure surface in an axisymmetric run has no per-radian area (exit 3).
TEST(AxisymmetricLoadsDeck, SurfacesMatchTheRunKind) {
  const double h = 0.125;
  const std::string body = "<box label=\"b\"><min>[0.25,0,0]</min><max>[0.5,0.25,0.125]</max></box>";
  const std::string box_load =
      "<pressure><geom_object><box><min>[0.25,0.25,0]</min><max>[0.5,0.25,0.125]</max></box></geom_object>" +
      ramp(1, 1) + "</pressure>";
  auto d1 = load_deck_from_string(axi_deck("linear", body, box_load, Vec3(1, 1, h), h, {"x-"}), "a.ups", ".");
  EXPECT_THROW(make_mpm_component(*d1), MissingFeature);
  std::string cartesian = axi_deck("linear", body,
                                   "<pressure><geom_object><cylinder><bottom>[0,0,0]</bottom><top>[0,1,0]</top>"
                                   "<radius>0.25</radius><axisymmetric_side>true</axisymmetric_side></cylinder>"
                                   "</geom_object>" + ramp(1, 1) + "</pressure>",
                                   Vec3(1, 1, h), h, {"x-"});
  cartesian.replace(cartesian.find("<axisymmetric>true</axisymmetric>"), 33, "");
  auto d2 = load_deck_from_string(cartesian, "b.ups", ".");
  EXPECT_THROW(make_mpm_component(*d2), DeckError);
}

}  // namespace
}  // namespace tephra
