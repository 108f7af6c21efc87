// <PhysicalBC><MPM><heat_flux> (mpm/loads/ParticleLoads.h, Vaango's
// HeatFluxBC): a flux q(t) [W/m^2] through a surface of area A, shared by the
// N particles flagged on it, Q_p = q A / N [W] each, taken into the particle
// heating rate Q_p / (m_p c_v). Energy balance (exact, first law with
// insulated faces): the thermal energy sum m_p c_v T_p grows by the heat
// that entered,
//   E(t_n) - E(0) = A sum_{k<n} dt q(t_k)      (= q A t for a constant flux),
// with or without conduction (the Galerkin conduction conserves sum m c_v T
// to round-off, docs/mpm-thermal.md). Without conduction each flagged
// particle warms by n dt Q_p / (m_p c_v) and the others stay at T0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/Schema.h"
#include "core/deck/Validate.h"
#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

const double kRho = 1000.0, kCv = 100.0, kT0 = 300.0;

// A block [0.25, 0.75]^3 (2 particles per cell of 1/8: spacing 1/16) at rest,
// with a heat flux on its x- face: the plane x = 0.25, A = 0.25 m^2, whose
// flags (reference x within 1/16 of the plane) hold the first particle layer,
// 8 x 8 = 64 particles.
MpmSetup heated_block(double conductivity, const std::string& curve) {
  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3::Ones();
  s.grid.cells = IntVec3::Constant(8);
  s.grid.dx = Vec3::Constant(0.125);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  auto deck = load_deck_from_string(
      "<Uintah_specification><PhysicalBC><MPM><heat_flux><geom_object><box><min>[0.25,0.25,0.25]</min>"
      "<max>[0.25,0.75,0.75]</max></box></geom_object>" + curve + "</heat_flux></MPM></PhysicalBC></Uintah_specification>",
      "heat_flux.ups", ".");
  s.loads = parse_particle_loads(deck->root.child("PhysicalBC"), true);
  MpmMaterial m;
  m.density = kRho;
  m.specific_heat = kCv;
  m.thermal_conductivity = conductivity;
  m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{1e5, 5e4});
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(Vec3::Constant(0.25), Vec3::Constant(0.75));
  src.res = IntVec3::Constant(2);
  src.velocity = Vec3::Zero();
  src.temperature = kT0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  return s;
}

double thermal_energy(const MpmComponent& c) { return c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0]; }

TEST(MpmHeatFlux, ConstantFluxPutsInQATWithAndWithoutConduction) {
  const double q = 2.0e4, A = 0.25, dt = 1e-3;
  const int n = 50;
  for (double k : {0.0, 5.0}) {
    MpmComponent c(heated_block(k, "<load_curve><id>1</id><time_point><time>0</time><load>20000</load></time_point>"
                                   "</load_curve>"));
    c.initialize();
    const double E0 = thermal_energy(c);
    for (int s = 0; s < n; ++s) c.advance(s * dt, dt, s + 1);
    const double dE = thermal_energy(c) - E0, exact = q * A * n * dt;
    std::printf("heat flux (k = %g): energy in %.15g J, q A t = %.15g J, relative error %.1e\n", k, dE, exact,
                dE / exact - 1);
    EXPECT_NEAR(dE / exact, 1.0, 1e-9);  // E0 = 1.9e7 J: round-off of the sum ~ 1e-16 E0 / (q A t = 250 J) ~ 1e-11
    const Particles& p = c.materials()[0].particles;
    if (k == 0.0) {
      int flagged = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.x[i][0] < 0.3) {
          ++flagged;
          EXPECT_NEAR(p.temperature[i] - kT0, n * dt * (q * A / 64) / (p.mass[i] * kCv), 1e-10);
        } else {
          EXPECT_EQ(p.temperature[i], kT0);
        }
      }
      EXPECT_EQ(flagged, 64);
    } else {
      EXPECT_GT(p.temperature[0], kT0);  // conduction spread it; the sum is checked above
    }
  }
}

TEST(MpmHeatFlux, RampFluxPutsInTheSumOfQAtTheStepStarts) {
  // q(t) = b t, b = 4e5 W/(m^2 s): energy in A b dt^2 n (n - 1) / 2 (left sums of the step starts).
  const double b = 4e5, A = 0.25, dt = 1e-3;
  const int n = 40;
  MpmComponent c(heated_block(2.0, "<load_curve><id>1</id><time_point><time>0</time><load>0</load></time_point>"
                                   "<time_point><time>1</time><load>400000</load></time_point></load_curve>"));
  c.initialize();
  const double E0 = thermal_energy(c);
  for (int s = 0; s < n; ++s) c.advance(s * dt, dt, s + 1);
  const double dE = thermal_energy(c) - E0, exact = A * b * dt * dt * n * (n - 1) / 2;
  std::printf("ramp heat flux: energy in %.15g J, A b dt^2 n (n-1)/2 = %.15g J\n", dE, exact);
  EXPECT_NEAR(dE / exact, 1.0, 1e-9);
}

TEST(MpmHeatFlux, Parsing) {
  auto loads = [](const std::string& bc, bool use) {
    auto d = load_deck_from_string(
        "<Uintah_specification><PhysicalBC><MPM>" + bc + "</MPM></PhysicalBC></Uintah_specification>", "t.ups", ".");
    return parse_particle_loads(d->root.child("PhysicalBC"), use);
  };
  const std::string hf = "<heat_flux><geom_object><box><min>[0,0,0]</min><max>[0,2,3]</max></box></geom_object>"
                         "<load_curve><id>1</id><time_point><time>0</time><load>5</load></time_point></load_curve>";
  const ParticleLoads l = loads(hf + "</heat_flux>", true);
  ASSERT_EQ(l.heat_flux.size(), 1u);
  EXPECT_EQ(l.heat_flux[0].area, 6.0);
  EXPECT_TRUE(loads(hf + "</heat_flux>", false).heat_flux.empty());  // needs <use_load_curves>
  EXPECT_THROW(loads(hf + "<bogus/></heat_flux>", true), DeckError);
  // Vaango's spec types the curve's time and load INTEGER; its HeatFluxBC reads
  // doubles, and so does Tephra's schema (core/deck/schema/ups_schema_extensions.txt):
  // no "expected an integer" problem for the fractional values (the fragment
  // lacks <Grid> etc., which check_deck also reports; those are ignored).
  auto d = load_deck_from_string(
      "<Uintah_specification><PhysicalBC><MPM><heat_flux><geom_object><box><min>[0,0,0]</min><max>[0,2,3]</max>"
      "</box></geom_object><load_curve><id>1</id><time_point><time>0</time><load>0</load></time_point>"
      "<time_point><time>0.5e-3</time><load>1.5e4</load></time_point></load_curve></heat_flux></MPM></PhysicalBC>"
      "</Uintah_specification>",
      "t.ups", ".");
  for (const DeckProblem& problem : check_deck(d->root, Schema::builtin()))
    EXPECT_EQ(problem.message.find("integer"), std::string::npos) << problem.message;
  const ParticleLoads f = parse_particle_loads(d->root.child("PhysicalBC"), true);
  ASSERT_EQ(f.heat_flux.size(), 1u);
  EXPECT_DOUBLE_EQ(f.heat_flux[0].curve.at(0.25e-3), 0.75e4);
}

}  // namespace
}  // namespace tephra
