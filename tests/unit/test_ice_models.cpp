// ICE source models (ice/models/): each model's rate at a chosen state
// against the rate law evaluated by hand, and the conservation identities of
// a reactant -> product conversion: sum over materials of the mass and
// momentum sources = 0 exactly, of the energy sources = E0 dm (the released
// heat), of the specific-volume sources = 0 exactly. The deck layout rules
// (both JWLpp placements, unknown parameters, material names) as well.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "ice/IceComponent.h"
#include "ice/models/IceModel.h"
#include "mpmice/ComponentFactory.h"

namespace tephra {
namespace {

// Two ideal-gas materials "reactant" and "product" on a 3 x 1 x 1 grid of
// 1 mm cells, every face a symmetry plane, and the given <Models> block
// (or <CFD><ICE> extra).
std::string deck(const std::string& models, const std::string& ice_extra = "") {
  std::ostringstream s;
  s << R"(<Uintah_specification>
  <SimulationComponent type="ice"/>
  <Grid><BoundaryConditions>)";
  for (const char* f : {"x-", "x+", "y-", "y+", "z-", "z+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/></Face>";
  s << R"(</BoundaryConditions>
    <Level><Box label="1"><lower>[0,0,0]</lower><upper>[3e-3,1e-3,1e-3]</upper>
      <extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches><resolution>[3,1,1]</resolution></Box></Level>
  </Grid>
  <CFD><cfl>0.5</cfl><ICE><advection type="FirstOrder"/>)" << ice_extra << R"(</ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
    <material name="reactant"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>1000</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="all"><min>[-1,-1,-1]</min><max>[1,1,1]</max></box><res>[2,2,2]</res>
        <velocity>[0,0,0]</velocity><temperature>300</temperature><density>1000</density><pressure>101325</pressure></geom_object>
    </material>
    <material name="product"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>700</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="none"><min>[9,9,9]</min><max>[10,10,10]</max></box><res>[2,2,2]</res>
        <velocity>[0,0,0]</velocity><temperature>300</temperature><density>1</density><pressure>101325</pressure></geom_object>
    </material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>[1e15]</momentum><heat>[1e15]</heat></exchange_coefficients></exchange_properties>
  </MaterialProperties>
  )" << models << "\n</Uintah_specification>\n";
  return s.str();
}

std::unique_ptr<IceComponent> component(const std::string& text) {
  auto d = load_deck_from_string(text, "models.ups", ".");
  return make_ice_component(*d);
}

// A hand-made state on the component's grid: in every cell the reactant has
// bulk density rho_r, micro density rho_mr, velocity u, T = 300 K; the
// product bulk density rho_p; pressure p; cv from the deck.
struct State {
  std::vector<IceMaterialFields> mats;
  std::vector<CellScalars> cv;
  CellScalars press;
  IceModelSources src;
  State(const IceComponent& ice, double rho_r, double rho_mr, double rho_p, double p, const Vec3& u) {
    const Grid& g = ice.grid();
    for (std::size_t m = 0; m < 2; ++m) {
      mats.emplace_back(g, 2);
      cv.emplace_back(g, 2);
      cv[m].fill(ice.setup().materials[m].cv);
      src.mass.emplace_back(g, 0);
      src.energy.emplace_back(g, 0);
      src.sp_vol.emplace_back(g, 0);
      src.momentum.emplace_back(g, 0);
      src.mass[m].fill(0.0);
      src.energy[m].fill(0.0);
      src.sp_vol[m].fill(0.0);
      src.momentum[m].fill(Vec3::Zero());
    }
    mats[0].rho_CC.fill(rho_r);
    mats[1].rho_CC.fill(rho_p);
    mats[0].sp_vol_CC.fill(1.0 / rho_mr);
    mats[1].sp_vol_CC.fill(1.0 / 2000.0);
    mats[0].vol_frac_CC.fill(rho_r / rho_mr);
    mats[1].vol_frac_CC.fill(1.0 - rho_r / rho_mr);
    for (auto& f : mats) {
      f.vel_CC.fill(u);
      f.temp_CC.fill(300.0);
    }
    press = CellScalars(g, 2);
    press.fill(p);
  }
  IceModelInput input(const IceComponent& ice, double t, double dt) const {
    return {ice.grid(), ice.setup().materials, mats, cv, press, t, dt, 1};
  }
};

// Conservation of one conversion in cell c: returns dm (mass gained by the product).
double check_conversion(const State& s, const IntVec3& c, double E0) {
  const double dm = s.src.mass[1][0](c);
  EXPECT_EQ(s.src.mass[0][0](c) + dm, 0.0);
  EXPECT_EQ((s.src.momentum[0][0](c) + s.src.momentum[1][0](c)).norm(), 0.0);
  EXPECT_EQ(s.src.sp_vol[0][0](c) + s.src.sp_vol[1][0](c), 0.0);
  EXPECT_NEAR(s.src.energy[0][0](c) + s.src.energy[1][0](c), E0 * dm, 1e-14 * std::abs(E0 * dm) + 1e-300);
  return dm;
}

const char* kJwlppFlat = R"(<Models><Model type="JWLpp">
  <fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>
  <G>3.5083e-7</G><b>1.3</b><rho0>1160</rho0><E0>5.558e6</E0><ThresholdPressure>2e8</ThresholdPressure>
</Model></Models>)";

// JWL++ at a state: F = rho_p/(rho_r + rho_p), dm = G p^b (1 - F) dt (M_r + M_p)
// (Souers' rate; the 20 % cap and M_r do not bind here).
TEST(IceModels, JwlppRateAtAStateAndConservation) {
  auto ice = component(deck(kJwlppFlat));
  ASSERT_EQ(ice->models().size(), 1u);
  IceModel& model = *ice->models()[0];
  EXPECT_EQ(model.type(), "JWLpp");
  const Grid& g = ice->grid();
  model.initialize(g, ice->fields());
  const double rho_r = 900, rho_p = 100, p = 5e9, dt = 1e-9, V = g.cell_volume();
  State s(*ice, rho_r, 1200, rho_p, p, Vec3(3, -2, 1));
  model.compute_sources(s.input(*ice, 0.0, dt), s.src);
  const double F = rho_p / (rho_r + rho_p);
  const double expect = 3.5083e-7 * std::pow(p, 1.3) * (1 - F) * dt * (rho_r + rho_p) * V;
  const IntVec3 c(1, 0, 0);
  const double dm = check_conversion(s, c, 5.558e6);
  EXPECT_NEAR(dm, expect, 1e-13 * expect);
  // The reactant's momentum, internal energy and volume leave with dm.
  EXPECT_NEAR(s.src.momentum[1][0](c)[0], 3 * dm, 1e-14 * dm);
  EXPECT_NEAR(s.src.energy[0][0](c), -dm * 1000.0 * 300.0, 1e-12 * dm * 3e5);
  EXPECT_NEAR(s.src.sp_vol[1][0](c), dm / 1200.0, 1e-14 * dm);
  std::map<std::string, std::vector<double>> sums;
  model.reductions({"totalMassBurned", "totalHeatReleased"}, sums);
  EXPECT_NEAR(sums["totalMassBurned"][0], 3 * expect, 1e-12 * expect);
  // Below the threshold pressure nothing burns.
  State cold(*ice, rho_r, 1200, rho_p, 1e8, Vec3::Zero());
  model.compute_sources(cold.input(*ice, 0.0, dt), cold.src);
  EXPECT_EQ(cold.src.mass[1][0](c), 0.0);
}

// The 20 % limit: dm <= 0.2 rho0 V (Souers p. 55), and dm <= M_r.
TEST(IceModels, JwlppBurnsAtMostTwentyPercentOfACellPerStep) {
  auto ice = component(deck(kJwlppFlat));
  IceModel& model = *ice->models()[0];
  model.initialize(ice->grid(), ice->fields());
  State s(*ice, 1100, 1200, 1, 3e10, Vec3::Zero());
  model.compute_sources(s.input(*ice, 0.0, 1e-6), s.src);
  EXPECT_NEAR(check_conversion(s, {0, 0, 0}, 5.558e6), 0.2 * 1160 * ice->grid().cell_volume(), 1e-20);
}

// Uintah's layout <Model type="JWLpp"><JWLpp>...</JWLpp> reads the same.
TEST(IceModels, JwlppParametersInsideAJwlppBlock) {
  const std::string nested = R"(<Models><Model type="JWLpp"><JWLpp>
  <fromMaterial>0</fromMaterial><toMaterial>1</toMaterial>
  <G>3.5083e-7</G><b>1.3</b><rho0>1160</rho0><E0>5.558e6</E0><ThresholdPressure>2e8</ThresholdPressure>
  </JWLpp></Model></Models>)";
  auto a = component(deck(kJwlppFlat)), b = component(deck(nested));
  for (auto* ice : {a.get(), b.get()}) ice->models()[0]->initialize(ice->grid(), ice->fields());
  State sa(*a, 900, 1200, 100, 5e9, Vec3::Zero()), sb(*b, 900, 1200, 100, 5e9, Vec3::Zero());
  a->models()[0]->compute_sources(sa.input(*a, 0, 1e-9), sa.src);
  b->models()[0]->compute_sources(sb.input(*b, 0, 1e-9), sb.src);
  EXPECT_EQ(sa.src.mass[1][0](1, 0, 0), sb.src.mass[1][0](1, 0, 0));
  EXPECT_GT(sa.src.mass[1][0](1, 0, 0), 0.0);
}

