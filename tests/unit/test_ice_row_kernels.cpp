// The ICE hot loops as row kernels (ice/RowLoop.h; IceStep.cpp, IceAdvection.cpp,
// IceEnergy.cpp, IceComponent.cpp). Claims:
//   * every row kernel writes only the entries of its own (j, k) row, so a
//     step gives the same bits with 1 and 2 threads (one and two materials,
//     24 x 24 x 16 cells: above kMinCellsPerParallelLoop, so the loops split);
//   * the one-material shortcut of sum_volume_flux_and_kappa: with theta = 1
//     in every cell the limited slopes are 0 and the second-order flux of
//     theta is phi = u dt/dx itself, bit for bit (density_fluxes computes it);
//   * check_outflux (threaded screen) still reports the first failing cell in
//     (k, j, i) order, and a cell that loses exactly its content (fraction
//     1, not > 1) passes.
#include <gtest/gtest.h>

#include <random>
#include <span>
#include <sstream>
#include <string>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "ice/IceAdvection.h"
#include "ice/IceComponent.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

// Ideal-gas box n x n x nz, second order, symmetry walls; material m fills the slab
// m/nm < x < (m+1)/nm with a hot, fast-moving upper half (3-D flow).
std::string box_deck(int n, int nz, int nm) {
  std::ostringstream x;
  x << R"(<?xml version="1.0"?><Uintah_specification><Meta><title>rows</title></Meta>
  <SimulationComponent type="ice"/>
  <Time><maxTime>1</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max>
    <timestep_multiplier>1</timestep_multiplier></Time>
  <DataArchiver><filebase>rows.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>0.4</cfl><ICE><advection type="SecondOrder"/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>)";
  for (int m = 0; m < nm; ++m) {
    const double x0 = double(m) / nm, x1 = double(m + 1) / nm;
    x << R"(<material><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>716</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="a)" << m << R"("><min>[)" << x0 << R"(,0,0]</min><max>[)" << x1
      << R"(,0.5,1]</max></box><res>[2,2,2]</res><velocity>[0,0,0]</velocity><density>)" << 1.1768 * (1 + m)
      << R"(</density><pressure>101325</pressure><temperature>)" << 300 + 50 * m << R"(</temperature></geom_object>
      <geom_object><box label="b)" << m << R"("><min>[)" << x0 << R"(,0.5,0]</min><max>[)" << x1
      << R"(,1,1]</max></box><res>[2,2,2]</res><velocity>[0,0,30]</velocity><density>)" << 1.5 * (1 + m)
      << R"(</density><pressure>101325</pressure><temperature>)" << 400 + 50 * m
      << R"(</temperature></geom_object></material>)";
  }
  x << "</ICE>";
  if (nm > 1)
    x << "<exchange_properties><exchange_coefficients><momentum>1e10</momentum><heat>1e10</heat>"
         "</exchange_coefficients></exchange_properties>";
  x << R"(</MaterialProperties><Grid><BoundaryConditions>)";
  for (const char* side : {"x-", "x+", "y-", "y+", "z-", "z+"})
    x << "<Face side=\"" << side << R"("><BCType id="all" label="Symmetric" var="symmetry"/></Face>)";
  x << R"(</BoundaryConditions><Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,1,1]</upper>
    <resolution>[)" << n << "," << n << "," << nz << R"(]</resolution><extraCells>[1,1,1]</extraCells>
    <patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>)";
  return x.str();
}

// The state after `steps` steps with `threads` threads.
std::unique_ptr<IceComponent> run_box(int nm, int threads, int steps) {
  ThreadCountScope t(threads);
  auto deck = load_deck_from_string(box_deck(24, 16, nm), "rows.ups", ".");
  auto ice = make_ice_component(*deck);
  ice->initialize();
  double time = 0;
  for (int s = 1; s <= steps; ++s) {
    const double dt = ice->stable_timestep();
    ice->advance(time, dt, s);
    time += dt;
  }
  return ice;
}

template <class Field>
void expect_same_bits(const Field& a, const Field& b, const char* what) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t pi = 0; pi < a.size(); ++pi) {
    ASSERT_EQ(a[pi].size(), b[pi].size());
    std::size_t differ = 0;
    for (std::size_t e = 0; e < a[pi].size(); ++e)
      if (!(a[pi].data()[e] == b[pi].data()[e])) ++differ;
    EXPECT_EQ(differ, 0u) << what;
  }
}

