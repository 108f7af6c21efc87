// ICE advection (step 10, ice/IceAdvection.h) against exact transport.
//
// 1. The advection operator alone on a periodic 1-D grid with a uniform face
//    velocity u: q_t + u q_x = 0 has the exact solution q(x - u t); after one
//    period (t = L/u) the profile must return to q0. For the smooth
//    q0 = 1 + 0.5 sin(2 pi x) the L1 error E_N = sum |q - q0| dx must fall at
//    the order of the scheme (3 resolutions: 128/256/512 cells first order,
//    whose error on coarser grids is pre-asymptotic, 32/64/128 second order): ~1 for FirstOrder (donor cell, leading error
//    u dx (1 - phi)/2 q_xx), ~2 for SecondOrder (limited slopes; the limiter
//    clips only O(dx)-wide regions at the two extrema, which costs O(dx^3) in
//    L1). Observed order = log2(E_N / E_2N).
//    The specific quantity psi carried by the mass fluxes (compatible
//    fluxes): (rho psi)_t + (u rho psi)_x = 0 with rho and psi both smooth;
//    psi = (rho psi)/rho returns to psi0 with the same orders. At second
//    order the donor outflow bounds of ice/AdvectionBounds.h are applied as
//    in the ICE step (inactive on this smooth profile: same orders).
// 2. A square block of a second material in a periodic box moving at a
//    uniform velocity through the full ICE step (both orders): the total mass
//    of each material is a sum of telescoping face fluxes, so it is
//    conserved to round-off; volume fractions stay in [0, 1] and sum to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/HaloExchange.h"
#include "core/grid/Loop.h"
#include "ice/AdvectionBounds.h"
#include "ice/IceAdvection.h"
#include "ice/IceComponent.h"

namespace tephra {
namespace {

constexpr double kPi = 3.14159265358979323846;

Grid periodic_line(int n, int patches) {
  std::ostringstream x;
  const double h = 1.0 / n;
  x << "<Uintah_specification><Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1," << h << "," << h
    << "]</upper><resolution>[" << n << ",1,1]</resolution><extraCells>[0,0,0]</extraCells><patches>[" << patches
    << ",1,1]</patches></Box><periodic>[1,1,1]</periodic></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(x.str(), "line.ups", ".");
  return make_grid(deck->root.require_child("Grid"));
}

struct LineErrors {
  double q = 0, psi = 0;
};

// One period of transport at u = 1 with Courant number 0.5 (2N steps).
LineErrors advect_one_period(int n, AdvectionOrder order) {
  set_thread_count(1);  // 1-D lines: loop-helper threads cost more than they save
  const Grid g = periodic_line(n, 2);
  LocalHaloExchange halo(g);
  CellScalars q(g, 2), mass(g, 2), psi(g, 2), dq(g, 2), dm(g, 2), dpsi(g, 2), limit(g, 2);
  FaceScalars u(g, 0), flux(g, 0), mflux(g, 0), pflux(g, 0);
  u.x.fill(1.0);
  u.y.fill(0.0);
  u.z.fill(0.0);
  auto q0 = [](double x) { return 1.0 + 0.5 * std::sin(2 * kPi * x); };
  auto rho0 = [](double x) { return 1.0 + 0.3 * std::cos(2 * kPi * x); };
  auto psi0 = [](double x) { return 2.0 + std::sin(2 * kPi * x) * std::sin(2 * kPi * x); };
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const double x = g.cell_center(i, j, k)[0];
      q[pi](i, j, k) = q0(x);
      mass[pi](i, j, k) = rho0(x);
      psi[pi](i, j, k) = psi0(x);
    });
  const double dt = 0.5 * g.dx[0];
  const int steps = 2 * n;
  for (int s = 0; s < steps; ++s) {
    halo.exchange(q);
    halo.exchange(mass);
    halo.exchange(psi);
    density_fluxes(g, order, q, u, dt, flux);
    density_fluxes(g, order, mass, u, dt, mflux);
    if (order != AdvectionOrder::First) {  // the donor outflow bound (AdvectionBounds.h) as in the ICE step
      outflow_limits(g, q, u, nullptr, dt, flux, limit);
      halo.exchange(limit);
      limit_outflow(g, q, u, nullptr, dt, limit, flux);
      outflow_limits(g, mass, u, nullptr, dt, mflux, limit);
      halo.exchange(limit);
      limit_outflow(g, mass, u, nullptr, dt, limit, mflux);
    }
    flux_divergence(g, flux, dq);
    flux_divergence(g, mflux, dm);
    specific_fluxes(g, order, psi, u, mflux, dt, pflux);
    if (order != AdvectionOrder::First) {
      flag_out_of_range_donors(g, psi, mass, mflux, pflux, limit);
      halo.exchange(limit);
      donor_value_fluxes(g, psi, mflux, limit, pflux);
    }
    flux_divergence(g, pflux, dpsi);
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        q[pi](i, j, k) += dq[pi](i, j, k);
        const double m_new = mass[pi](i, j, k) + dm[pi](i, j, k);
        psi[pi](i, j, k) = (mass[pi](i, j, k) * psi[pi](i, j, k) + dpsi[pi](i, j, k)) / m_new;
        mass[pi](i, j, k) = m_new;
      });
  }
  LineErrors e;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const double x = g.cell_center(i, j, k)[0];
      e.q += std::abs(q[pi](i, j, k) - q0(x)) * g.dx[0];
      e.psi += std::abs(psi[pi](i, j, k) - psi0(x)) * g.dx[0];
    });
  return e;
}

