// ICE reaction and source models in full runs (ice/models/, docs/algorithms/ice.md
// "Reactions").
//
// Chapman-Jouguet state of a barotropic product EOS. Both the JWLC products
// (p = A e^{-R1 V} + B e^{-R2 V} + C V^{-(1+om)}, V = rho0/rho) and the
// Murnaghan reactant depend on density only, so mass and momentum alone fix
// a steady detonation: across the wave, from the unreacted state (rho0, p0,
// u = 0) to the products at relative volume V,
//   mass:     rho0 D = rho (D - u)            =>  u = D (1 - V)
//   momentum: p - p0 = rho0 D u = rho0 D^2 (1 - V)          (the Rayleigh line)
// The CJ state is the sonic point, where the Rayleigh line touches the
// product curve p(V):  rho0 D^2 = -dp/dV  and  p(V) - p0 = -dp/dV (1 - V).
// One equation in V, solved by bisection on [0.3, 0.99]; D_CJ = sqrt(-p'(V)/rho0).
// (Energy, and so E0, sets the temperature only.) ANFO (JWLEOSANFO.xml):
// V_CJ = 0.748, p_CJ = 10.2 GPa, D_CJ = 5.90 km/s; Comp-B (JWLEOSCompBProd.xml):
// V_CJ = 0.730, p_CJ = 30.3 GPa, D_CJ = 8.09 km/s (the LightTime deck's D is 8.1 km/s).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"
#include "core/io/StateArchive.h"
#include "tests/support/ChapmanJouguet.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

// The CJ state of tests/support/ChapmanJouguet (the derivation above).
using Jwlc = test::JwlcProducts;
using test::chapman_jouguet;
using test::CjState;

// The JWLC constants of an EOSData include, read back from the deck.
Jwlc jwlc_of(const DeckNode& eos) {
  return {eos.get_double("A"), eos.get_double("B"), eos.get_double("C"), eos.get_double("R1"),
          eos.get_double("R2"), eos.get_double("om"), eos.get_double("rho0")};
}

const DeckNode& product_eos(const Deck& d) {
  const DeckNode& ice = d.root.require_child("MaterialProperties").require_child("ICE");
  return ice.children_named("material")[1]->require_child("EOS");
}

double cell_x(const Grid& g, int i) { return g.lower[0] + (i + 0.5) * g.dx[0]; }

// The model field `label` of the first model (F, delF, ...).
const CellScalars& model_field(const IceComponent& ice, const std::string& label) {
  for (const IceModelP& m : ice.models())
    for (const ModelField& f : m->fields())
      if (f.label == label) return *f.field;
  throw std::runtime_error("no model field " + label);
}

// ICE/LightTime.ups (decks README A15): programmed burn of a 1-D Comp-B stick
// at D = 8.1 km/s, run to 8 us with n cells of the 0.16 m stick (the deck's
// 640 cells of 0.25 mm cost minutes; its transverse 0.25 mm is set to the cell
// size, since the conservative time step also counts the transverse faces).
// Oracles: (1) the burn front is at D t cell-wise: after the step that
// started at t_n, exactly the cells with centre x_c <= D t_n have F > 0;
// (2) the peak pressure approaches the CJ pressure of the products (derived
// above) from below as the cells shrink (a programmed burn at D ~ D_CJ drives
// the products to the CJ state, smeared over the ~1.5-cell front): it rises
// from 2 mm to 1 mm cells and stays within [0.8, 1.02] p_CJ. (The unchanged
// deck to 12 us: 0.903 p_CJ, docs/algorithms/ice.md.)
struct LightTimeRun {
  double peak = 0;
};