TEST(IceModels, DeckErrorsNameTheElement) {
  // A misspelt parameter is not ignored.
  std::string bad = kJwlppFlat;
  bad.replace(bad.find("<b>1.3</b>"), 10, "<bb>1.3</bb>");
  EXPECT_THROW(component(deck(bad)), DeckError);
  // An unknown material name.
  std::string badm = kJwlppFlat;
  badm.replace(badm.find(">product<"), 9, ">products<");
  EXPECT_THROW(component(deck(badm)), DeckError);
  // A Vaango model Tephra lacks: exit 3; an unknown one: a DeckError.
  EXPECT_THROW(component(deck(R"(<Models><Model type="Steady_Burn"/></Models>)")), MissingFeature);
  EXPECT_THROW(component(deck(R"(<Models><Model type="Nonsense"/></Models>)")), DeckError);
  const auto keys = registered_keys("Model");
  for (const char* k : {"ADD_HEAT", "IandG", "JWLpp", "LightTime", "PassiveScalar", "ZeroOrder", "mass_momentum_energy_src"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
}

// ZeroOrder: dm = G p^b dt (M_r + M_p).
TEST(IceModels, ZeroOrderRate) {
  auto ice = component(deck(R"(<Models><Model type="ZeroOrder"><ZeroOrder>
    <fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>
    <G>1e-9</G><b>1.0</b><rho0>1000</rho0><E0>4e6</E0><ThresholdPressure>1e6</ThresholdPressure>
    </ZeroOrder></Model></Models>)"));
  IceModel& model = *ice->models()[0];
  model.initialize(ice->grid(), ice->fields());
  State s(*ice, 800, 1000, 50, 2e9, Vec3::Zero());
  model.compute_sources(s.input(*ice, 0, 1e-8), s.src);
  const double expect = 1e-9 * 2e9 * 1e-8 * 850 * ice->grid().cell_volume();
  EXPECT_NEAR(check_conversion(s, {2, 0, 0}, 4e6), expect, 1e-13 * expect);
}

// Lee-Tarver ignition and growth at F = 0.2, rho_r = 1.1 rho0, p = 5 GPa with
// Figmax = 0.3, FG1max = 0.5, FG2min = 0.1 (all three terms active):
//   dF/dt = I (1-F)^b (rho_r/rho0 - 1 - a)^x + G1 (1-F)^c F^d p^y + G2 (1-F)^e F^g p^z.
TEST(IceModels, IgnitionAndGrowthRateAtAState) {
  auto ice = component(deck(R"(<Models><Model type="IandG"><IandG>
    <fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>
    <I>4e6</I><G1>1e-18</G1><G2>2e-18</G2><a>0.02</a><b>0.667</b><c>0.667</c><d>0.111</d>
    <e>0.333</e><g>1.0</g><x>7.0</x><y>2.0</y><z>2.0</z><Figmax>0.3</Figmax><FG1max>0.5</FG1max><FG2min>0.1</FG2min>
    <rho0>1000</rho0><E0>5e6</E0><ThresholdPressure>1e8</ThresholdPressure>
    </IandG></Model></Models>)"));
  IceModel& model = *ice->models()[0];
  model.initialize(ice->grid(), ice->fields());
  const double rho_r = 800, rho_p = 200, p = 5e9, dt = 1e-10, F = 0.2;
  State s(*ice, rho_r, 1100, rho_p, p, Vec3::Zero());
  model.compute_sources(s.input(*ice, 0, dt), s.src);
  const double rate = 4e6 * std::pow(0.8, 0.667) * std::pow(0.08, 7.0) +
                      1e-18 * std::pow(0.8, 0.667) * std::pow(F, 0.111) * p * p +
                      2e-18 * std::pow(0.8, 0.333) * F * p * p;
  const double expect = rate * dt * (rho_r + rho_p) * ice->grid().cell_volume();
  EXPECT_NEAR(check_conversion(s, {0, 0, 0}, 5e6), expect, 1e-12 * expect);
}

// LightTime: a plane front from x = 0 along +x at D; the cell centred at
// x_c = 1.5 mm is lit at t_b = x_c/D; at t its reacted fraction is
// F = (t - t_b)/delta_L, delta_L = 1.5 V^(1/3)/D, and dm = F (M_r + M_p) when
// the product holds no mass yet (F_old = 0 with rho_p -> the tiny value).
TEST(IceModels, LightTimeLightsACellAtDistanceOverD) {
  auto ice = component(deck(R"(<Models><Model type="LightTime"><LightTime>
    <fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>
    <D>8000</D><E0>4.95e6</E0><starting_location>[0,0,0]</starting_location>
    <direction_if_plane>[1,0,0]</direction_if_plane><react_mixed_cells>true</react_mixed_cells>
    </LightTime></Model></Models>)"));
  IceModel& model = *ice->models()[0];
  model.initialize(ice->grid(), ice->fields());
  const double D = 8000, V = ice->grid().cell_volume(), delta_L = 1.5 * std::cbrt(V) / D;
  const double t_b = 1.5e-3 / D, t = t_b + 0.3 * delta_L;
  State s(*ice, 1000, 1000, 0.0, 1e5, Vec3::Zero());
  model.compute_sources(s.input(*ice, t, 1e-9), s.src);
  EXPECT_NEAR(check_conversion(s, {1, 0, 0}, 4.95e6), 0.3 * 1000 * V, 1e-12 * 1000 * V);
  EXPECT_GT(s.src.mass[1][0](0, 0, 0), 0.0);   // x_c = 0.5 mm: lit earlier
  EXPECT_EQ(s.src.mass[1][0](2, 0, 0), 0.0);   // x_c = 2.5 mm: not yet
  // A cell whose fraction would pass 0.96 burns out completely.
  State late(*ice, 1000, 1000, 0.0, 1e5, Vec3::Zero());
  model.compute_sources(late.input(*ice, t_b + 0.97 * delta_L, 1e-9), late.src);
  EXPECT_NEAR(late.src.mass[1][0](1, 0, 0), 1000 * V, 1e-12 * 1000 * V);
}

// ADD_HEAT: dE = coeff dt rho V in every cell of the listed material inside
// [t_start, t_final], nothing outside.
TEST(IceModels, AddHeatAddsCoeffTimesDtTimesMass) {
  auto ice = component(deck("", R"(<ADD_HEAT><add_heat_matls>[0]</add_heat_matls><add_heat_coeff>[8e5]</add_heat_coeff>
    <add_heat_t_start>1e-6</add_heat_t_start><add_heat_t_final>2e-6</add_heat_t_final></ADD_HEAT>)"));
  ASSERT_EQ(ice->models().size(), 1u);
  IceModel& model = *ice->models()[0];
  model.initialize(ice->grid(), ice->fields());
  const double V = ice->grid().cell_volume(), dt = 1e-8;
  State s(*ice, 900, 1000, 1, 1e5, Vec3::Zero());
  model.compute_sources(s.input(*ice, 1.5e-6, dt), s.src);
  double total = 0;
  for_each_cell_serial(ice->grid().patches[0].cells(), [&](int i, int j, int k) {
    EXPECT_NEAR(s.src.energy[0][0](i, j, k), 8e5 * dt * 900 * V, 1e-14 * 8e5 * dt * 900 * V);
    EXPECT_EQ(s.src.energy[1][0](i, j, k), 0.0);
    total += s.src.energy[0][0](i, j, k);
  });
  std::map<std::string, std::vector<double>> sums;
  model.reductions({"TotalHeatAdded"}, sums);
  EXPECT_NEAR(sums["TotalHeatAdded"][0], total, 1e-14 * total);
  State before(*ice, 900, 1000, 1, 1e5, Vec3::Zero());
  model.compute_sources(before.input(*ice, 0.5e-6, dt), before.src);
  EXPECT_EQ(before.src.energy[0][0](0, 0, 0), 0.0);
}

}  // namespace
}  // namespace tephra