void expect_thread_independent(int nm) {
  const auto one = run_box(nm, 1, 2), two = run_box(nm, 2, 2);
  expect_same_bits(one->press_CC(), two->press_CC(), "press_CC");
  expect_same_bits(one->delP_Dilatate(), two->delP_Dilatate(), "delP_Dilatate");
  for (int m = 0; m < nm; ++m) {
    const IceMaterialFields &a = one->fields()[m], &b = two->fields()[m];
    expect_same_bits(a.rho_CC, b.rho_CC, "rho_CC");
    expect_same_bits(a.vel_CC, b.vel_CC, "vel_CC");
    expect_same_bits(a.temp_CC, b.temp_CC, "temp_CC");
    expect_same_bits(a.sp_vol_CC, b.sp_vol_CC, "sp_vol_CC");
    expect_same_bits(a.vol_frac_CC, b.vol_frac_CC, "vol_frac_CC");
    expect_same_bits(a.mom_L_ME_CC, b.mom_L_ME_CC, "mom_L_ME_CC");
  }
  // The flow did move (the step did work): the upper half's z-velocity spread.
  EXPECT_NE(one->fields()[0].vel_CC[0](3, 11, 5)[1], 0.0);
}

TEST(IceRowKernels, OneMaterialStepIsBitIdenticalForOneAndTwoThreads) { expect_thread_independent(1); }
TEST(IceRowKernels, TwoMaterialStepIsBitIdenticalForOneAndTwoThreads) { expect_thread_independent(2); }

Grid box_grid(int n) {
  std::ostringstream x;
  x << "<Uintah_specification><Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1,1,1]</upper>"
    << "<resolution>[" << n << "," << n << "," << n << "]</resolution><extraCells>[1,1,1]</extraCells>"
    << "<patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(x.str(), "grid.ups", ".");
  return make_grid(deck->root.require_child("Grid"));
}

TEST(IceRowKernels, UnitVolumeFractionFluxIsPhi) {
  const Grid g = box_grid(12);
  CellScalars theta(g, 2);
  theta.fill(1.0);
  FaceScalars u(g, 0), flux(g, 0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> s(-40.0, 40.0);
  for (int d = 0; d < 3; ++d)
    for (double& v : std::span<double>(u.at(d, 0).data(), u.at(d, 0).size())) v = s(rng);
  u.at(1, 0)(4, 5, 6) = 0.0;  // a face at rest: flux exactly 0
  const double dt = 1e-4;
  density_fluxes(g, AdvectionOrder::Second, theta, u, dt, flux);
  long long faces = 0;
  for (int d = 0; d < 3; ++d)
    for_each_cell_serial({g.patches[0].lo, g.patches[0].hi + IntVec3::Unit(d)}, [&](int i, int j, int k) {
      const double phi = u.at(d, 0)(i, j, k) * (dt / g.dx[d]);
      ASSERT_EQ(flux.at(d, 0)(i, j, k), phi == 0.0 ? 0.0 : phi) << d << " " << i << " " << j << " " << k;
      ++faces;
    });
  EXPECT_EQ(faces, 3LL * 13 * 12 * 12);
}

TEST(IceRowKernels, OutfluxCheckNamesTheFirstCellInKJIOrder) {
  const int n = 24;  // 13824 cells: the screen runs on two threads
  ThreadCountScope t(2);
  const Grid g = box_grid(n);
  FaceScalars u(g, 0);
  for (int d = 0; d < 3; ++d) u.at(d, 0).fill(0.0);
  const double dt = 1.0, dx = g.dx[0];
  // Exactly its content out of cell (1,1,1) through its high x face: fraction dx dt/dx = 1, allowed.
  u.at(0, 0)(2, 1, 1) = dx / dt;
  EXPECT_NO_THROW(check_outflux(g, u, dt, 7));
  // Three cells losing 1.5 of their content; the first in (k, j, i) order is (20,3,9).
  u.at(0, 0)(6, 7, 9) = 1.5 * dx / dt;    // cell (5,7,9), high x face
  u.at(1, 0)(20, 3, 9) = -1.5 * dx / dt;  // cell (20,3,9), low y face
  u.at(2, 0)(3, 2, 13) = 1.5 * dx / dt;   // cell (3,2,12), high z face
  try {
    check_outflux(g, u, dt, 7);
    FAIL() << "no NumericalFailure";
  } catch (const NumericalFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("step 7: cell (20,3,9) would lose a fraction 1.5 > 1"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace tephra