LightTimeRun light_time(int cells, const CjState& cj) {
  const double dx = 0.16 / cells, D = 8.1e3, t_end = 8e-6;
  test::IceRun r = test::make_ice_run(test::shared_dir() + "/decks/inputs/ICE/LightTime.ups", [&](DeckNode& root) {
    test::deck_node(root, {"Grid", "Level", "Box", "resolution"}).text = "[" + std::to_string(cells) + ", 1, 1]";
    std::ostringstream up;
    up << "[0.16, " << dx << ", " << dx << "]";
    test::deck_node(root, {"Grid", "Level", "Box", "upper"}).text = up.str();
  });
  EXPECT_NEAR(chapman_jouguet(jwlc_of(product_eos(*r.deck)), 101325.0).D, cj.D, 1e-9);
  const Grid& g = r.ice->grid();
  LightTimeRun out;
  double t_last = 0;
  const double delt_init = r.deck->root.require_child("Time").get_double("delt_init");
  while (r.time < t_end * (1 - 1e-14)) {
    double dt = r.steps == 0 ? delt_init : r.ice->stable_timestep();
    dt = std::min(dt, t_end - r.time);
    t_last = r.time;
    r.ice->advance(r.time, dt, ++r.steps);
    r.time += dt;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        out.peak = std::max(out.peak, r.ice->press_CC()[pi](i, j, k));
      });
  }
  const CellScalars& F = model_field(*r.ice, "F");
  int lit = 0, wrong = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const bool reached = cell_x(g, i) <= D * t_last;
      const bool burning = F[pi](i, j, k) > 0;
      lit += burning;
      wrong += reached != burning;
    });
  std::printf("LightTime %d cells: %d steps to t = %.3g s, %d cells lit (front at D t = %.4f m), peak p = %.4g GPa, "
              "p_CJ = %.4g GPa (ratio %.3f)\n",
              cells, r.steps, r.time, lit, D * t_last, out.peak / 1e9, cj.p / 1e9, out.peak / cj.p);
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(lit, int(std::floor(D * t_last / g.dx[0] + 0.5)));
  return out;
}

TEST(IceReactions, LightTimeFrontAtDtAndPeakPressureTowardsCJ) {
  set_thread_count(1);
  // Comp-B products (JWLEOSCompBProd.xml, scaled by 1.014 for this deck).
  const CjState cj = chapman_jouguet({5.0999434e11, 4.0522056e9, 1.3233369e9, 4.06244, 0.94846, 0.35, 1717.0}, 101325.0);
  EXPECT_NEAR(cj.D, 8089, 2);  // the deck's D = 8.1 km/s
  const LightTimeRun coarse = light_time(80, cj), fine = light_time(160, cj);
  EXPECT_GT(fine.peak, coarse.peak);
  EXPECT_GT(fine.peak / cj.p, 0.8);
  EXPECT_LT(fine.peak / cj.p, 1.02);
}

// A 1-D JWL++ detonation in ANFO (Murnaghan reactant and JWLC products from
// the EOSData files, the rate constants of ICE/JWLpp8mmRS.ups),
// 1 cell across, initiated by a 2 mm booster of products at the CJ density
// against the symmetry plane x = 0 (at T = 300 K + E0/c_v, the temperature of
// burned products: the JWLC products' pressure does not depend on T, and a
// colder booster runs out of internal energy in its expansion). The front (first cell from the right with
// F >= 0.5) is sampled every step; its speed from a least-squares line over
// the second half of the run must be within 3 % of D_CJ of the products.
std::string anfo_deck(double length, int cells, double rho_booster) {
  const std::string eos = test::shared_dir() + "/decks/inputs/ICE/EOSData/";
  std::ostringstream s;
  s << R"(<Uintah_specification><SimulationComponent type="ice"/>
  <Time><maxTime>1</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1e-6</delt_max>
    <delt_init>1e-9</delt_init><timestep_multiplier>1</timestep_multiplier></Time>
  <Grid><BoundaryConditions>
    <Face side="x-"><BCType id="all" var="symmetry" label="Symmetric"/></Face>
    <Face side="x+">
      <BCType id="all" label="Pressure" var="Neumann"><value>0</value></BCType>
      <BCType id="all" label="Velocity" var="Neumann"><value>[0,0,0]</value></BCType>
      <BCType id="all" label="Temperature" var="Neumann"><value>0</value></BCType>
      <BCType id="all" label="Density" var="Neumann"><value>0</value></BCType>
      <BCType id="all" label="SpecificVol" var="computeFromDensity"><value>0</value></BCType>
    </Face>)";
  for (const char* f : {"y-", "y+", "z-", "z+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"/></Face>";
  const double dx = length / cells;
  s << R"(</BoundaryConditions>
    <Level><Box label="1"><lower>[0,0,0]</lower><upper>[)" << length << "," << dx << "," << dx << R"(]</upper>
      <extraCells>[1,1,1]</extraCells><patches>[2,1,1]</patches><resolution>[)" << cells << R"(,1,1]</resolution></Box></Level>
  </Grid>
  <DataArchiver><filebase>anfo.uda</filebase><outputInterval>1</outputInterval></DataArchiver>
  <CFD><cfl>0.5</cfl><ICE><advection type="FirstOrder"/>
    <TimestepControl><Scheme_for_delT_calc>aggressive</Scheme_for_delT_calc><knob_for_speedSound>1.0</knob_for_speedSound></TimestepControl>
    <ClampSpecificVolume>true</ClampSpecificVolume></ICE></CFD>
  <PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>
  <MaterialProperties><ICE>
    <material name="reactant"><include href=")" << eos << R"(MurnaghanEOSANFO.xml"/>
      <dynamic_viscosity>0</dynamic_viscosity><thermal_conductivity>0</thermal_conductivity>
      <specific_heat>1515.31</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="charge"><min>[2e-3,-1,-1]</min><max>[1,1,1]</max></box><res>[2,2,2]</res>
        <velocity>[0,0,0]</velocity><temperature>300</temperature><density>1160</density><pressure>101325</pressure></geom_object>
    </material>
    <material name="product"><include href=")" << eos << R"(JWLEOSANFO.xml"/>
      <dynamic_viscosity>0</dynamic_viscosity><thermal_conductivity>0</thermal_conductivity>
      <specific_heat>544.96</specific_heat><gamma>1.4</gamma>
      <geom_object><box label="booster"><min>[-1,-1,-1]</min><max>[2e-3,1,1]</max></box><res>[2,2,2]</res>
        <velocity>[0,0,0]</velocity><temperature>10500</temperature><density>)" << rho_booster << R"(</density><pressure>101325</pressure></geom_object>
    </material>
  </ICE>
  <exchange_properties><exchange_coefficients><momentum>[1e15]</momentum><heat>[1e15]</heat></exchange_coefficients></exchange_properties>
  </MaterialProperties>
  <Models><Model type="JWLpp">
    <fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>
    <G>3.5083e-7</G><b>1.3</b><rho0>1160.0</rho0><E0>5.558e6</E0><ThresholdPressure>200000000.</ThresholdPressure>
  </Model></Models>
</Uintah_specification>)";
  return s.str();
}

