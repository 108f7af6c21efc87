// ICE source models in full runs of a closed box (ice/models/, docs/algorithms/ice.md
// "Reactions and source models").
//
// mass_momentum_energy_src in a closed uniform box of one ideal gas, all six
// faces symmetry planes, 2 x 1 x 1 cells, the momentum source along y and z
// (one cell across, so every face velocity stays 0 and nothing is advected;
// no gradients, so no pressure work and no diffusion). The totals must then
// grow linearly at exactly the given rates (Vaango MassMomEng_src: per step
// dm = mass_src dt V theta, dp = momentum_src dt V theta,
// dE = energy_src dt V theta, theta = 1 for one material):
//   TotalMass(t)     = M0 + mass_src   Vbox t
//   TotalMomentum(t) =      momentum_src Vbox t
//   TotalIntEng(t)   = E0 + energy_src Vbox t       (internal energy sum M cv T)
// and nothing before mme_src_t_start.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "ice/IceComponent.h"
#include "ice/models/IceModel.h"
#include "mpmice/ComponentFactory.h"

namespace tephra {
namespace {

std::string box_deck(const std::string& models) {
  std::ostringstream s;
  s << R"(<Uintah_specification>
  <SimulationComponent type="ice"/>
  <Grid><BoundaryConditions>)";
  for (const char* f : {"x-", "x+", "y-", "y+", "z-", "z+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/></Face>";
  s << R"(</BoundaryConditions>
    <Level><Box label="1"><lower>[0,0,0]</lower><upper>[2e-2,1e-2,1e-2]</upper>
      <extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches><resolution>[2,1,1]</resolution></Box></Level>
  </Grid>
  <CFD><cfl>0.4</cfl><ICE><advection type="FirstOrder"/></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
    <material name="air"><EOS type="ideal_gas"/><dynamic_viscosity>0</dynamic_viscosity>
      <thermal_conductivity>0</thermal_conductivity><specific_heat>716.5</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="all"><min>[-1,-1,-1]</min><max>[1,1,1]</max></box><res>[2,2,2]</res>
        <velocity>[0,0,0]</velocity><temperature>300</temperature><density>1.1792946927374306</density>
        <pressure>101325</pressure></geom_object>
    </material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>[]</momentum><heat>[]</heat></exchange_coefficients></exchange_properties>
  </MaterialProperties>
  )" << models << "\n</Uintah_specification>\n";
  return s.str();
}

TEST(IceSourceModels, MassMomentumEnergySourceGrowsTotalsAtTheGivenRates) {
  const double rm = 2.0, re = 3e5;  // kg/(m^3 s), W/m^3
  const Vec3 rp(0, 40.0, -25.0);    // kg/(m^2 s^2)
  const double t_start = 1e-4;
  std::ostringstream m;
  m << "<Models><Model type=\"mass_momentum_energy_src\"><MassMomEng_src><material>air</material>"
    << "<mass_src>" << rm << "</mass_src><momentum_src>[0," << rp[1] << "," << rp[2] << "]</momentum_src>"
    << "<energy_src>" << re << "</energy_src><mme_src_t_start>" << t_start << "</mme_src_t_start>"
    << "</MassMomEng_src></Model></Models>";
  auto d = load_deck_from_string(box_deck(m.str()), "mme.ups", ".");
  auto ice = make_ice_component(*d);
  ice->initialize();
  const std::set<std::string> labels{"TotalMass", "TotalMomentum", "TotalIntEng", "TotalMass_src"};
  auto r0 = ice->reductions(labels);
  const double M0 = r0["TotalMass"][0], E0 = r0["TotalIntEng"][0];
  const double Vbox = 2e-2 * 1e-2 * 1e-2;
  // Fixed steps of 1e-5 s: 10 before t_start (no source), then 200 with it.
  const double dt = 1e-5;
  double t = 0;
  int n_active = 0;
  for (int step = 1; step <= 210; ++step) {
    ASSERT_LT(dt, ice->stable_timestep());
    ice->advance(t, dt, step);
    if (t >= t_start * (1 - 1e-12)) ++n_active;
    t += dt;
    if (step == 5) {  // before t_start: unchanged
      auto r = ice->reductions(labels);
      EXPECT_NEAR(r["TotalMass"][0], M0, 1e-14 * M0);
      EXPECT_NEAR(r["TotalIntEng"][0], E0, 1e-14 * E0);
    }
  }
  ASSERT_EQ(n_active, 200);
  const double ts = n_active * dt;  // time the source was on
  auto r = ice->reductions(labels);
  const double M = M0 + rm * Vbox * ts, E = E0 + re * Vbox * ts;
  std::printf("mass_momentum_energy_src: rel. errors mass %.2e, mom_y %.2e, mom_z %.2e, int. energy %.2e\n",
              std::abs(r["TotalMass"][0] / M - 1), std::abs(r["TotalMomentum"][1] / (rp[1] * Vbox * ts) - 1),
              std::abs(r["TotalMomentum"][2] / (rp[2] * Vbox * ts) - 1), std::abs(r["TotalIntEng"][0] / E - 1));
  EXPECT_NEAR(r["TotalMass"][0], M, 1e-12 * M);
  EXPECT_NEAR(r["TotalMomentum"][0], 0.0, 1e-15);
  EXPECT_NEAR(r["TotalMomentum"][1], rp[1] * Vbox * ts, 1e-12 * std::abs(rp[1] * Vbox * ts));
  EXPECT_NEAR(r["TotalMomentum"][2], rp[2] * Vbox * ts, 1e-12 * std::abs(rp[2] * Vbox * ts));
  EXPECT_NEAR(r["TotalIntEng"][0], E, 1e-12 * E);
  // The model's own sum over the last step: rm dt Vbox.
  EXPECT_NEAR(r["TotalMass_src"][0], rm * dt * Vbox, 1e-12 * rm * dt * Vbox);
}


// Deck layouts: parameters directly in <Model> (Vaango's schema), material
// by index; a misspelt parameter and t_final < t_start are DeckErrors.
TEST(IceSourceModels, MassMomentumEnergySourceDeckLayouts) {
  const std::string flat = "<Models><Model type=\"mass_momentum_energy_src\"><material>0</material>"
                           "<mass_src>1</mass_src><momentum_src>[0,0,0]</momentum_src><energy_src>0</energy_src>"
                           "</Model></Models>";
  auto d = load_deck_from_string(box_deck(flat), "mme.ups", ".");
  auto ice = make_ice_component(*d);
  ASSERT_EQ(ice->models().size(), 1u);
  EXPECT_EQ(ice->models()[0]->type(), "mass_momentum_energy_src");
  std::string bad = flat;
  bad.replace(bad.find("<mass_src>1</mass_src>"), 22, "<mass_srcs>1</mass_srcs>");
  EXPECT_THROW(make_ice_component(*load_deck_from_string(box_deck(bad), "mme.ups", ".")), DeckError);
  std::string window = flat;
  window.replace(window.find("<energy_src>"), 0, "<mme_src_t_start>2</mme_src_t_start><mme_src_t_final>1</mme_src_t_final>");
  EXPECT_THROW(make_ice_component(*load_deck_from_string(box_deck(window), "mme.ups", ".")), DeckError);
}

}  // namespace
}  // namespace tephra
