// Contracts every registered ICE equation of state must meet (models/eos):
//   dp/drho|_e and dp/de|_rho against central finite differences of p(rho, T)
//     (dp/de = (dp/dT)/c_v, e = c_v T),
//   beta = (dp/dT)/(rho dp/drho) (cyclic relation) against the same differences,
//   c^2 = dp/drho + p/rho^2 dp/de > 0 over the sample states,
//   rho(p(rho, T), T) = rho,
//   the closed form at a reference state (hand-evaluated formula in each case),
// and every EOS include of Vaango's EOSData folder parses in an ICE deck.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "ice/IceComponent.h"
#include "models/eos/EquationOfState.h"
#include "tests/support/SolidModelDriver.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using test::MapModelParameters;

struct Sample {
  std::map<std::string, double> params;
  EosMaterialConstants constants;
  std::vector<std::pair<double, double>> states;  // (rho, T) in the valid range
  // Heat capacity of de = c_v dT (Thomsen-Hartka's is p, T dependent).
  std::function<double(double rho, double T, double p)> cv;
  std::function<void(const EquationOfState&)> reference;  // closed-form check
};

double rel(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300}); }

const std::map<std::string, Sample>& samples() {
  static const std::map<std::string, Sample> table = [] {
    std::map<std::string, Sample> t;
    const auto const_cv = [](double cv) { return [cv](double, double, double) { return cv; }; };
    // Ideal gas, air: p = (gamma - 1) rho cv T; at rho = 1.2, T = 300: 0.4 * 1.2 * 717.5 * 300 = 103320.
    t["ideal_gas"] = {{}, {1.4, 717.5}, {{0.1, 200}, {1.2, 300}, {10, 1000}}, const_cv(717.5),
                      [](const EquationOfState& e) { EXPECT_NEAR(e.at(1.2, 300).p, 103320.0, 1e-9); }};
    // Hard-sphere gas, b = 1e-3: p = 0.4 * 100 * 717.5 * 300/(1 - 0.1) = 9566666.67.
    t["hard_sphere_gas"] = {{{"b", 1e-3}}, {1.4, 717.5}, {{0.1, 200}, {100, 300}, {500, 1000}}, const_cv(717.5),
                            [](const EquationOfState& e) {
                              EXPECT_LT(rel(e.at(100, 300).p, 0.4 * 100 * 717.5 * 300 / 0.9), 1e-14);
                            }};
    // TST with the parameters of Vaango's SteadyBurn_2dRT.ups (product gas).
    // Reference: rho = 100, T = 2000, v = 0.01:
    //   p = 0.63 * 514.96 * 2000/(v - b) - a/((v - 0.5 b)(v + 3 b)).
    t["TST"] = {{{"a", -260.1385968}, {"b", 7.955153678e-4}, {"u", -0.5}, {"w", 3.0}, {"Gamma", 1.63}},
                {1.63, 514.96},
                {{1, 300}, {100, 2000}, {800, 3000}},
                const_cv(514.96),
                [](const EquationOfState& e) {
                  const double v = 0.01, b = 7.955153678e-4, a = -260.1385968;
                  const double p = 0.63 * 514.96 * 2000 / (v - b) - a / ((v - 0.5 * b) * (v + 3 * b));
                  EXPECT_LT(rel(e.at(100, 2000).p, p), 1e-14);
                }};
    // JWL, LX-17 products (EOSData/JWLEOSLX-17Product.xml; cv = Cv/rho0 = 1e6/1905).
    // At rho = rho0 (V = 1): p = A e^-R1 + B e^-R2 + om cv T rho0.
    {
      const double cv = 1e6 / 1905;
      t["JWL"] = {{{"A", 1669.3e9}, {"B", 48.61e9}, {"R1", 6.2}, {"R2", 2.2}, {"om", 0.5}, {"rho0", 1905}},
                  {1.4, cv},
                  {{10, 300}, {500, 1500}, {1905, 3000}, {2500, 300}},
                  const_cv(cv),
                  [cv](const EquationOfState& e) {
                    const double p = 1669.3e9 * std::exp(-6.2) + 48.61e9 * std::exp(-2.2) + 0.5 * cv * 3000 * 1905;
                    EXPECT_LT(rel(e.at(1905, 3000).p, p), 1e-14);
                  }};
    }
    // JWLC, ANFO (EOSData/JWLEOSANFO.xml). At rho0: p = A e^-R1 + B e^-R2 + C.
    t["JWLC"] = {{{"A", 2.9867e11}, {"B", 4.11706e9}, {"C", 7.206147e8}, {"R1", 4.95}, {"R2", 1.15}, {"om", 0.35},
                  {"rho0", 1160}},
                 {1.4, 544.96},
                 {{10, 300}, {500, 300}, {1160, 300}, {2000, 300}},
                 const_cv(544.96),
                 [](const EquationOfState& e) {
                   const double p = 2.9867e11 * std::exp(-4.95) + 4.11706e9 * std::exp(-1.15) + 7.206147e8;
                   EXPECT_LT(rel(e.at(1160, 300).p, p), 1e-14);
                 }};
    // Murnaghan, ANFO (EOSData/MurnaghanEOSANFO.xml). p(rho0) = P0;
    // p(1.1 rho0) = P0 + (1.1^7.4 - 1)/(7.4 K).
    t["Murnaghan"] = {{{"K", 39e-11}, {"n", 7.4}, {"P0", 101325}, {"rho0", 1160}},
                      {1.4, 1515.31},
                      {{1159.99, 300}, {1200, 300}, {1500, 300}},
                      const_cv(1515.31),
                      [](const EquationOfState& e) {
                        EXPECT_LT(rel(e.at(1160, 300).p, 101325), 1e-14);
                        EXPECT_LT(rel(e.at(1276, 300).p, 101325 + (std::pow(1.1, 7.4) - 1) / (7.4 * 39e-11)), 1e-12);
                      }};
    // Birch-Murnaghan with the same constants; x = 1.1:
    //   p = P0 + 3/(2K)(x^(7/3) - x^(5/3))(1 + 3/4 (n - 4)(x^(2/3) - 1)).
    t["BirchMurnaghan"] = {{{"K", 39e-11}, {"n", 7.4}, {"P0", 101325}, {"rho0", 1160}},
                           {1.4, 1515.31},
                           {{1159.99, 300}, {1200, 300}, {1500, 300}},
                           const_cv(1515.31),
                           [](const EquationOfState& e) {
                             const double x = 1.1;
                             const double p = 101325 + 1.5 / 39e-11 * (std::pow(x, 7.0 / 3) - std::pow(x, 5.0 / 3)) *
                                                           (1 + 0.75 * 3.4 * (std::pow(x, 2.0 / 3) - 1));
                             EXPECT_LT(rel(e.at(1276, 300).p, p), 1e-12);
                             EXPECT_LT(rel(e.at(1160, 300).p, 101325), 1e-14);
                           }};
    // Linear Gruneisen-type (water-like constants): p(rho0, T0) = P0,
    // p(1010, 310) = P0 + A 0.01 + B 10.
    t["Gruneisen"] = {{{"A", 2.2e9}, {"B", 1e6}, {"rho0", 1000}, {"T0", 300}, {"P0", 101325}},
                      {1.4, 4180},
                      {{990, 280}, {1000, 300}, {1100, 400}},
                      const_cv(4180),
                      [](const EquationOfState& e) {
                        EXPECT_LT(rel(e.at(1000, 300).p, 101325), 1e-14);
                        EXPECT_LT(rel(e.at(1010, 310).p, 101325 + 2.2e7 + 1e7), 1e-14);
                      }};
    // Tillotson (granite-like constants). At rho0 (mu = 0), E = 1.034777e-5 Es:
    //   p = E rho0 (a + b/(E/E0 + 1)).
    t["Tillotson"] = {{{"a", 0.5}, {"b", 1.3}, {"A", 18e9}, {"B", 18e9}, {"E0", 16e6}, {"Es", 3.5e6}, {"Esp", 18e6},
                       {"alpha", 5}, {"beta", 5}, {"rho0", 2700}},
                      {1.4, 790},
                      {{2000, 300}, {2600, 300}, {3000, 300}},
                      const_cv(790),
                      [](const EquationOfState& e) {
                        const double E = 1.034777e-5 * 3.5e6;
                        EXPECT_LT(rel(e.at(2700, 300).p, E * 2700 * (0.5 + 1.3 / (E / 16e6 + 1))), 1e-14);
                      }};
    // Thomsen-Hartka water. Reference: the closed-form inverse rho(p, T) = 1/(vo(1 - ko p + L x^2))
    // at p = 1e7, T = 300 gives back p.
    {
      const double a = 2e-7, b = 2.6, co = 4205.7, ko = 5e-10, To = 277, L = 8e-6, vo = 1.00008e-3;
      t["Thomsen_Hartka_water"] = {
          {{"a", a}, {"b", b}, {"co", co}, {"ko", ko}, {"To", To}, {"L", L}, {"vo", vo}},
          {1.4, 4180},
          {{995, 300}, {1000, 290}, {1010, 320}},
          [=](double, double T, double p) { return co + b * (To - T) + 2 * p * L * vo * (To - a * p - 2 * T); },
          [=](const EquationOfState& e) {
            const double p = 1e7, T = 300, x = a * p + T - To;
            const double rho = 1 / (vo * (1 - ko * p + L * x * x));
            EXPECT_LT(rel(e.at(rho, T).p, p), 1e-9);
          }};
    }
    // Knauss sea water, Vaango's defaults: p(rho0, T0) = P0, p(rho0 + 1, T0) = P0 + 1/K.
    t["KnaussSeaWater"] = {{},
                           {1.4, 3985},
                           {{1020, 280}, {1027, 283.15}, {1040, 300}},
                           const_cv(3985),
                           [](const EquationOfState& e) {
                             EXPECT_LT(rel(e.at(1027, 283.15).p, 101325), 1e-14);
                             EXPECT_LT(rel(e.at(1028, 283.15).p, 101325 + 1 / 4.5e-7), 1e-12);
                           }};
    return t;
  }();
  return table;
}

