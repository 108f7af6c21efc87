// SimpleRxn (ice/models/SimpleRxn.cpp): a two-gas ideal mixture carried by a
// mixture fraction f on one ICE material (Uintah's SimpleRxn.cc):
//   cv = f cv_fuel + (1-f) cv_air,  R = f R_fuel + (1-f) R_air,  gamma = R/cv + 1,
//   1/rho_0 = f/rho_fuel + (1-f)/rho_air,  p = (gamma-1) rho cv T = rho R T,  c^2 = gamma R T,
// f advected with the mass and diffused with D (forward Euler).
//
// 1. Mixture properties: after initialisation, in cells at f = 0, 0.25, 0.5,
//    1, the density, pressure, speed of sound and TotalIntEng equal the
//    formulas above (relative 1e-14).
// 2. Advection at uniform velocity u of a fuel block in air at equal p and T
//    (rho_fuel R_fuel = rho_air R_air): the exact solution is the block moving
//    at u with p, u, T unchanged. With cv and R linear in f and the energy
//    advected as M cv T, a mixed cell gets rho R_mix T = sum_i (V_i/V)
//    rho_i R_i T = p and T_new = T exactly, so p, u and T stay uniform to
//    round-off. With first-order upwind fluxes F = u dt A (rho f)_donor at
//    uniform u, the first moment of M f moves exactly: sum M f x / sum M f
//    = x_0 + u t (the flux sum telescopes); sum M f is conserved to round-off.
// 3. Diffusion of a step (air and fuel with the same rho, R and cv, at rest:
//    f_t = D f_xx) against erfc((x - L/2)/(2 sqrt(D t)))/2, second order in dx
//    (as PassiveScalar's test_ice_scalar_diffusion).
// 4. Bad input: a non-ideal-gas material is a DeckError; an initial
//    smoothing knob > 1 and per-cell conductivity are MissingFeature (exit 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "ice/IceComponent.h"
#include "ice/models/IceModel.h"
#include "mpmice/ComponentFactory.h"

namespace tephra {
namespace {

struct Gas {
  double rho, R, cv;
};
// Air and a helium-like fuel at 300 K and the same pressure (rho R equal).
constexpr Gas kAir{1.1792946927374306, 287.0, 717.5};
constexpr Gas kFuel{1.1792946927374306 * 287.0 / 2077.0, 2077.0, 3116.0};
constexpr double kT = 300.0;

struct DeckSpec {
  int n = 100;
  double length = 1.0;
  double u = 0;
  const char* advection = "FirstOrder";
  Gas air = kAir, fuel = kFuel;
  double D = 0;
  std::string regions;         // <geom_object>s of the scalar
  std::string eos = "ideal_gas";
  std::string extra_constants;  // appended to <constants>
  std::string knob = "1";
};

std::string box(double x0, double x1, double f) {
  static int label = 0;  // geometry labels are deck-wide: one per box
  std::ostringstream s;
  s.precision(17);
  s << "<geom_object><box label=\"b" << ++label << "\"><min>[" << x0 << ",-1,-1]</min><max>[" << x1
    << ",2,2]</max></box><scalar>" << f << "</scalar></geom_object>";
  return s.str();
}

std::string deck(const DeckSpec& d) {
  const double dx = d.length / d.n;
  std::ostringstream s;
  s.precision(17);
  s << R"(<Uintah_specification>
  <SimulationComponent type="ice"/>
  <Grid><BoundaryConditions>)";
  // x faces zero-gradient (the uniform state continues), y and z symmetry (one cell across).
  for (const char* f : {"x-", "x+"})
    s << "<Face side=\"" << f << "\">"
      << R"(<BCType id="all" label="Pressure" var="Neumann"><value>0</value></BCType>
            <BCType id="all" label="Velocity" var="Neumann"><value>[0,0,0]</value></BCType>
            <BCType id="all" label="Temperature" var="Neumann"><value>0</value></BCType>
            <BCType id="all" label="Density" var="Neumann"><value>0</value></BCType>
            <BCType id="all" label="SpecificVol" var="computeFromDensity"><value>0</value></BCType></Face>)";
  for (const char* f : {"y-", "y+", "z-", "z+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/></Face>";
  s << R"(</BoundaryConditions>
    <Level><Box label="1"><lower>[0,0,0]</lower><upper>[)" << d.length << "," << dx << "," << dx << R"(]</upper>
      <extraCells>[1,1,1]</extraCells><patches>[2,1,1]</patches><resolution>[)" << d.n << R"(,1,1]</resolution></Box></Level>
  </Grid>
  <CFD><cfl>0.4</cfl><ICE><advection type=")" << d.advection << R"("/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
    <material name="gas">)";
  if (d.eos == "ideal_gas")
    s << R"(<EOS type="ideal_gas"/>)";
  else
    s << R"(<EOS type="hard_sphere_gas"><b>1e-3</b></EOS>)";
  s << R"(<dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>716.5</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="all"><min>[-1,-1,-1]</min><max>[2,2,2]</max></box><res>[2,2,2]</res>
        <velocity>[)" << d.u << R"(,0,0]</velocity><temperature>)" << kT << R"(</temperature><density>1.1792946927374306</density>
        <pressure>101325</pressure></geom_object>
    </material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>[]</momentum><heat>[]</heat></exchange_coefficients></exchange_properties>
  </MaterialProperties>
  <Models><Model type="SimpleRxn"><SimpleRxn><material>gas</material><scalar name="f">
    <constants><f_stoichometric>0.5</f_stoichometric><diffusivity>)" << d.D << R"(</diffusivity>
      <rho_air>)" << d.air.rho << "</rho_air><rho_fuel>" << d.fuel.rho << "</rho_fuel><cv_air>" << d.air.cv
    << "</cv_air><cv_fuel>" << d.fuel.cv << "</cv_fuel><R_air>" << d.air.R << "</R_air><R_fuel>" << d.fuel.R
    << R"(</R_fuel>
      <thermalCond_air>0</thermalCond_air><thermalCond_fuel>0</thermalCond_fuel>
      <viscosity_air>0</viscosity_air><viscosity_fuel>0</viscosity_fuel>
      <initialize_diffusion_knob>)" << d.knob << "</initialize_diffusion_knob>" << d.extra_constants << R"(</constants>
    )" << d.regions << R"(
    <test_conservation>true</test_conservation>
  </scalar></SimpleRxn></Model></Models>
</Uintah_specification>
)";
  return s.str();
}

