// LODI characteristic outflow (ice/Lodi.h) against reflecting and
// zero-gradient ends.
//
// A 1-D air tube [0, 1] m, 200 cells, with a hot slab (T 330 K instead of
// 300 K, same density: p 10 % above ambient) in [0.45, 0.55]: the pressure
// excess splits into two acoustic pulses of about 5 % that travel to the
// ends at c = sqrt(gamma R T) ~ 347 m/s; the entropy spot stays in the middle
// at ambient pressure. The incident amplitude A is measured at t = 0.8 ms in
// [0.6, 1] (the right pulse on its way out). At t = 2.2 ms the right pulse has
// left (its tail reaches x = 1 at 1.59 ms) and whatever it reflected sits near
// x = 0.84; the reflection coefficient is R = max |p - p_inf| over [0.6, 1]
// at 2.2 ms divided by A. Oracles: a symmetry wall reflects fully (R ~ 1);
// linear theory of the relaxed outflow (Poinsot & Lele 1992, sec. 4.2):
// R(omega) = 1/sqrt(1 + (2 omega/K)^2) with K = sigma c/L, here
// K/(2 omega) ~ 0.27 * 0.1 m/(2 pi * 1 m) ~ 0.004, so LODI's reflection must
// be small (asserted < 3 %) and well below the zero-gradient (Neumann) end's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "ice/IceComponent.h"

namespace tephra {
namespace {

constexpr double kRho = 1.1768, kCv = 716.0, kT = 300.0;
const double kPinf = 0.4 * kRho * kCv * kT;  // ideal gas p = (gamma - 1) rho c_v T

std::string tube_deck(const std::string& end, int n, const std::string& lodi_block = "") {
  std::ostringstream x;
  x.precision(17);
  const double h = 1.0 / n;
  x << R"(<Uintah_specification><Meta><title>lodi pulse</title></Meta><SimulationComponent type="ice"/>
  <Time><maxTime>1</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max></Time>
  <DataArchiver><filebase>lodi.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>0.4</cfl><ICE><advection type="SecondOrder"/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE><material name="air"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
   <thermal_conductivity>0</thermal_conductivity><specific_heat>)" << kCv << R"(</specific_heat><gamma>1.4</gamma>
   <geom_object><difference><box label="all"><min>[-1,-1,-1]</min><max>[2,2,2]</max></box>
     <box label="hot"><min>[0.45,-1,-1]</min><max>[0.55,2,2]</max></box></difference>
    <res>[2,1,1]</res><velocity>[0,0,0]</velocity><density>)" << kRho << R"(</density><pressure>101325</pressure>
    <temperature>)" << kT << R"(</temperature></geom_object>
   <geom_object><box label="hot"/><res>[2,1,1]</res><velocity>[0,0,0]</velocity><density>)" << kRho
    << R"(</density><pressure>101325</pressure><temperature>330</temperature></geom_object></material></ICE>
  </MaterialProperties>
  <Grid><BoundaryConditions>)" << lodi_block;
  for (const char* side : {"x-", "x+"}) {
    x << "<Face side=\"" << side << "\">";
    if (end == "symmetry") {
      x << R"(<BCType id="0" label="Symmetric" var="symmetry"/>)";
    } else {
      const std::string v = end == "LODI" ? "LODI" : "Neumann";
      x << R"(<BCType id="0" label="Pressure" var=")" << v << R"("><value>0</value></BCType>
        <BCType id="0" label="Velocity" var=")" << v << R"("><value>[0,0,0]</value></BCType>
        <BCType id="0" label="Temperature" var=")" << v << R"("><value>0</value></BCType>
        <BCType id="0" label="Density" var=")" << v << R"("><value>0</value></BCType>
        <BCType id="0" label="SpecificVol" var="computeFromDensity"><value>0</value></BCType>)";
    }
    x << "</Face>";
  }
  for (const char* side : {"y-", "y+", "z-", "z+"})
    x << "<Face side=\"" << side << R"("><BCType id="0" label="Symmetric" var="symmetry"/></Face>)";
  x << R"(</BoundaryConditions><Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,)" << h << "," << h
    << R"(]</upper><resolution>[)" << n << R"(,1,1]</resolution><extraCells>[1,1,1]</extraCells>
   <patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>)";
  return x.str();
}

std::string lodi_block(const char* material = "air") {
  std::ostringstream x;
  x.precision(17);
  x << "<LODI><press_infinity>" << kPinf << "</press_infinity><sigma>0.27</sigma><material>" << material
    << "</material></LODI>";
  return x.str();
}

struct Reflection {
  double incident = 0, reflected = 0;
};

// Max |p - p_inf| over cells with x in [0.6, 1] at 0.8 ms and at 2.2 ms.
Reflection measure(const std::string& end) {
  set_thread_count(1);
  auto deck = load_deck_from_string(tube_deck(end, 200, end == "LODI" ? lodi_block() : ""), "lodi.ups", ".");
  auto ice = make_ice_component(*deck);
  ice->initialize();
  const Grid& g = ice->grid();
  auto excess = [&] {
    double a = 0;
    for (int i = 0; i < g.cells[0]; ++i)
      if (g.cell_center(i, 0, 0)[0] >= 0.6) a = std::max(a, std::abs(ice->press_CC()[0](i, 0, 0) - kPinf));
    return a;
  };
  Reflection r;
  double t = 0;
  int step = 0;
  for (double t_stop : {0.8e-3, 2.2e-3}) {
    while (t < t_stop * (1 - 1e-12)) {
      const double dt = std::min(ice->stable_timestep(), t_stop - t);
      ice->advance(t, dt, ++step);
      t += dt;
    }
    (t_stop < 1e-3 ? r.incident : r.reflected) = excess();
  }
  std::printf("%-9s ends: incident %.1f Pa, after reflection %.2f Pa, R = %.4f\n", end.c_str(), r.incident,
              r.reflected, r.reflected / r.incident);
  return r;
}

TEST(IceLodi, OutflowPulseLeavesWithSmallReflection) {
  const Reflection wall = measure("symmetry"), neumann = measure("Neumann"), lodi = measure("LODI");
  // The incident pulse is the same in all three runs (nothing has reached the ends yet).
  EXPECT_NEAR(lodi.incident, wall.incident, 1e-9 * wall.incident);
  EXPECT_GT(lodi.incident, 0.03 * kPinf);  // ~5 % pulse
  EXPECT_GT(wall.reflected / wall.incident, 0.8);  // reflecting wall
  EXPECT_LT(lodi.reflected / lodi.incident, 0.03);
  EXPECT_LT(lodi.reflected, 0.5 * neumann.reflected);
}

TEST(IceLodi, DeckChecks) {
  // A LODI face without the <LODI> block, and a <LODI> naming no ICE material.
  EXPECT_THROW(make_ice_component(*load_deck_from_string(tube_deck("LODI", 20), "a.ups", ".")), DeckError);
  EXPECT_THROW(make_ice_component(*load_deck_from_string(tube_deck("LODI", 20, lodi_block("steel")), "b.ups", ".")),
               DeckError);
  EXPECT_NO_THROW(make_ice_component(*load_deck_from_string(tube_deck("LODI", 20, lodi_block("0")), "c.ups", ".")));
}

}  // namespace
}  // namespace tephra