struct AnfoFront {
  double speed = 0, peak = 0;
};

// Runs the 1-D stick of `cells` cells over `length` to t_end (or until the
// front is 5 mm from the outflow face) and returns the front speed (least
// squares over the second half of the per-step samples) and the peak pressure.
AnfoFront anfo_front(double length, int cells, double t_end, const Jwlc& anfo, const CjState& cj) {
  test::IceRun r;
  r.deck = load_deck_from_string(anfo_deck(length, cells, anfo.rho0 / cj.V), "anfo1d.ups", ".");
  // The include carries the same constants the test derives D_CJ from.
  const Jwlc file = jwlc_of(product_eos(*r.deck));
  EXPECT_EQ(file.A, anfo.A);
  EXPECT_EQ(file.R1, anfo.R1);
  r.ice = make_ice_component(*r.deck);
  r.ice->initialize();
  const Grid& g = r.ice->grid();
  std::vector<double> ts, xs;
  AnfoFront out;
  while (r.time < t_end) {
    const double dt = r.steps == 0 ? 1e-9 : std::min(r.ice->stable_timestep(), 1e-6);
    r.ice->advance(r.time, dt, ++r.steps);
    r.time += dt;
    // Front: the largest x_c whose product mass fraction is >= 1/2.
    double front = 0;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        const double rr = r.ice->fields()[0].rho_CC[pi](i, j, k), rp = r.ice->fields()[1].rho_CC[pi](i, j, k);
        if (rp / (rr + rp) >= 0.5) front = std::max(front, cell_x(g, i));
        out.peak = std::max(out.peak, r.ice->press_CC()[pi](i, j, k));
      });
    if (front > length - 5e-3) break;  // stop before the outflow face
    ts.push_back(r.time);
    xs.push_back(front);
  }
  // Least-squares speed over the second half of the samples.
  const std::size_t n0 = ts.size() / 2;
  double st = 0, sx = 0, stt = 0, stx = 0;
  const double n = double(ts.size() - n0);
  for (std::size_t i = n0; i < ts.size(); ++i) {
    st += ts[i];
    sx += xs[i];
    stt += ts[i] * ts[i];
    stx += ts[i] * xs[i];
  }
  out.speed = (n * stx - st * sx) / (n * stt - st * st);
  std::printf("JWL++ ANFO 1-D, dx = %.3g mm: %d steps, t = %.3g s, front %.4f m; speed %.1f m/s vs D_CJ %.1f m/s "
              "(%.2f %%); peak p %.3g GPa vs p_CJ %.3g GPa\n",
              1e3 * length / cells, r.steps, r.time, xs.back(), out.speed, cj.D, 100 * (out.speed / cj.D - 1),
              out.peak / 1e9, cj.p / 1e9);
  return out;
}

