// Hydrostatic pressure boundary condition of ICE (ice/IceBoundary.h,
// apply_hydrostatic_pressure_bc; Uintah's HydrostaticPressureAdjustment):
// with gravity on, the pressure in an extra cell carries the weight of the
// fluid between it and the inner cell, so a fluid at rest in a closed or
// pressure-held column stays at rest.
//
// Exact discrete steady state: a column of one ideal gas at constant density
// rho0 with p(y) = p0 + rho0 g_y (y - y0) (g_y = -9.81 m/s^2, y0 the centre
// of the bottom cell) and T(y) = p(y)/(rho0 R), R = (gamma - 1) c_v, u = 0.
// In the ICE step it is steady to round-off: the face velocity of eq. 26.1,
//   u_f = -dt 2 v_L v_R/(v_L + v_R) (p_R - p_L)/dy + g_y dt,
// is zero because (p_R - p_L)/dy = rho0 g_y and v = 1/rho0; the cell-centred
// momentum source -V grad(p_face) + M g (eq. 26.5) is zero because the
// face pressures (p_L rho_R + p_R rho_L)/(rho_L + rho_R) are linear in y;
// no advection at u = 0, no conduction (k = 0). Only the extra cells can
// break it: without the adjustment a symmetry or zero-gradient wall puts the
// inner cell's p in the extra cell, the wall-face pressure misses
// rho0 g dy/2 and the end cells accelerate at about g/2 (max|v| of order
// g t = 171 m/s over this run; docs/algorithms/ice.md "Gravity"). With it, p_e = p_i +
// g_n dy (rho_i + rho_e)/2 on the walls, and on a Dirichlet face holding
// the reference pressure p0 of cell (0,0,0), p_e = p0 + rho_e g . (x_e - x_0):
// both give the extra cells the linear profile exactly.
//
// Checks, after 300 steps (t = 17.45 s): max|v| over the column below
// 1e-9 g t (round-off), and every cell's pressure equal to
// p0 + rho0 g_y (y - y0) to 1e-12 relative; for (a) all six faces symmetry
// planes, (b) y+ a Dirichlet pressure face (the open top of a pressure-held
// column). Measured: max|v| 7.1e-13 and 6.0e-13 m/s, max|p/p_exact - 1|
// 7.8e-16 in both.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "ice/IceComponent.h"
#include "mpmice/ComponentFactory.h"

namespace tephra {
namespace {

constexpr double kH = 1000.0, kG = 9.81, kRho0 = 1.2, kP0 = 101325.0;
constexpr double kCv = 716.5, kGamma = 1.4, kR = (kGamma - 1) * kCv;
constexpr int kN = 20;
constexpr double kDy = kH / kN;

double p_exact(double y) { return kP0 - kRho0 * kG * (y - 0.5 * kDy); }

std::string column_deck(bool dirichlet_top) {
  std::ostringstream s;
  s.precision(17);
  s << R"(<Uintah_specification>
  <SimulationComponent type="ice"/>
  <Grid><BoundaryConditions>)";
  for (const char* f : {"x-", "x+", "y-", "y+", "z-", "z+"}) {
    if (dirichlet_top && std::string(f) == "y+") {
      s << "<Face side=\"y+\"><BCType id=\"all\" var=\"Dirichlet\" label=\"Pressure\"><value>" << kP0
        << R"(</value></BCType>
        <BCType id="all" var="Dirichlet" label="Velocity"><value>[0,0,0]</value></BCType>
        <BCType id="all" var="Neumann" label="Temperature"><value>0</value></BCType>
        <BCType id="all" var="Neumann" label="Density"><value>0</value></BCType>
        <BCType id="all" var="computeFromDensity" label="SpecificVol"><value>0</value></BCType></Face>)";
    } else {
      s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/></Face>";
    }
  }
  s << R"(</BoundaryConditions>
    <Level><Box label="1"><lower>[0,0,0]</lower><upper>[)" << kDy << "," << kH << "," << kDy << R"(]</upper>
      <extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches><resolution>[1,)" << kN << R"(,1]</resolution></Box></Level>
  </Grid>
  <CFD><cfl>0.4</cfl><ICE><advection type="SecondOrder"/></ICE></CFD>
  <PhysicalConstants><gravity>[0,)" << -kG << R"(,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
    <material name="air"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>)" << kCv << R"(</specific_heat><gamma>)" << kGamma
    << "</gamma>\n";
  for (int j = -1; j <= kN; ++j) {  // one layer per cell row, at its exact state
    const double y0 = j * kDy, y1 = (j + 1) * kDy, p = p_exact((j + 0.5) * kDy);
    s << "<geom_object><box label=\"l" << j << "\"><min>[-1e6," << y0 << ",-1e6]</min><max>[1e6," << y1
      << ",1e6]</max></box><res>[1,1,1]</res><velocity>[0,0,0]</velocity><temperature>" << p / (kRho0 * kR)
      << "</temperature><density>" << kRho0 << "</density><pressure>" << p << "</pressure></geom_object>\n";
  }
  s << R"(</material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>[]</momentum><heat>[]</heat></exchange_coefficients></exchange_properties>
  </MaterialProperties>
</Uintah_specification>
)";
  return s.str();
}

void expect_column_at_rest(bool dirichlet_top) {
  auto d = load_deck_from_string(column_deck(dirichlet_top), "hydrostatic.ups", ".");
  auto ice = make_ice_component(*d);
  ice->initialize();
  double t = 0;
  for (int step = 1; step <= 300; ++step) {
    const double dt = ice->stable_timestep();
    ice->advance(t, dt, step);
    t += dt;
  }
  const auto& ic = dynamic_cast<const IceComponent&>(*ice);
  const auto& f = ic.fields()[0];
  double max_v = 0, max_dp = 0;
  for (int j = 0; j < kN; ++j) {
    max_v = std::max(max_v, f.vel_CC[0](0, j, 0).norm());
    max_dp = std::max(max_dp, std::abs(ic.press_CC()[0](0, j, 0) / p_exact((j + 0.5) * kDy) - 1));
  }
  std::printf("%s: t = %.3f s, max|v| = %.3e m/s (g t = %.3g), max|p/p_exact - 1| = %.3e\n",
              dirichlet_top ? "Dirichlet top" : "closed column", t, max_v, kG * t, max_dp);
  EXPECT_GT(t, 0.5);  // long enough for the walls' g/2 error to show as m/s
  EXPECT_LT(max_v, 1e-9 * kG * t);
  EXPECT_LT(max_dp, 1e-12);
}

TEST(IceHydrostaticBc, ClosedColumnAtRestStaysAtRest) { expect_column_at_rest(false); }

TEST(IceHydrostaticBc, PressureHeldColumnAtRestStaysAtRest) { expect_column_at_rest(true); }

}  // namespace
}  // namespace tephra