struct RxnRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<Component> comp;
  const IceComponent& ice() const { return dynamic_cast<const IceComponent&>(*comp); }
  const CellScalars& f() const {
    for (const ModelField& m : ice().models()[0]->fields())
      if (m.label == "scalar-f") return *m.field;
    throw std::runtime_error("no scalar-f");
  }
};

RxnRun start(const DeckSpec& spec) {
  RxnRun r;
  r.deck = load_deck_from_string(deck(spec), "simple_rxn.ups", ".");
  r.comp = make_ice_component(*r.deck);
  r.comp->initialize();
  return r;
}

double mix(double f, double fuel, double air) { return f * fuel + (1 - f) * air; }

TEST(IceSimpleRxn, MixturePropertiesFollowTheMassFraction) {
  DeckSpec s;
  s.n = 8;
  // f = 0 (x < 0.25), 0.25, 0.5, 1 (x > 0.75); later regions overwrite earlier ones.
  s.regions = box(0.25, 2, 0.25) + box(0.5, 2, 0.5) + box(0.75, 2, 1.0);
  RxnRun r = start(s);
  const IceComponent& ice = r.ice();
  const Grid& g = ice.grid();
  const double V = g.cell_volume();
  double eint = 0;
  int checked = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int i = g.patches[pi].cells().lo[0]; i < g.patches[pi].cells().hi[0]; ++i) {
      const double x = (i + 0.5) / s.n;
      const double f = x < 0.25 ? 0 : x < 0.5 ? 0.25 : x < 0.75 ? 0.5 : 1.0;
      EXPECT_EQ(r.f()[pi](i, 0, 0), f);
      const double cv = mix(f, kFuel.cv, kAir.cv), R = mix(f, kFuel.R, kAir.R), gamma = R / cv + 1;
      const double rho = 1.0 / (f / kFuel.rho + (1 - f) / kAir.rho);
      const auto& m = ice.fields()[0];
      EXPECT_NEAR(m.rho_CC[pi](i, 0, 0), rho, 1e-14 * rho) << "cell " << i;
      EXPECT_NEAR(ice.press_equil_CC()[pi](i, 0, 0), rho * R * kT, 1e-14 * rho * R * kT) << "cell " << i;
      const double c = std::sqrt(gamma * R * kT);
      EXPECT_NEAR(m.speedSound_CC[pi](i, 0, 0), c, 1e-14 * c) << "cell " << i;
      EXPECT_NEAR(m.vol_frac_CC[pi](i, 0, 0), 1.0, 1e-15);
      eint += rho * V * cv * kT;
      ++checked;
    }
  EXPECT_EQ(checked, 8);
  const double E = r.comp->reductions({"TotalIntEng"}).at("TotalIntEng")[0];
  EXPECT_NEAR(E, eint, 1e-14 * eint);
}