// The steady speed converges to D_CJ with the cell size: 1, 0.5 and 0.25 mm
// cells (the JWL++ reaction zone of ANFO is a few mm long, so 1 mm cells
// hold about 2 cells of it). The deficit 1 - D/D_CJ must fall at each
// halving and be within 3 % at 0.5 mm and 2 % at 0.25 mm (the issue's 3 %).
// Measured: 5704.5, 5789.2, 5811.9 m/s = -3.30, -1.87, -1.48 % (observed
// orders 0.82, 0.33: what is left at 0.25 mm is mostly the front still
// accelerating over the 12 cm run, not dx); 13.7 s CPU for the three runs.
TEST(IceReactions, JwlppAnfoDetonationRunsAtTheChapmanJouguetSpeed) {
  set_thread_count(1);
  const Jwlc anfo{2.9867e11, 4.11706e9, 7.206147e8, 4.95, 1.15, 0.35, 1160.0};
  const CjState cj = chapman_jouguet(anfo, 101325.0);
  const double length = 0.12, t_end = 20e-6;
  double deficit[3];
  const int cells[3] = {120, 240, 480};
  for (int i = 0; i < 3; ++i) deficit[i] = 1 - anfo_front(length, cells[i], t_end, anfo, cj).speed / cj.D;
  for (int i = 1; i < 3; ++i)
    std::printf("deficit %.4f -> %.4f: observed order %.2f\n", deficit[i - 1], deficit[i],
                std::log2(deficit[i - 1] / deficit[i]));
  EXPECT_GT(deficit[0], deficit[1]);
  EXPECT_GT(deficit[1], deficit[2]);
  EXPECT_LT(std::abs(deficit[1]), 0.03);
  EXPECT_LT(std::abs(deficit[2]), 0.02);
}

}  // namespace
}  // namespace tephra

namespace tephra {
namespace {

// PassiveScalar on ICE/advect.ups (uniform air at (1,1,1) m/s, 5 m box, here
// with 0.25 m cells): a scalar blob (q = 1 in the cube [2,3]^3) is carried with
// the air's mass fluxes. Oracles: with no decay sum M q is conserved to
// round-off (the blob stays 8 cells from the boundaries for the deck's
// 0.01 s); with decayRate k the per-step source q (e^{-k dt} - 1) makes
// sum M q(t) = e^{-k t} sum M q(0) to round-off (the mass is unchanged).
// The schema layout (<scalar> directly in <Model>, geom_objects inside it) and
// the Vaango-code layout (<PassiveScalar><material/><scalar>...<initialization>)
// are both read; the second call uses the schema layout.
double scalar_total(double decay, double* initial, bool schema_layout = false) {
  auto edit = [&](DeckNode& root) {
    test::deck_node(root, {"Grid", "Level", "spacing"}).text = "[0.25, 0.25, 0.25]";
    std::ostringstream m;
    const char* blob = R"(<geom_object><box label="blob"><min>[2,2,2]</min><max>[3,3,3]</max></box><scalar>1</scalar></geom_object>)";
    if (schema_layout)
      m << R"(<Uintah_specification><Models><Model type="PassiveScalar"><scalar name="f"><material>0</material>
        <constants><decayRate>)" << decay << R"(</decayRate><diffusivity>0</diffusivity></constants>)" << blob
        << R"(</scalar></Model></Models></Uintah_specification>)";
    else
      m << R"(<Uintah_specification><Models><Model type="PassiveScalar"><PassiveScalar><material>0</material>
      <scalar name="f"><test_conservation>true</test_conservation>
        <constants><decayRate>)" << decay << R"(</decayRate><diffusivity>0</diffusivity></constants>
        <initialization>)" << blob << R"(</initialization>
      </scalar></PassiveScalar></Model></Models></Uintah_specification>)";
    auto snippet = load_deck_from_string(m.str(), "models.xml", ".");
    root.children.push_back(snippet->root.children[0]);
  };
  test::IceRun r = test::make_ice_run(test::shared_dir() + "/decks/inputs/ICE/advect.ups", edit);
  const std::set<std::string> label = {"totalSum_scalar-f"};
  *initial = r.ice->reductions(label).at("totalSum_scalar-f")[0];
  test::run_to(r);
  EXPECT_GE(r.steps, 7);
  const double now = r.ice->reductions(label).at("totalSum_scalar-f")[0];
  return now / std::exp(-decay * r.time);
}

