// ICE <geom_object><volumeFraction> (ice/IceComponent.cpp initialize; the
// meaning is Uintah's ICEMaterial::initializeCells): a piece with
// volumeFraction v gives its material theta = v x (the covered share of the
// cell) and rho_CC = theta rho; with theta = 0 the material is absent,
// rho_CC = tiny_rho rho with the state (rho_micro, T) of the last piece that
// covers the cell. Out-of-range values are deck errors.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "ice/IceComponent.h"

namespace tephra {
namespace {

// Two ideal-gas materials on a 4 x 1 x 1 grid of 1 mm cells, closed by
// symmetry planes; each material's <geom_object>s are given as text.
std::string deck(const std::string& objects_a, const std::string& objects_b, double cv_b) {
  std::ostringstream s;
  s << R"(<Uintah_specification>
  <SimulationComponent type="ice"/>
  <Grid><BoundaryConditions>)";
  for (const char* f : {"x-", "x+", "y-", "y+", "z-", "z+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/></Face>";
  s << R"(</BoundaryConditions>
    <Level><Box label="1"><lower>[0,0,0]</lower><upper>[4e-3,1e-3,1e-3]</upper>
      <extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches><resolution>[4,1,1]</resolution></Box></Level>
  </Grid>
  <CFD><cfl>0.5</cfl><ICE><advection type="FirstOrder"/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
    <material name="a"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>717.5</specific_heat><gamma>1.4</gamma>
      )" << objects_a << R"(
    </material>
    <material name="b"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>)" << cv_b << R"(</specific_heat><gamma>1.4</gamma>
      )" << objects_b << R"(
    </material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>[1e10]</momentum><heat>[1e10]</heat></exchange_coefficients></exchange_properties>
  </MaterialProperties>
</Uintah_specification>
)";
  return s.str();
}

std::string object(const std::string& box, double T, double rho, const std::string& extra = "") {
  std::ostringstream s;
  s << "<geom_object>" << box << "<res>[2,2,2]</res><velocity>[0,0,0]</velocity><temperature>" << T
    << "</temperature><density>" << rho << "</density><pressure>101325</pressure>" << extra << "</geom_object>";
  return s.str();
}

const std::string kAll = R"(<box label="all"><min>[-1,-1,-1]</min><max>[1,1,1]</max></box>)";
const std::string kLeft = R"(<box label="left"><min>[-1,-1,-1]</min><max>[2e-3,1,1]</max></box>)";
const std::string kRight = R"(<box label="right"><min>[2e-3,-1,-1]</min><max>[1,1,1]</max></box>)";
const std::string kNowhere = R"(<box label="nowhere"><min>[9,9,9]</min><max>[10,10,10]</max></box>)";

std::unique_ptr<IceComponent> initialized(const std::string& text) {
  auto d = load_deck_from_string(text, "volume_fraction.ups", ".");
  auto ice = make_ice_component(*d);
  ice->initialize();
  return ice;
}

// Both materials fill every cell with volumeFraction 0.25 and 0.75. The
// bulk densities are theta rho: 0.25 x 1.2 = 0.3 and 0.75 x 2.0 = 1.5
// kg/m^3. With cv_b = 0.3 cv_a the two ideal gases are at one pressure,
// (gamma - 1) rho cv T: 0.4 x 1.2 x 717.5 x 300 = 0.4 x 2.0 x 215.25 x 600
// = 103320 Pa, so the equilibration keeps the fractions: theta = 0.25,
// 0.75 and p = 103320 Pa in every cell.
TEST(IceVolumeFraction, SetsTheFractionsOfTwoMaterialsSharingEveryCell) {
  auto ice = initialized(deck(object(kAll, 300, 1.2, "<volumeFraction>0.25</volumeFraction>"),
                              object(kAll, 600, 2.0, "<volumeFraction>0.75</volumeFraction>"), 0.3 * 717.5));
  const auto& f = ice->fields();
  for (int i = 0; i < 4; ++i) {
    const IntVec3 c(i, 0, 0);
    EXPECT_NEAR(f[0].rho_CC[0](c), 0.3, 1e-15) << i;
    EXPECT_NEAR(f[1].rho_CC[0](c), 1.5, 1e-15) << i;
    EXPECT_NEAR(f[0].vol_frac_CC[0](c), 0.25, 1e-12) << i;
    EXPECT_NEAR(f[1].vol_frac_CC[0](c), 0.75, 1e-12) << i;
    EXPECT_NEAR(f[0].temp_CC[0](c), 300.0, 1e-12) << i;
    EXPECT_NEAR(f[1].temp_CC[0](c), 600.0, 1e-12) << i;
    EXPECT_NEAR(ice->press_CC()[0](c) / 103320.0, 1.0, 1e-12) << i;
  }
}

// BurnRate.ups's layout for the product ("b"): a piece outside the domain
// (source 0, 500 K), a volumeFraction 0 piece over the right half (300 K,
// 13.9 kg/m^3), and a plain piece over the left half (3000 K, 1.39 kg/m^3);
// material "a" fills the right half. Left: b alone, rho_CC = 1.39, T = 3000.
// Right: b absent, rho_CC = tiny_rho x 13.9 = 1.39e-11 with T = 300 K (the
// covering volumeFraction-0 piece's state, not source 0's 500 K); "a" there
// has theta = 1 to round-off.
TEST(IceVolumeFraction, ZeroFractionPieceMakesTheMaterialAbsentWithItsState) {
  const std::string b = object(kNowhere, 500, 13.9) + object(kRight, 300, 13.9, "<volumeFraction>0.0</volumeFraction>") +
                        object(kLeft, 3000, 1.39);
  auto ice = initialized(deck(object(kRight, 300, 1.2), b, 717.5));
  const auto& f = ice->fields();
  for (int i = 0; i < 2; ++i) {
    const IntVec3 c(i, 0, 0);
    EXPECT_NEAR(f[1].rho_CC[0](c), 1.39, 1e-14) << i;
    EXPECT_NEAR(f[1].temp_CC[0](c), 3000.0, 1e-12) << i;
    EXPECT_LT(f[0].rho_CC[0](c), 1e-11) << i;
  }
  for (int i = 2; i < 4; ++i) {
    const IntVec3 c(i, 0, 0);
    EXPECT_NEAR(f[1].rho_CC[0](c), 1e-12 * 13.9, 1e-26) << i;
    EXPECT_EQ(f[1].temp_CC[0](c), 300.0) << i;
    EXPECT_NEAR(f[0].rho_CC[0](c), 1.2, 1e-14) << i;
    EXPECT_NEAR(f[0].vol_frac_CC[0](c), 1.0, 1e-10) << i;
  }
}

// Uintah's absent value -1 reads as no volumeFraction (theta = covered
// share); values outside [0, 1] are deck errors naming the element.
TEST(IceVolumeFraction, MinusOneIsAbsentAndOutOfRangeIsADeckError) {
  auto ice = initialized(deck(object(kAll, 300, 1.2, "<volumeFraction>-1</volumeFraction>"),
                              object(kNowhere, 300, 1.0), 717.5));
  EXPECT_NEAR(ice->fields()[0].rho_CC[0](IntVec3(1, 0, 0)), 1.2, 1e-15);
  for (const char* bad : {"1.5", "-0.1"}) {
    const std::string text = deck(object(kAll, 300, 1.2, std::string("<volumeFraction>") + bad + "</volumeFraction>"),
                                  object(kNowhere, 300, 1.0), 717.5);
    auto d = load_deck_from_string(text, "volume_fraction.ups", ".");
    try {
      make_ice_component(*d);
      ADD_FAILURE() << "volumeFraction " << bad << " accepted";
    } catch (const DeckError& e) {
      EXPECT_NE(std::string(e.what()).find("volumeFraction"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace tephra
