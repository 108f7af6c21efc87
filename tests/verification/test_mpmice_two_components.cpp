// Two MPMICE components in one process are independent: advanced step by
// step alternately (A, B, A, B, ...) each must give the same bits as one
// component advanced alone. Any state kept per process (a static or
// thread_local cache that carries a value from one component's call to the
// other's) breaks this; with two different components (grid, dt, models)
// such a cache would hand one component the other's values. Session 18
// reported every array differing after 8 alternated steps (docs/mpmice.md
// "DDT0, Test, SolidReactionModel, MesoBurn"); session 19 could not
// reproduce it on this code (these cases pass; see that section).
//
// Oracle: the whole restart state (save_state: particles, nodes, cells of
// every material, model state) of each alternated component against the
// single run's, every step: 0 differing entries (bit-equality, no tolerance).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/deck/DeckLoader.h"
#include "core/io/StateArchive.h"
#include "core/grid/Loop.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using DeckMaker = std::function<std::unique_ptr<Deck>()>;

std::unique_ptr<MpmIceComponent> make(const DeckMaker& make_deck, std::unique_ptr<Deck>& deck) {
  deck = make_deck();
  auto c = make_mpmice_component(*deck);
  c->initialize();
  return c;
}

// Entries of two archives whose bits differ; `first` names the first array that differs.
long long differing(const StateArchive& a, const StateArchive& b, std::string& first) {
  long long n = 0;
  for (const auto& [name, va] : a.all_doubles()) {
    const std::vector<double>& vb = b.doubles(name);
    long long d = 0;
    if (va.size() != vb.size()) d = static_cast<long long>(std::max(va.size(), vb.size()));
    else
      for (std::size_t i = 0; i < va.size(); ++i) d += va[i] != vb[i] && !(va[i] != va[i] && vb[i] != vb[i]);
    if (d && first.empty()) first = name;
    n += d;
  }
  for (const auto& [name, va] : a.all_ints()) {
    const long long d = va != b.ints(name);
    if (d && first.empty()) first = name;
    n += d;
  }
  return n;
}