TEST(IceReactions, PassiveScalarBlobConservesItsIntegral) {
  set_thread_count(1);
  double s0 = 0;
  const double s1 = scalar_total(0.0, &s0);
  ASSERT_GT(s0, 0.0);
  std::printf("PassiveScalar: sum M q relative change %.3g (no decay)\n", s1 / s0 - 1);
  EXPECT_NEAR(s1, s0, 1e-13 * s0);
  const double s2 = scalar_total(50.0, &s0, true);  // e^{-50 * 0.01} = 0.61
  std::printf("PassiveScalar: sum M q e^{kt} relative change %.3g (k = 50/s)\n", s2 / s0 - 1);
  EXPECT_NEAR(s2, s0, 1e-13 * s0);
}

// Stability sweep of <cfl> on the JWL++ ANFO detonation (the 60-cell, 3 cm
// tube above with its open x+ end, run to 3 us, aggressive time step,
// the deck's first-order advection; two materials, so Uintah's energy
// equation: docs/algorithms/ice.md "Total energy at shocks"). Each run either
// reaches 3 us with finite, positive states (check_state after every step) or
// stops with NumericalFailure (exit 4 through tephra) naming the cell; any
// other exception fails. Measured (docs/algorithms/ice.md "Stability"): cfl 0.1 ... 1.2
// complete (no dt/2 restart; mass burned 3.46e-6 kg at 0.1, 3.32e-6 at 0.9,
// 3.19e-6 at 1.2); 1.5, 2, 3 stop at steps 4, 3, 2 (a cell would lose more
// than its content). The 1-D aggressive step dx/(c + |u|) with the cell's c
// leaves the face-swept fraction below 1 up to cfl ~1.2 here (Sod: 1.0 stops).
TEST(IceReactions, DetonationCflSweepStopsCleanlyAboveTheLimit) {
  set_thread_count(1);
  const std::string base = anfo_deck(0.03, 60, 1160.0 / 0.748);
  double burned_ref = 0;
  for (double cfl : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0, 1.2, 1.5, 2.0, 3.0}) {
    std::string text = base;
    const std::size_t a = text.find("<cfl>"), b = text.find("</cfl>");
    text.replace(a, b + 6 - a, "<cfl>" + std::to_string(cfl) + "</cfl>");
    test::IceRun r;
    r.deck = load_deck_from_string(text, "anfo_cfl.ups", ".");
    r.ice = make_ice_component(*r.deck);
    r.ice->initialize();
    std::string stop;
    double burned = 0;
    try {
      while (r.time < 3e-6) {
        const double dt = r.steps == 0 ? 1e-9 : r.ice->stable_timestep();
        r.ice->advance(r.time, dt, ++r.steps);
        r.time += dt;
        burned += r.ice->reductions({"totalMassBurned"})["totalMassBurned"][0];
      }
    } catch (const NumericalFailure& e) {
      stop = e.what();
    }
    std::printf("ANFO cfl %.2f: %s after %d steps (%d dt/2 restarts), t = %.3g s, burned %.3g kg %s\n", cfl,
                stop.empty() ? "completes" : "exit 4", r.steps, r.ice->step_restarts(), r.time, burned,
                stop.substr(0, 160).c_str());
    if (cfl == 0.1) burned_ref = burned;
    if (cfl <= 1.2) {
      EXPECT_TRUE(stop.empty()) << "cfl " << cfl << ": " << stop;
      // The burn to ~3 us is the same within 5 % up to cfl 1 (measured -4 % at 0.9, -8 % at 1.2).
      if (cfl <= 1.0) EXPECT_NEAR(burned, burned_ref, 0.05 * burned_ref) << "cfl " << cfl;
    } else {
      EXPECT_FALSE(stop.empty()) << "cfl " << cfl << " completes: the recorded limit moved";
    }
  }
}