EquationOfStateP make(const std::string& type) {
  const Sample& s = samples().at(type);
  MapModelParameters p(s.params);
  return create_equation_of_state(type, p, s.constants);
}

TEST(EosContracts, EveryRegisteredEosHasASample) {
  for (const std::string& type : equation_of_state_types()) EXPECT_TRUE(samples().count(type)) << type;
  // Every Vaango type is registered except KumariDass (EquationOfStateRegistry.cpp).
  EXPECT_EQ(equation_of_state_types().size() + 1, vaango_equation_of_state_types().size());
}

class EosContract : public ::testing::TestWithParam<std::string> {};

TEST_P(EosContract, DerivativesMatchFiniteDifferences) {
  const Sample& s = samples().at(GetParam());
  const EquationOfStateP eos = make(GetParam());
  for (auto [rho, T] : s.states) {
    const EosState st = eos->at(rho, T);
    // Small steps: Murnaghan's expansion branch has exponent 1/(K P0) = 25316,
    // whose central-difference truncation error is (25316 h/rho)^2/6.
    const double hr = 1e-8 * rho, hT = 1e-7 * T;
    const double dp_drho = (eos->at(rho + hr, T).p - eos->at(rho - hr, T).p) / (2 * hr);
    const double dp_dT = (eos->at(rho, T + hT).p - eos->at(rho, T - hT).p) / (2 * hT);
    // Relative 1e-6, plus the round-off of the differences, a few |p| eps/h.
    const double tol_r = 1e-6 * std::abs(dp_drho) + 1e-14 * std::abs(st.p) / hr;
    const double tol_T = 1e-6 * std::abs(dp_dT) + 1e-14 * std::abs(st.p) / hT;
    EXPECT_NEAR(st.dp_drho, dp_drho, tol_r) << GetParam() << " rho=" << rho << " T=" << T;
    const double cv = s.cv(rho, T, st.p);
    EXPECT_NEAR(st.dp_de * cv, dp_dT, tol_T) << GetParam() << " rho=" << rho << " T=" << T;
    // beta = (dp/dT)/(rho dp/drho).
    const double beta = dp_dT / (rho * dp_drho);
    EXPECT_NEAR(eos->thermal_expansivity_at(rho, T), beta, 1e-5 * std::abs(beta) + tol_T / (rho * dp_drho))
        << GetParam() << " rho=" << rho;
    // c^2 = dp/drho + p/rho^2 dp/de, positive in the valid range.
    EXPECT_LT(rel(st.c2, st.dp_drho + st.p / (rho * rho) * st.dp_de), 1e-14);
    EXPECT_GT(st.c2, 0.0) << GetParam() << " rho=" << rho;
  }
}

