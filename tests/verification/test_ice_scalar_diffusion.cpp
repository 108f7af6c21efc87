// Diffusion of a PassiveScalar (<constants><diffusivity> D; ice/models/
// FluidModels.cpp), the scalar-diffusion part SimpleRxn also needs.
//
// Closed tube of uniform air at rest (symmetry faces: no pressure gradient,
// every face velocity 0, nothing advected), N cells along x over L = 1 m,
// one cell across. The scalar starts as a step, q = 1 for x < L/2, else 0.
// With rho uniform and u = 0 the model source makes q obey q_t = D q_xx,
// whose solution on the infinite line is (heat equation, error function)
//   q(x, t) = erfc((x - L/2) / (2 sqrt(D t))) / 2;
// at D t = 2.5e-3 m^2 (sqrt(4 D t) = 0.1 m) the walls at 0 and L are 5 diffusion
// lengths away: their effect is below erfc(5)/2 ~ 8e-13.
// Checks: L1 error against the erf solution falls at second order (forward
// Euler in time at dt ~ dx^2 and the 3-point Laplacian are both O(dx^2));
// Sum M q conserved to round-off (no-flux walls, rho uniform). Two patches
// along x (the Laplacian reads across the patch boundary).
// Measured: N = 50/100/200: L1 3.83e-4, 9.47e-5, 2.36e-5 (orders 2.02, 2.01);
// Sum M q drift 6.7e-16, 7.8e-16, 2.4e-15.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "ice/IceComponent.h"
#include "mpmice/ComponentFactory.h"

namespace tephra {
namespace {

constexpr double kD = 1.0;        // m^2/s (large, so that diffusion, not sound, sets the time scale)
constexpr double kTEnd = 2.5e-3;  // s: D t = 2.5e-3 m^2

std::string tube_deck(int n) {
  const double dx = 1.0 / n;
  std::ostringstream s;
  s.precision(17);
  s << R"(<Uintah_specification>
  <SimulationComponent type="ice"/>
  <Grid><BoundaryConditions>)";
  for (const char* f : {"x-", "x+", "y-", "y+", "z-", "z+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/></Face>";
  s << R"(</BoundaryConditions>
    <Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,)" << dx << "," << dx << R"(]</upper>
      <extraCells>[1,1,1]</extraCells><patches>[2,1,1]</patches><resolution>[)" << n << R"(,1,1]</resolution></Box></Level>
  </Grid>
  <CFD><cfl>0.4</cfl><ICE><advection type="SecondOrder"/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
    <material name="air"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>716.5</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="all"><min>[-1,-1,-1]</min><max>[2,2,2]</max></box><res>[2,2,2]</res>
        <velocity>[0,0,0]</velocity><temperature>300</temperature><density>1.1792946927374306</density>
        <pressure>101325</pressure></geom_object>
    </material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>[]</momentum><heat>[]</heat></exchange_coefficients></exchange_properties>
  </MaterialProperties>
  <Models><Model type="PassiveScalar"><scalar name="f"><material>air</material>
    <constants><diffusivity>)" << kD << R"(</diffusivity></constants>
    <geom_object><box label="left"><min>[-1,-1,-1]</min><max>[0.5,2,2]</max></box><scalar>1</scalar></geom_object>
  </scalar></Model></Models>
</Uintah_specification>
)";
  return s.str();
}

struct TubeResult {
  double l1 = 0;         // L1(q - erf solution) over [0, 1]
  double sum_drift = 0;  // |Sum M q / initial - 1|
  int steps = 0;
};

TubeResult run_tube(int n) {
  auto d = load_deck_from_string(tube_deck(n), "scalar_diffusion.ups", ".");
  auto ice = make_ice_component(*d);
  ice->initialize();
  const std::set<std::string> label{"totalSum_scalar-f"};
  const double sum0 = ice->reductions(label).at("totalSum_scalar-f")[0];
  double t = 0;
  int step = 0;
  while (t < kTEnd * (1 - 1e-12)) {
    // dt = 0.05 dx^2/D (below both the acoustic and the diffusion limit for
    // N = 50...200): the forward-Euler error (dt/2) D^2 q_xxxx is then a fixed
    // fraction (6 D dt/dx^2 = 0.3) of the Laplacian's D dx^2/12 q_xxxx.
    const double dx = 1.0 / n;
    const double dt = std::min({ice->stable_timestep(), 0.05 * dx * dx / kD, kTEnd - t});
    ice->advance(t, dt, ++step);
    t += dt;
  }
  const auto& ic = dynamic_cast<const IceComponent&>(*ice);
  TubeResult r;
  r.steps = step;
  r.sum_drift = std::abs(ice->reductions(label).at("totalSum_scalar-f")[0] / sum0 - 1);
  const IceModel& model = *ic.models()[0];
  const CellScalars* q = nullptr;
  for (const ModelField& f : model.fields())
    if (f.label == "scalar-f") q = f.field;
  EXPECT_NE(q, nullptr);
  const double dx = 1.0 / n;
  const Grid& g = ic.grid();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int i = g.patches[pi].cells().lo[0]; i < g.patches[pi].cells().hi[0]; ++i) {
      const double x = (i + 0.5) * dx;
      const double exact = 0.5 * std::erfc((x - 0.5) / (2 * std::sqrt(kD * t)));
      r.l1 += std::abs((*q)[pi](i, 0, 0) - exact) * dx;
    }
  return r;
}

TEST(IceScalarDiffusion, StepDiffusesAsTheErfSolution) {
  const int ns[3] = {50, 100, 200};
  TubeResult r[3];
  for (int i = 0; i < 3; ++i) {
    r[i] = run_tube(ns[i]);
    std::printf("N = %3d: %d steps, L1(q - erfc) = %.3e, |sum M q drift| = %.1e\n", ns[i], r[i].steps, r[i].l1,
                r[i].sum_drift);
    EXPECT_LT(r[i].sum_drift, 1e-13);
  }
  for (int i = 1; i < 3; ++i) {
    const double order = std::log2(r[i - 1].l1 / r[i].l1);
    std::printf("order %d -> %d: %.2f\n", ns[i - 1], ns[i], order);
    EXPECT_GT(order, 1.8);
  }
}

TEST(IceScalarDiffusion, TimeStepObeysTheForwardEulerLimit) {
  // dt <= 1/(2 D sum_d 1/dx_d^2), dx = 1/200 in all three directions:
  // 1/(2 * 1 * 3 * 40000) = 4.17e-6 s, below the acoustic cfl 0.4 dx/c =
  // 5.8e-6 s (c = 347 m/s), so it is the component's time step.
  auto d = load_deck_from_string(tube_deck(200), "scalar_diffusion.ups", ".");
  auto ice = make_ice_component(*d);
  ice->initialize();
  const auto& ic = dynamic_cast<const IceComponent&>(*ice);
  const double limit = 0.5 / (kD * 3 * 200.0 * 200.0);
  EXPECT_NEAR(ic.models()[0]->stable_timestep(), limit, 1e-14 * limit);
  EXPECT_NEAR(ice->stable_timestep(), limit, 1e-14 * limit);
}

TEST(IceScalarDiffusion, NegativeDiffusivityIsADeckError) {
  std::string deck = tube_deck(10);
  const std::string from = "<diffusivity>1</diffusivity>";
  const auto at = deck.find(from);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, from.size(), "<diffusivity>-1</diffusivity>");
  auto d = load_deck_from_string(deck, "scalar_diffusion.ups", ".");
  EXPECT_THROW(make_ice_component(*d), DeckError);
}

}  // namespace
}  // namespace tephra
