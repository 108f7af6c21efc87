// tabular_eos (VT §22.2): the JSON reader, the linear table p(eta), the model's
// point function and MPMICE hooks, and the deck errors.
//
// Oracles:
//  - the inventory's (seed-inventory-vaango-theory ch. 22): a table of a linear
//    function is interpolated exactly; the bulk modulus of a linear p is its slope;
//  - a table sampled from a closed-form EOS (Murnaghan, VT eq. 3.11 in density form
//    p = (K/K')(eta^K' - 1)) on a uniform eta grid of spacing h reproduces it with the
//    linear-interpolation error <= h^2/8 max|p''|: observed order 2 for p, for the
//    stored energy W(J) = (K/K')[(J^{1-K'} - 1)/(K' - 1) + J - 1] (its exact integral,
//    models/solid/ViscousFluid.h) and for the inverse rho(p) = rho0 (1 + K' p/K)^{1/K'};
//    order 1 for c^2 = dp/drho = K eta^{K'-1}/rho0 (the slope of a segment).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <Eigen/Geometry>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "models/JsonValue.h"
#include "models/solid/TabularEos.h"
#include "models/solid/ViscousFluid.h"
#include "mpm/DeckModelParameters.h"
#include "tests/support/SolidModelDriver.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;

const double kK = 8.0e9, kKp = 4.0, kRho0 = 7800.0;

double murnaghan_p(double eta) { return kK / kKp * (std::pow(eta, kKp) - 1.0); }

// The Vaango tabular-data document of p(eta) sampled at n + 1 uniform points on [a, b].
std::string murnaghan_table_json(double a, double b, int n) {
  std::ostringstream x, p;
  x.precision(17);
  p.precision(17);
  for (int k = 0; k <= n; ++k) {
    const double eta = a + (b - a) * k / n;
    x << (k ? ", " : "") << eta;
    p << (k ? ", " : "") << murnaghan_p(eta);
  }
  return "{\"Vaango_tabular_data\": {\n \"Meta\": {\"title\": \"Murnaghan\"},\n \"Data\": {\n  \"DensityRatio\": [" +
         x.str() + "],\n  \"Pressure\": [" + p.str() + "]\n }\n}}\n";
}