TEST(IceSimpleRxn, BlockAdvectsAtTheFlowSpeedWithPressureUnchanged) {
  DeckSpec s;
  s.n = 100;
  s.u = 100.0;
  s.regions = box(0.2, 0.4, 1.0);
  RxnRun r = start(s);
  const IceComponent& ice = r.ice();
  const Grid& g = ice.grid();
  const auto moments = [&] {
    double m0 = 0, m1 = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for (int i = g.patches[pi].cells().lo[0]; i < g.patches[pi].cells().hi[0]; ++i) {
        const double q = ice.fields()[0].rho_CC[pi](i, 0, 0) * g.cell_volume() * r.f()[pi](i, 0, 0);
        m0 += q;
        m1 += q * (i + 0.5) * g.dx[0];
      }
    return std::pair<double, double>(m0, m1 / m0);
  };
  const auto [sum0, x0] = moments();
  EXPECT_NEAR(x0, 0.3, 1e-12);
  const double t_end = 2e-3;  // the block moves 0.2 m: from [0.2, 0.4] to [0.4, 0.6]
  double t = 0;
  int step = 0;
  while (t < t_end * (1 - 1e-12)) {
    const double dt = std::min(r.comp->stable_timestep(), t_end - t);
    r.comp->advance(t, dt, ++step);
    t += dt;
  }
  const auto [sum1, x1] = moments();
  std::printf("%d steps: sum M f drift %.1e, centroid %.15f (exact %.15f)\n", step, sum1 / sum0 - 1, x1, x0 + s.u * t);
  EXPECT_NEAR(sum1 / sum0, 1.0, 1e-13);
  EXPECT_NEAR(x1, x0 + s.u * t, 1e-12);
  double dp = 0, du = 0, dT = 0, fmin = 1, fmax = 0;
  const double p0 = kAir.rho * kAir.R * kT;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int i = g.patches[pi].cells().lo[0]; i < g.patches[pi].cells().hi[0]; ++i) {
      const auto& m = ice.fields()[0];
      dp = std::max(dp, std::abs(ice.press_CC()[pi](i, 0, 0) / p0 - 1));
      du = std::max(du, std::abs(m.vel_CC[pi](i, 0, 0)[0] / s.u - 1));
      dT = std::max(dT, std::abs(m.temp_CC[pi](i, 0, 0) / kT - 1));
      fmin = std::min(fmin, r.f()[pi](i, 0, 0));
      fmax = std::max(fmax, r.f()[pi](i, 0, 0));
    }
  std::printf("max relative change: p %.1e, u %.1e, T %.1e; f in [%.3g, %.3g]\n", dp, du, dT, fmin, fmax);
  EXPECT_LT(dp, 1e-12);
  EXPECT_LT(du, 1e-12);
  EXPECT_LT(dT, 1e-12);
  EXPECT_GE(fmin, -1e-15);
  EXPECT_LE(fmax, 1 + 1e-15);
  EXPECT_GT(fmax, 0.5);  // the block is smeared but still there
}

double diffusion_l1(int n) {
  constexpr double kD = 1.0, kTEnd = 2.5e-3;  // sqrt(4 D t) = 0.1 m: walls 5 lengths away
  DeckSpec s;
  s.n = n;
  s.D = kD;
  s.advection = "SecondOrder";
  s.fuel = kAir;  // same rho, R and cv: f is a passive scalar, f_t = D f_xx
  s.regions = box(-1, 0.5, 1.0);
  RxnRun r = start(s);
  const Grid& g = r.ice().grid();
  double t = 0;
  int step = 0;
  const double dx = 1.0 / n;
  while (t < kTEnd * (1 - 1e-12)) {
    const double dt = std::min({r.comp->stable_timestep(), 0.05 * dx * dx / kD, kTEnd - t});
    r.comp->advance(t, dt, ++step);
    t += dt;
  }
  double l1 = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int i = g.patches[pi].cells().lo[0]; i < g.patches[pi].cells().hi[0]; ++i) {
      const double x = (i + 0.5) * dx;
      l1 += std::abs(r.f()[pi](i, 0, 0) - 0.5 * std::erfc((x - 0.5) / (2 * std::sqrt(kD * t)))) * dx;
    }
  return l1;
}

TEST(IceSimpleRxn, StepDiffusesAsTheErfSolution) {
  const double e50 = diffusion_l1(50), e100 = diffusion_l1(100);
  std::printf("L1(f - erfc): N = 50: %.3e, N = 100: %.3e, order %.2f\n", e50, e100, std::log2(e50 / e100));
  EXPECT_LT(e100, 1.2e-4);
  EXPECT_GT(std::log2(e50 / e100), 1.8);
}

TEST(IceSimpleRxn, BadInput) {
  DeckSpec s;
  s.n = 4;
  s.regions = box(0.5, 2, 1.0);
  s.eos = "hard_sphere_gas";
  EXPECT_THROW(start(s), DeckError);
  s.eos = "ideal_gas";
  s.knob = "3";
  EXPECT_THROW(start(s), MissingFeature);
  s.knob = "1";
  std::string d = deck(s);
  const std::string from = "<thermalCond_fuel>0</thermalCond_fuel>";
  d.replace(d.find(from), from.size(), "<thermalCond_fuel>0.1</thermalCond_fuel>");
  auto loaded = load_deck_from_string(d, "simple_rxn.ups", ".");
  EXPECT_THROW(make_ice_component(*loaded), MissingFeature);
  const auto types = ice_model_types();
  EXPECT_NE(std::find(types.begin(), types.end(), "SimpleRxn"), types.end());
}

}  // namespace
}  // namespace tephra
