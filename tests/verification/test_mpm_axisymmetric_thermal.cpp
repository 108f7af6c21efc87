// Axisymmetric heat conduction (mpm/thermal/HeatConduction.cpp with the
// axisymmetric stencils: in-plane gradients, per-radian volumes and masses,
// so the node sums are the Galerkin form of rho c_v dT/dt = (1/r) d/dr (k r dT/dr)).
//
// A solid cylinder 0 <= r <= a = 1 m, insulated everywhere (no temperature
// BC: zero flux), with T(r, 0) = T0 + A J0(k r). The regular solutions of
// the radial heat equation with dT/dr(a) = 0 are
//   T(r, t) = T0 + A J0(k r) exp(-alpha k^2 t),  J0'(k a) = -J1(k a) = 0,
// so k a = j_{1,1} = 3.8317059702075123, alpha = k_th / (rho c_v).
// Run to alpha k^2 t = 1 (the mode decays to 1/e) at 16 and 32 cells; the
// error is the rms over the particles of (T_p - T(r_p, t)) / A. The time
// step is a fixed fraction of the conduction limit (dt ~ h^2), so the
// forward-Euler error is O(h^2) too: observed order >= 1.8 asserted.
// The thermal energy per radian sum m_p c_v T_p is conserved to round-off
// (insulated faces; HeatConduction.h).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

constexpr double kJ11 = 3.8317059702075123;  // first positive zero of J1

std::string thermal_deck(const std::string& interp, int cells) {
  const double h = 1.0 / cells;
  std::ostringstream s;
  s.precision(17);
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator><axisymmetric>true</axisymmetric></MPM>"
    << "<MaterialProperties><MPM><material><density>1000</density><thermal_conductivity>1000</thermal_conductivity>"
    << "<specific_heat>1</specific_heat><constitutive_model type=\"hypo_elastic\"><K>6e6</K><G>3e6</G>"
    << "</constitutive_model><geom_object><box label=\"rod\"><min>[0,0,0]</min><max>[1.0," << 2 * h << "," << h
    << "]</max></box><res>[2,2,1]</res><velocity>[0,0,0]</velocity><temperature>300</temperature>"
    << "</geom_object></material></MPM></MaterialProperties><Grid><BoundaryConditions>";
  for (const char* f : {"x-", "x+", "y-", "y+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"></BCType></Face>";
  s << "</BoundaryConditions><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1.0," << 2 * h << "," << h
    << "]</upper><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box><spacing>[" << h << "," << h << ","
    << h << "]</spacing></Level></Grid></Uintah_specification>";
  return s.str();
}

struct ThermalResult {
  double error = 0;         // rms (T - exact) / A
  double energy_drift = 0;  // |sum m c T - start| / sum m c |T - T0| at start
  int steps = 0;
};

ThermalResult radial_conduction(const std::string& interp, int cells) {
  set_thread_count(1);
  auto deck = load_deck_from_string(thermal_deck(interp, cells), "axi_heat.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  Particles& p = c->materials()[0].particles;
  const double T0 = 300, A = 10, k = kJ11, alpha = 1000.0 / (1000.0 * 1.0);
  auto energy = [&] {
    double e = 0;
    for (std::size_t i = 0; i < p.size(); ++i) e += p.mass[i] * p.temperature[i];  // c_v = 1
    return e;
  };
  double scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.temperature[i] = T0 + A * std::cyl_bessel_j(0.0, k * p.x[i][0]);
    scale += p.mass[i] * std::abs(p.temperature[i] - T0);
  }
  const double e0 = energy();
  const double t_end = 1.0 / (alpha * k * k);
  const double h = 1.0 / cells;
  // The conduction limit h^2 / (4 alpha) (two in-plane directions), a quarter of it.
  const int n = int(std::ceil(t_end / (0.25 * h * h / (4 * alpha))));
  const double dt = t_end / n;
  EXPECT_LE(dt, c->stable_timestep());
  double t = 0;
  for (int step = 1; step <= n; ++step, t += dt) c->advance(t, dt, step);
  double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double exact = T0 + A * std::cyl_bessel_j(0.0, k * p.x[i][0]) * std::exp(-alpha * k * k * t_end);
    sum += std::pow((p.temperature[i] - exact) / A, 2);
  }
  ThermalResult r;
  r.error = std::sqrt(sum / p.size());
  r.energy_drift = std::abs(energy() - e0) / scale;
  r.steps = n;
  return r;
}

class AxisymmetricConduction : public ::testing::TestWithParam<const char*> {};

TEST_P(AxisymmetricConduction, BesselModeDecaysAtSecondOrder) {
  const ThermalResult r16 = radial_conduction(GetParam(), 16), r32 = radial_conduction(GetParam(), 32);
  const double order = std::log2(r16.error / r32.error);
  std::printf("%s axisymmetric J0 conduction mode at alpha k^2 t = 1: rms error / A %.4e (16 cells, %d steps), "
              "%.4e (32 cells, %d steps), order %.3f; energy drift %.2e, %.2e\n",
              GetParam(), r16.error, r16.steps, r32.error, r32.steps, order, r16.energy_drift, r32.energy_drift);
  EXPECT_LT(r32.error, 5e-3);
  EXPECT_GE(order, 1.8);
  EXPECT_LT(r16.energy_drift, 1e-12);
  EXPECT_LT(r32.energy_drift, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(LinearGimpCpdi, AxisymmetricConduction, ::testing::Values("linear", "gimp", "cpdi"));

}  // namespace
}  // namespace tephra