// ---------------------------------------------------------------- JSON reader
TEST(JsonReader, ValuesAndLines) {
  const JsonValue v = parse_json("{\"a\": [1, -2.5e3, 0.25],\n \"b\": {\"s\": \"x\\\"y\\u00e9\"},\n"
                                 " \"t\": true, \"n\": null}");
  ASSERT_TRUE(v.is_object());
  EXPECT_EQ(v.find("a")->numbers("a"), (std::vector<double>{1, -2500, 0.25}));
  EXPECT_EQ(v.find("b")->find("s")->string, "x\"y\xc3\xa9");
  EXPECT_EQ(v.find("b")->line, 2);
  EXPECT_TRUE(v.find("t")->boolean);
  EXPECT_EQ(v.find("n")->kind, JsonValue::Kind::Null);
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(JsonReader, ErrorsNameTheLine) {
  auto line_of = [](const std::string& text) {
    try {
      parse_json(text);
    } catch (const JsonError& e) {
      return e.line();
    }
    return -1;
  };
  EXPECT_EQ(line_of("{\"a\": [1, 2,\n 3,]\n}"), 2);        // trailing comma
  EXPECT_EQ(line_of("{\"a\": 1\n\n \"b\": 2}"), 3);          // missing comma
  EXPECT_EQ(line_of("{\"a\": \"open\n}"), 1);                // unterminated string
  EXPECT_EQ(line_of("{\"a\": 01}"), 1);                      // leading zero
  EXPECT_EQ(line_of("{\"a\": 1, \"a\": 2}"), 1);             // repeated key
  EXPECT_EQ(line_of("[1, 2]\n x"), 2);                       // text after the value
  EXPECT_EQ(line_of("{\"a\": NaN}"), 1);
  EXPECT_EQ(line_of("{\"a\": 1e999}"), 1);                   // not a finite double
  EXPECT_THROW(parse_json("[1, \"2\"]").numbers("x"), JsonError);
}

// ---------------------------------------------------------------- the table
TEST(TabularEos, LinearTableIsInterpolatedExactly) {
  // p = 3e9 (eta - 1) + 1e6 tabulated at uneven knots: exact everywhere, also
  // extrapolated; dp/deta = 3e9 on every segment; the inverse is exact.
  const std::string json =
      "{\"Vaango_tabular_data\": {\"Data\": {\"eta\": [0.6, 0.9, 1.0, 1.3, 1.7],"
      " \"p\": [-1.199e9, -2.99e8, 1e6, 9.01e8, 2.101e9]}}}";
  const PressureTable t = read_pressure_table(json, "eta", "p");
  for (double eta = 0.4; eta < 2.0; eta += 0.0137) {
    EXPECT_NEAR(t.pressure(eta), 3e9 * (eta - 1) + 1e6, 1e-6) << eta;
    EXPECT_NEAR(t.slope(eta), 3e9, 1e-5) << eta;
    EXPECT_NEAR(t.density_ratio(3e9 * (eta - 1) + 1e6), eta, 1e-14) << eta;
  }
  // A knot belongs to the segment on its left (Vaango's lower_bound search).
  EXPECT_EQ(t.segment(0.9), 0u);
  EXPECT_EQ(t.segment(0.9 + 1e-12), 1u);
  EXPECT_EQ(t.segment(0.1), 0u);
  EXPECT_EQ(t.segment(5.0), 3u);
}

TEST(TabularEos, MurnaghanTableConvergesAtSecondOrder) {
  double err_p[4], err_W[4], err_c2[4], err_rho[4];
  const int ns[4] = {10, 20, 40, 80};
  for (int r = 0; r < 4; ++r) {
    const PressureTable t = read_pressure_table(murnaghan_table_json(0.7, 1.5, ns[r]), "DensityRatio", "Pressure");
    err_p[r] = err_W[r] = err_c2[r] = err_rho[r] = 0;
    for (int k = 0; k <= 997; ++k) {
      const double eta = 0.7 + 0.8 * k / 997.0;
      const double J = 1 / eta;
      err_p[r] = std::max(err_p[r], std::abs(t.pressure(eta) - murnaghan_p(eta)));
      err_W[r] = std::max(err_W[r], std::abs(t.energy(eta) - power_law_energy(J, kK / kKp, kKp)));
      err_c2[r] = std::max(err_c2[r], std::abs(t.slope(eta) / kRho0 - kK * std::pow(eta, kKp - 1) / kRho0));
      const double p = murnaghan_p(eta);
      err_rho[r] = std::max(err_rho[r], std::abs(t.density_ratio(p) - std::pow(1 + kKp * p / kK, 1 / kKp)));
    }
    // The bound of linear interpolation: h^2/8 max|p''|, p'' = K (K'-1) eta^{K'-2}.
    const double h = 0.8 / ns[r];
    EXPECT_LE(err_p[r], h * h / 8 * kK * (kKp - 1) * std::pow(1.5, kKp - 2) * (1 + 1e-12));
  }
  for (int r = 1; r < 4; ++r) {
    const double op = std::log2(err_p[r - 1] / err_p[r]), oW = std::log2(err_W[r - 1] / err_W[r]);
    const double oc = std::log2(err_c2[r - 1] / err_c2[r]), orho = std::log2(err_rho[r - 1] / err_rho[r]);
    std::printf("N = %d: |p| err %.3e (order %.3f), |W| err %.3e (%.3f), |c^2| err %.3e (%.3f), |eta(p)| err %.3e (%.3f)\n",
                ns[r], err_p[r], op, err_W[r], oW, err_c2[r], oc, err_rho[r], orho);
    EXPECT_NEAR(op, 2.0, 0.05);
    EXPECT_NEAR(oW, 2.0, 0.1);
    EXPECT_NEAR(oc, 1.0, 0.05);
    EXPECT_NEAR(orho, 2.0, 0.1);
  }
}

// ---------------------------------------------------------------- the model
ConstitutiveModelP murnaghan_model(int n) {
  // One folder per test: ctest runs the tests that call this in parallel
  // processes, and scratch_dir empties its folder (a shared one raced).
  const std::string path =
      test::scratch_dir(std::string("tabular_eos_model_") +
                        ::testing::UnitTest::GetInstance()->current_test_info()->name()) +
      "/murnaghan.json";
  std::ofstream(path) << murnaghan_table_json(0.7, 1.5, n);
  test::MapModelParameters p;
  p.strings = {{"filename", path}, {"independent_variables", "DensityRatio"}, {"dependent_variables", "Pressure"}};
  p.add_block("interpolation", "linear");
  return create_constitutive_model("tabular_eos", p);
}

TEST(TabularEos, PointFunctionIsThePressureOfTheTable) {
  const ConstitutiveModelP m = murnaghan_model(16);
  const auto& t = static_cast<const TabularEos&>(*m).table();
  EXPECT_EQ(m->type(), "tabular_eos");
  EXPECT_EQ(m->shear_modulus(), 0.0);
  EXPECT_NEAR(m->bulk_modulus(), t.slope(1.0), 0.0);
  for (double lambda : {0.75, 0.9, 1.0, 1.1, 1.3}) {
    // Uniaxial strain F = diag(lambda, 1, 1) plus a rotation: sigma = -p(1/lambda) I exactly.
    test::PointState s(*m);
    const M3 Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const M3 F = Q * Eigen::Vector3d(lambda, 1, 1).asDiagonal();
    ASSERT_EQ(test::step_point(*m, kRho0, s, F, 1e-6), -1);
    // (J of the rotated F differs from lambda by round-off: eta by ~1e-16, p by slope x 1e-16 ~ 1e-5 Pa.)
    EXPECT_LE((s.stress + t.pressure(1 / lambda) * M3::Identity()).norm(), 1e-13 * kK) << lambda;
    // Within the table's h^2/8 bound of the Murnaghan pressure (h = 0.05).
    EXPECT_NEAR(-s.stress(0, 0), murnaghan_p(1 / lambda), 0.05 * 0.05 / 8 * kK * 3 * 1.5 * 1.5) << lambda;
    EXPECT_NEAR(s.wave_speed * s.wave_speed, t.slope(1 / lambda) / kRho0, 1e-12 * kK / kRho0);
    EXPECT_EQ(s.plastic_work, 0.0);
    EXPECT_EQ(s.heating, 0.0);
  }
}

TEST(TabularEos, MpmIceHooksInvertTheTable) {
  const ConstitutiveModelP m = murnaghan_model(16);
  for (double x : {0.72, 0.93, 1.01, 1.17, 1.49, 1.6}) {  // off the knots 0.7 + 0.05 k (a kink of p)
    const auto e = *m->pressure_at_density(x * kRho0, kRho0, 300.0);
    EXPECT_NEAR(*m->density_at_pressure(e.pressure, kRho0, 300.0), x * kRho0, 1e-12 * kRho0) << x;
    // dp/drho: central difference inside the segment (the interpolant is linear there).
    const double h = 1e-6 * kRho0;
    const double fd = (m->pressure_at_density(x * kRho0 + h, kRho0, 300)->pressure -
                       m->pressure_at_density(x * kRho0 - h, kRho0, 300)->pressure) / (2 * h);
    EXPECT_NEAR(e.dp_drho, fd, 1e-6 * e.dp_drho) << x;
    EXPECT_EQ(e.c2, e.dp_drho);
  }
  // Tension beyond any positive density: NaN (MPMICE reports it).
  EXPECT_TRUE(std::isnan(*m->density_at_pressure(-1e12, kRho0, 300.0)));
}

// ---------------------------------------------------------------- deck errors
struct Built {
  std::unique_ptr<Deck> deck;
  ConstitutiveModelP model;
};

// <constitutive_model> of an in-memory deck whose folder is `dir` (the table file is looked up there).
Built build_from_deck(const std::string& dir, const std::string& children) {
  Built b;
  b.deck = load_deck_from_string("<Uintah_specification>\n<constitutive_model type=\"tabular_eos\">\n" + children +
                                     "\n</constitutive_model>\n</Uintah_specification>\n",
                                 dir + "/deck.ups", dir);
  const DeckNode* cm = b.deck->root.child("constitutive_model");
  DeckModelParameters params(*cm);
  b.model = create_constitutive_model("tabular_eos", params);
  params.check_all_used("constitutive_model type 'tabular_eos'");
  return b;
}

std::string deck_children(const std::string& file, const std::string& interp = "linear",
                          const std::string& indep = "DensityRatio") {
  return "<filename>" + file + "</filename>\n<independent_variables>" + indep +
         "</independent_variables>\n<dependent_variables>Pressure</dependent_variables>\n"
         "<interpolation type=\"" + interp + "\"/>";
}

template <class E>
std::string message_of(const std::string& dir, const std::string& children) {
  try {
    build_from_deck(dir, children);
  } catch (const E& e) {
    std::printf("%s\n", e.what());
    return e.what();
  }
  ADD_FAILURE() << "no exception";
  return "";
}

TEST(TabularEos, DeckTableBesideTheDeckBuilds) {
  const std::string dir = test::scratch_dir("tabular_eos_deck");
  std::ofstream(dir + "/table.json") << murnaghan_table_json(0.7, 1.5, 8);
  const Built b = build_from_deck(dir, deck_children("table.json"));  // relative: beside the deck
  ASSERT_TRUE(b.model);
  EXPECT_NEAR(b.model->pressure_at_density(1.5 * kRho0, kRho0, 300)->pressure, murnaghan_p(1.5), 1e-6 * kK);
}

TEST(TabularEos, DeckErrorsNameTheTableLineAndTheElement) {
  const std::string dir = test::scratch_dir("tabular_eos_errors");
  // Missing file: DeckError at <filename> (line 3 of the deck).
  std::string m = message_of<DeckError>(dir, deck_children("nowhere.json"));
  EXPECT_NE(m.find("deck.ups:3"), std::string::npos);
  EXPECT_NE(m.find("nowhere.json"), std::string::npos);
  // Malformed JSON: the table's line.
  std::ofstream(dir + "/bad.json") << "{\"Vaango_tabular_data\": {\"Data\": {\n\"DensityRatio\": [1, 2,],\n"
                                      "\"Pressure\": [0, 1]}}}";
  m = message_of<DeckError>(dir, deck_children("bad.json"));
  EXPECT_NE(m.find("bad.json:2:"), std::string::npos);
  EXPECT_NE(m.find("constitutive_model/filename>"), std::string::npos);
  // Pressure not increasing: the line of the offending value.
  std::ofstream(dir + "/flat.json") << "{\"Vaango_tabular_data\": {\"Data\": {\n\"DensityRatio\": [0.9, 1.0, 1.1],\n"
                                       "\"Pressure\": [-1e8,\n 0,\n 0]}}}";
  m = message_of<DeckError>(dir, deck_children("flat.json"));
  EXPECT_NE(m.find("flat.json:5:"), std::string::npos);
  // A variable the file does not have; sizes that differ.
  std::ofstream(dir + "/names.json") << "{\"Vaango_tabular_data\": {\"Data\": {\"Density\": [0.9, 1.1],"
                                        " \"Pressure\": [0, 1]}}}";
  m = message_of<DeckError>(dir, deck_children("names.json"));
  EXPECT_NE(m.find("DensityRatio"), std::string::npos);
  std::ofstream(dir + "/sizes.json") << "{\"Vaango_tabular_data\": {\"Data\": {\"DensityRatio\": [0.9, 1.1],"
                                        " \"Pressure\": [0, 1, 2]}}}";
  EXPECT_NE(message_of<DeckError>(dir, deck_children("sizes.json")).find("3 values"), std::string::npos);
  std::ofstream(dir + "/root.json") << "{\"Data\": {}}";
  EXPECT_NE(message_of<DeckError>(dir, deck_children("root.json")).find("Vaango_tabular_data"), std::string::npos);
  // Two independent variables: DeckError; cubic interpolation: MissingFeature (exit 3).
  std::ofstream(dir + "/ok.json") << murnaghan_table_json(0.7, 1.5, 4);
  EXPECT_NE(message_of<DeckError>(dir, deck_children("ok.json", "linear", "DensityRatio, Temperature"))
                .find("exactly one independent variable"),
            std::string::npos);
  EXPECT_NE(message_of<MissingFeature>(dir, deck_children("ok.json", "cubic")).find("cubic"), std::string::npos);
  EXPECT_THROW(build_from_deck(dir, deck_children("ok.json", "spline")), DeckError);
}

}  // namespace
}  // namespace tephra