// Runs `steps` steps: each deck's component alone, then the two alternated
// (step n of the first, step n of the second, ...); every step, the entries
// of each alternated component that differ from its run alone.
void expect_alternated_equal_alone(const DeckMaker& first, double dt1, const DeckMaker& second, double dt2, int steps,
                                   int threads = 1) {
  set_thread_count(threads);
  const DeckMaker makers[2] = {first, second};
  const double dts[2] = {dt1, dt2};
  std::vector<StateArchive> alone[2];
  for (int r = 0; r < 2; ++r) {
    std::unique_ptr<Deck> d;
    auto a = make(makers[r], d);
    for (int n = 1; n <= steps; ++n) {
      a->advance((n - 1) * dts[r], dts[r], n);
      a->save_state(alone[r].emplace_back());
    }
  }
  std::unique_ptr<Deck> d[2];
  std::unique_ptr<MpmIceComponent> c[2] = {make(makers[0], d[0]), make(makers[1], d[1])};
  for (int n = 1; n <= steps; ++n) {
    for (int r = 0; r < 2; ++r) c[r]->advance((n - 1) * dts[r], dts[r], n);
    for (int r = 0; r < 2; ++r) {
      StateArchive s;
      c[r]->save_state(s);
      std::string name;
      const long long k = differing(alone[r][static_cast<std::size_t>(n - 1)], s, name);
      EXPECT_EQ(k, 0) << "component " << r << ", step " << n << ": first differing array " << name;
      if (k) {
        std::printf("component %d, step %d: %lld entries differ (first %s)\n", r, n, k, name.c_str());
        return;
      }
    }
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const std::string& massx_dir() {
  static const std::string d = test::shared_dir() + "/decks/inputs/MPMICE";
  return d;
}

// massX.ups (decks README A13) unchanged: a solid cube, Simple_Burn, 1e-4 s steps.
std::unique_ptr<Deck> massx() {
  return load_deck_from_string(read_file(massx_dir() + "/massX.ups"), "massX.ups", massx_dir());
}

// The quiescent block (inputs/mpmice, 5^3 cells) thrown at 5 m/s; no <Models>.
std::unique_ptr<Deck> moving_block() {
  std::string text = read_file(test::source_dir() + "/inputs/mpmice/quiescent_block.ups");
  const std::string at_rest = "<velocity>          [0.0,0.0,0.0]   </velocity>";  // the MPM block's
  text.replace(text.find(at_rest), at_rest.size(), "<velocity>[5.0,0.0,0.0]</velocity>");
  return load_deck_from_string(text, "block.ups", test::source_dir() + "/inputs/mpmice");
}

// The session-18 case (test_mpmice_mass_models, MesoBurn): massX in a closed
// box at 600 K, its <Models> replaced by MesoBurn, the gas at p_ref.
std::unique_ptr<Deck> mesoburn_box() {
  std::string s = read_file(massx_dir() + "/massX.ups");
  const std::string meso = R"(<Model type="MesoBurn">
        <fromMaterial> reactant </fromMaterial> <toMaterial> product </toMaterial>
        <IdealGasConst> 8.314 </IdealGasConst> <PreExpCondPh> 1.637e15 </PreExpCondPh>
        <ActEnergyCondPh> 1.76e5 </ActEnergyCondPh> <PreExpGasPh> 1.6e-3 </PreExpGasPh>
        <CondPhaseHeat> 4.0e5 </CondPhaseHeat> <GasPhaseHeat> 3.018e6 </GasPhaseHeat>
        <HeatConductGasPh> 0.07 </HeatConductGasPh> <HeatConductCondPh> 0.2 </HeatConductCondPh>
        <SpecificHeatBoth> 1.4e3 </SpecificHeatBoth> <MoleWeightGasPh> 0.0342 </MoleWeightGasPh>
        <BoundaryParticles> 3 </BoundaryParticles> <ThresholdPressure> 500 </ThresholdPressure>
        <Ta> 1000 </Ta> <k> 1e10 </k> <Cv> 1000 </Cv>
      </Model>)";
  s = s.substr(0, s.find("<Models>")) + "<Models>" + meso + s.substr(s.find("</Models>"));
  auto d = load_deck_from_string(s, "massX_meso.ups", massx_dir());
  for (DeckNode& face : test::deck_node(d->root, {"Grid", "BoundaryConditions"}).children)
    for (DeckNode& bc : face.children) {
      std::string label;
      for (auto& [k, v] : bc.attributes)
        if (k == "label") label = v;
      for (auto& [k, v] : bc.attributes)
        if (k == "var" && label == "Pressure") v = "Neumann";
        else if (k == "var" && label == "Velocity") v = "Dirichlet";
      if (label == "Pressure") bc.children.at(0).text = "0.0";
    }
  test::deck_node(d->root, {"MaterialProperties", "MPM", "material", "geom_object", "temperature"}).text = "600";
  test::deck_node(d->root, {"MaterialProperties", "ICE", "material", "geom_object", "temperature"}).text = "600";
  test::deck_node(d->root, {"MaterialProperties", "ICE", "material", "geom_object", "density"}).text =
      "0.58963449720670391";  // 101325/(0.4 x 716 x 600): p = p_ref
  d->root.finalize_parents();
  return d;
}

TEST(MpmIceTwoComponents, TwoIdenticalMassXAlternatedEqualOneAlone) {
  expect_alternated_equal_alone(massx, 1e-4, massx, 1e-4, 12);
}

TEST(MpmIceTwoComponents, MassXAndMovingBlockAlternatedEqualEachAlone) {
  expect_alternated_equal_alone(massx, 1e-4, moving_block, 1e-5, 12);
}

TEST(MpmIceTwoComponents, MesoBurnBoxAndMassXAlternatedEqualEachAlone) {
  expect_alternated_equal_alone(mesoburn_box, 1e-4, massx, 1e-4, 12);
}

TEST(MpmIceTwoComponents, TwoThreadsMesoBurnBoxAndMassXAlternatedEqualEachAlone) {
  expect_alternated_equal_alone(mesoburn_box, 1e-4, massx, 1e-4, 12, 2);
}

TEST(MpmIceTwoComponents, TwoThreadsMassXAndMovingBlockAlternatedEqualEachAlone) {
  expect_alternated_equal_alone(massx, 1e-4, moving_block, 1e-5, 12, 2);
}

}  // namespace
}  // namespace tephra