TEST_P(EosContract, DensityInvertsPressure) {
  const Sample& s = samples().at(GetParam());
  const EquationOfStateP eos = make(GetParam());
  for (auto [rho, T] : s.states) {
    const double p = eos->at(rho, T).p;
    EXPECT_LT(rel(eos->density_at(p, T), rho), 1e-10) << GetParam() << " rho=" << rho << " T=" << T << " p=" << p;
  }
}

TEST_P(EosContract, ClosedFormAtReferenceState) { samples().at(GetParam()).reference(*make(GetParam())); }

INSTANTIATE_TEST_SUITE_P(AllEos, EosContract, ::testing::ValuesIn(equation_of_state_types()),
                         [](const auto& info) { return info.param; });

// Each file of Vaango's EOSData folder, included in place of the ideal gas of
// the advect deck (the real decks include them the same way), builds an ICE
// component. JWL files carry Tarver's volumetric Cv = rho0 cv: the deck's
// specific_heat is set to Cv/rho0 for them.
TEST(EosContracts, EveryEosDataIncludeParses) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(test::shared_dir()) / "decks/inputs/ICE/EOSData";
  std::ifstream in(fs::path(test::shared_dir()) / "decks/inputs/ICE/advect.ups");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string deck = ss.str();
  const std::string eos = "<EOS type = \"ideal_gas\">                     </EOS>";
  const std::string cv = "<specific_heat>      716.0                   </specific_heat>";
  ASSERT_NE(deck.find(eos), std::string::npos);
  ASSERT_NE(deck.find(cv), std::string::npos);
  int n = 0;
  for (const auto& f : fs::directory_iterator(dir)) {
    if (f.path().extension() != ".xml") continue;
    const std::string name = f.path().filename().string();
    std::ifstream xf(f.path());
    std::stringstream xs;
    xs << xf.rdbuf();
    const std::string xml = xs.str();
    std::string text = deck;
    if (xml.find("<EOS") != std::string::npos) {
      text.replace(text.find(eos), eos.size(), "<include href=\"inputs/ICE/EOSData/" + name + "\"/>");
      // JWL: specific_heat = Cv/rho0 from the file.
      auto value = [&](const char* tag) {
        const auto b = xml.find(std::string("<") + tag + ">");
        return b == std::string::npos ? 0.0 : std::stod(xml.substr(xml.find('>', b) + 1));
      };
      if (value("Cv") > 0)
        text.replace(text.find(cv), cv.size(), "<specific_heat>" + std::to_string(value("Cv") / value("rho0")) + "</specific_heat>");
    } else {
      // Specific-heat model or material constants: added beside the ideal-gas EOS.
      text.replace(text.find(eos), eos.size(), eos + "<include href=\"inputs/ICE/EOSData/" + name + "\"/>");
      if (xml.find("<specific_heat>") != std::string::npos) {  // a full property set: drop the deck's own
        for (const char* tag : {"specific_heat", "gamma", "dynamic_viscosity", "thermal_conductivity"}) {
          const auto b = text.find(std::string("<") + tag + ">");
          const auto e = text.find(std::string("</") + tag + ">", b);
          text.erase(b, e + std::strlen(tag) + 3 - b);
        }
      }
    }
    SCOPED_TRACE(name);
    try {
      auto d = load_deck_from_string(text, name, (fs::path(test::shared_dir()) / "decks/inputs/ICE").string());
      auto ice = make_ice_component(*d);
      EXPECT_TRUE(ice != nullptr);
    } catch (const MissingFeature& e) {
      ADD_FAILURE() << "MissingFeature: " << e.what();
    } catch (const DeckError& e) {
      ADD_FAILURE() << "DeckError: " << e.what();
    }
    ++n;
  }
  EXPECT_EQ(n, 23);
}

}  // namespace
}  // namespace tephra