void check_orders(AdvectionOrder order, const char* name, int n0, double lo, double hi) {
  const int n[3] = {n0, 2 * n0, 4 * n0};
  LineErrors e[3];
  for (int k = 0; k < 3; ++k) e[k] = advect_one_period(n[k], order);
  for (int k = 0; k < 2; ++k) {
    const double oq = std::log2(e[k].q / e[k + 1].q), op = std::log2(e[k].psi / e[k + 1].psi);
    std::printf("%s N=%d->%d: L1(q) %.3e -> %.3e order %.3f | L1(psi) %.3e -> %.3e order %.3f\n", name, n[k],
                n[k + 1], e[k].q, e[k + 1].q, oq, e[k].psi, e[k + 1].psi, op);
    EXPECT_GT(oq, lo);
    EXPECT_LT(oq, hi);
    EXPECT_GT(op, lo);
    EXPECT_LT(op, hi);
  }
}

TEST(IceAdvection, FirstOrderConvergesAtOrderOneOnASmoothProfile) {
  check_orders(AdvectionOrder::First, "FirstOrder", 128, 0.85, 1.15);
}

TEST(IceAdvection, SecondOrderConvergesAtOrderTwoOnASmoothProfile) {
  check_orders(AdvectionOrder::Second, "SecondOrder", 32, 1.8, 2.4);
}

// Two ideal gases at one pressure (rho T equal: 1.2 * 300 = 4.8 * 75) in a
// periodic 2-D box, the dense cold block [0.3, 0.6]^2 inside, everything at
// u = (40, 25, 0) m/s; momentum and heat exchange 1e10 (as the stock decks).
std::string block_deck(const char* advection, int n) {
  std::ostringstream x;
  const double h = 1.0 / n;
  x << R"(<Uintah_specification><Meta><title>block</title></Meta><SimulationComponent type="ice"/>
  <Time><maxTime>1</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max></Time>
  <DataArchiver><filebase>block.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>0.4</cfl><ICE><advection type=")"
    << advection << R"("/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
   <material><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity><thermal_conductivity>0</thermal_conductivity>
    <specific_heat>716</specific_heat><gamma>1.4</gamma>
    <geom_object><difference><box label="all"><min>[-1,-1,-1]</min><max>[2,2,2]</max></box>
      <box label="block"><min>[0.3,0.3,-1]</min><max>[0.6,0.6,2]</max></box></difference>
     <res>[2,2,1]</res><velocity>[40,25,0]</velocity><density>1.2</density><pressure>101325</pressure>
     <temperature>300</temperature></geom_object></material>
   <material><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity><thermal_conductivity>0</thermal_conductivity>
    <specific_heat>716</specific_heat><gamma>1.4</gamma>
    <geom_object><box label="block"/><res>[2,2,1]</res><velocity>[40,25,0]</velocity><density>4.8</density>
     <pressure>101325</pressure><temperature>75</temperature></geom_object></material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>1e10</momentum><heat>1e10</heat></exchange_coefficients>
  </exchange_properties></MaterialProperties>
  <Grid><Level><Box label="1"><lower>[0,0,0]</lower><upper>[1,1,)"
    << h << R"(]</upper><resolution>[)" << n << "," << n << R"(,1]</resolution><extraCells>[0,0,0]</extraCells>
   <patches>[2,2,1]</patches></Box><periodic>[1,1,1]</periodic></Level></Grid></Uintah_specification>)";
  return x.str();
}

void check_block(const char* advection) {
  set_thread_count(1);
  auto deck = load_deck_from_string(block_deck(advection, 40), "block.ups", ".");
  auto ice = make_ice_component(*deck);
  ice->initialize();
  const Grid& g = ice->grid();
  const double V = g.cell_volume();
  auto material_mass = [&](std::size_t m) {
    double s = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) { s += ice->fields()[m].rho_CC[pi](i, j, k) * V; });
    return s;
  };
  const double m0 = material_mass(0), m1 = material_mass(1);
  double t = 0, theta_lo = 1, theta_hi = 0, sum_dev = 0;
  for (int step = 1; step <= 60; ++step) {
    const double dt = ice->stable_timestep();
    ice->advance(t, dt, step);
    t += dt;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        double sum = 0;
        for (std::size_t m = 0; m < 2; ++m) {
          const double th = ice->fields()[m].vol_frac_CC[pi](i, j, k);
          theta_lo = std::min(theta_lo, th);
          theta_hi = std::max(theta_hi, th);
          sum += th;
        }
        sum_dev = std::max(sum_dev, std::abs(sum - 1.0));
      });
  }
  const double d0 = std::abs(material_mass(0) / m0 - 1), d1 = std::abs(material_mass(1) / m1 - 1);
  std::printf("block %s: t = %.4g s (block moved %.3f m), |dM/M| %.2e %.2e, theta in [%.3e, %.15f], max|sum theta - 1| %.2e\n",
              advection, t, 40 * t, d0, d1, theta_lo, theta_hi, sum_dev);
  EXPECT_GT(40 * t, 2 * g.dx[0]);  // the block has moved by more than two cells
  EXPECT_LT(d0, 1e-13);
  EXPECT_LT(d1, 1e-13);
  EXPECT_GE(theta_lo, 0.0);
  EXPECT_LE(theta_hi, 1.0 + 1e-12);
  EXPECT_LT(sum_dev, 1e-9);
}

TEST(IceAdvection, BlockConservesTheMassOfEachMaterialFirstOrder) { check_block("FirstOrder"); }
TEST(IceAdvection, BlockConservesTheMassOfEachMaterialSecondOrder) { check_block("SecondOrder"); }

}  // namespace
}  // namespace tephra