// Mass through a reacting run: the ANFO detonation in a closed tube (x+ made
// a symmetry plane), 60 cells, 3 us: reactant + product mass stays constant to
// round-off while a large share of the charge burns.
TEST(IceReactions, ReactingRunConservesMass) {
  set_thread_count(1);
  std::string text = anfo_deck(0.03, 60, 1160.0 / 0.748);
  const std::size_t a = text.find("<Face side=\"x+\">"), b = text.find("</Face>", a) + 7;
  text.replace(a, b - a, R"(<Face side="x+"><BCType id="all" var="symmetry" label="Symmetric"/></Face>)");
  test::IceRun r;
  r.deck = load_deck_from_string(text, "closed.ups", ".");
  r.ice = make_ice_component(*r.deck);
  r.ice->initialize();
  const std::set<std::string> labels = {"TotalMass"};
  const double m0 = r.ice->reductions(labels)["TotalMass"][0];
  double burned = 0;
  while (r.time < 3e-6) {
    const double dt = r.steps == 0 ? 1e-9 : r.ice->stable_timestep();
    r.ice->advance(r.time, dt, ++r.steps);
    r.time += dt;
    burned += r.ice->reductions({"totalMassBurned"})["totalMassBurned"][0];
  }
  const double m1 = r.ice->reductions(labels)["TotalMass"][0];
  std::printf("closed ANFO tube: %d steps, burned %.3g of %.3g kg, mass relative change %.3g\n", r.steps, burned, m0,
              m1 / m0 - 1);
  EXPECT_GT(burned, 0.3 * m0);
  EXPECT_NEAR(m1, m0, 1e-13 * m0);
}

}  // namespace
}  // namespace tephra

namespace tephra {
namespace {

// ICE/JWLpp8mmRS.ups (decks README C1, 100 x 15 x 15, three materials, JWLpp
// with its parameters directly under <Model>) starts: it builds, its saved F
// is a known label, and the first step completes (its tiny product material
// needs the dt/2 restarts in the symmetry corner) with F in [0, 1].
TEST(IceReactions, Jwlpp8mmRateStickStarts) {
  set_thread_count(2);
  test::IceRun r = test::make_ice_run(test::shared_dir() + "/decks/inputs/ICE/JWLpp8mmRS.ups");
  EXPECT_TRUE(r.ice->known_labels().count("F"));
  ASSERT_EQ(r.ice->models().size(), 1u);
  EXPECT_EQ(r.ice->models()[0]->type(), "JWLpp");
  test::run_to(r, -1, 1);
  EXPECT_EQ(r.steps, 1);
  const CellScalars& F = model_field(*r.ice, "F");
  const Grid& g = r.ice->grid();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      EXPECT_TRUE(F[pi](i, j, k) >= 0.0 && F[pi](i, j, k) <= 1.0);
    });
}

}  // namespace
}  // namespace tephra

namespace tephra {
namespace {

// A checkpoint of a reacting run (ANFO, 60 cells, after 40 steps) restored
// into a fresh component continues bit for bit, F included.
TEST(IceReactions, ReactingRestartContinuesBitForBit) {
  set_thread_count(1);
  const std::string text = anfo_deck(0.03, 60, 1160.0 / 0.748);
  auto make = [&] {
    test::IceRun r;
    r.deck = load_deck_from_string(text, "anfo.ups", ".");
    r.ice = make_ice_component(*r.deck);
    r.ice->initialize();
    return r;
  };
  auto step_to = [](test::IceRun& r, int n) {
    while (r.steps < n) {
      const double dt = r.steps == 0 ? 1e-9 : r.ice->stable_timestep();
      r.ice->advance(r.time, dt, ++r.steps);
      r.time += dt;
    }
  };
  test::IceRun a = make();
  step_to(a, 40);
  StateArchive ar;
  a.ice->save_state(ar);
  test::IceRun b = make();
  b.ice->load_state(ar);
  b.time = a.time;
  b.steps = a.steps;
  step_to(a, 80);
  step_to(b, 80);
  const auto& Fa = model_field(*a.ice, "F")[0];
  const auto& Fb = model_field(*b.ice, "F")[0];
  double Fmax = 0;
  for (std::size_t i = 0; i < Fa.size(); ++i) {
    ASSERT_EQ(Fa.data()[i], Fb.data()[i]);
    Fmax = std::max(Fmax, Fa.data()[i]);
  }
  EXPECT_GT(Fmax, 0.5);  // the charge is burning
  for (std::size_t m = 0; m < 2; ++m) {
    const auto& ra = a.ice->fields()[m].rho_CC[0];
    const auto& rb = b.ice->fields()[m].rho_CC[0];
    for (std::size_t i = 0; i < ra.size(); ++i) ASSERT_EQ(ra.data()[i], rb.data()[i]);
  }
}

}  // namespace
}  // namespace tephra
