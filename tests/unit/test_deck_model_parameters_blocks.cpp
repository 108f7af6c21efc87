// The deck adapter's sub-model blocks (ModelParameters::block / type_attribute /
// enclosing_double): the OFHC-Cu constitutive model of deck A4
// (adiCuJC4000s696K.ups) with type elastic_plastic_hp creates its model with
// every child read; an unread child inside a block is a DeckError; enabled
// damage starts from the damage model's D0; a Gaussian initial field (a text
// value read through get_string) is drawn per point.
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "models/solid/ConstitutiveModel.h"
#include "mpm/DeckModelParameters.h"

namespace tephra {
namespace {

std::string a4_material(const std::string& flow_extra, const std::string& evolve_damage) {
  return R"(<Uintah_specification><material name="OFHCCu">
  <density>8930.0</density><specific_heat>414.0</specific_heat><melt_temp>1356.0</melt_temp>
  <constitutive_model type="elastic_plastic_hp">
    <tolerance>1.0e-12</tolerance><isothermal>false</isothermal><do_melting>false</do_melting>
    <evolve_porosity>false</evolve_porosity><evolve_damage>)" + evolve_damage + R"(</evolve_damage>
    <check_TEPLA_failure_criterion>false</check_TEPLA_failure_criterion>
    <check_max_stress_failure>false</check_max_stress_failure>
    <initial_material_temperature>696.0</initial_material_temperature>
    <shear_modulus>46.0e9</shear_modulus><bulk_modulus>129.0e9</bulk_modulus>
    <coeff_thermal_expansion>0.0</coeff_thermal_expansion>
    <taylor_quinney_coeff>0.9</taylor_quinney_coeff><critical_stress>129.0e9</critical_stress>
    <equation_of_state type="mie_gruneisen"><C_0>3940</C_0><Gamma_0>2.02</Gamma_0><S_alpha>1.489</S_alpha><rho_0>8930.0</rho_0></equation_of_state>
    <flow_model type="johnson_cook"><A>90.0e6</A><B>292.0e6</B><C>0.025</C><n>0.31</n><m>1.09</m>)" +
         flow_extra + R"(</flow_model>
    <shear_modulus_model type="constant_shear"><shear_modulus>46.0e9</shear_modulus></shear_modulus_model>
    <melting_temp_model type="constant_Tm"></melting_temp_model>
    <internal_variable_model type="metal_internal_var"></internal_variable_model>
    <yield_condition type="von_mises"></yield_condition>
    <stability_check type="none"></stability_check>
    <damage_model type="hancock_mackenzie"><D0>0.0001</D0><Dc>0.7</Dc></damage_model>
  </constitutive_model></material></Uintah_specification>)";
}

ConstitutiveModelP parse(const std::string& xml) {
  auto deck = load_deck_from_string(xml, "a4.ups", ".");
  const DeckNode& cm = deck->root.require_child("material").require_child("constitutive_model");
  DeckModelParameters p(cm);
  auto m = create_constitutive_model("elastic_plastic_hp", p);
  p.check_all_used("elastic_plastic_hp");
  return m;
}

TEST(DeckModelParametersBlocks, A4CopperBlockCreatesElasticPlasticHP) {
  const auto m = parse(a4_material("", "false"));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->type(), "elastic_plastic_hp");
  EXPECT_EQ(m->shear_modulus(), 46.0e9);
}

TEST(DeckModelParametersBlocks, UnreadChildOfABlockIsADeckError) {
  EXPECT_THROW(parse(a4_material("<no_such_tag>1</no_such_tag>", "false")), DeckError);
}

TEST(DeckModelParametersBlocks, EnabledDamageStartsFromTheDamageModelsD0) {
  const auto m = parse(a4_material("", "true"));
  ASSERT_TRUE(m);
  for (const HistoryVariable& h : m->history())
    if (h.name == "damage") EXPECT_EQ(h.initial[0], 0.0001);  // <D0> of hancock_mackenzie
}

// Gaussian initial damage (MetalFailure.h): read from the deck, drawn per point at the
// first update; the sample mean/std of N points are within 4 standard errors of
// <initial_mean_scalar_damage> 0.005 and <initial_std_scalar_damage> 0.001 (inventory
// ch. 15 tags). An unknown distribution is a DeckError.
// The column `name` of n points after one initialization update of m (dt = 0, F = I), and
// after a second one in *again.
std::vector<double> drawn_column(const ConstitutiveModel& m, const std::string& name, std::size_t n,
                                 std::vector<double>* again) {
  const std::vector<HistoryVariable> h = m.history();
  std::vector<std::vector<double>> cols;
  int k_col = -1;
  for (std::size_t k = 0; k < h.size(); ++k) {
    cols.emplace_back(n * h[k].components, h[k].initial[0]);
    if (h[k].name == name) k_col = int(k);
  }
  EXPECT_GE(k_col, 0) << name;
  if (k_col < 0) return {};
  std::vector<std::span<double>> spans(cols.begin(), cols.end());
  std::vector<Eigen::Matrix3d> F(n, Eigen::Matrix3d::Identity()), L(n, Eigen::Matrix3d::Zero()),
      sig(n, Eigen::Matrix3d::Zero()), sig_out(n);
  std::vector<double> T(n, 696.0), c(n), w(n), pw(n), heat(n);
  SolidUpdateInput in;
  in.dt = 0.0;
  in.density0 = 8930.0;
  in.F_old = F, in.F_new = F, in.L = L, in.temperature = T, in.stress_old = sig;
  const SolidUpdateOutput out{sig_out, c, w, pw, heat, spans};
  EXPECT_EQ(m.update(in, out), -1);
  const std::vector<double> first = cols[k_col];
  EXPECT_EQ(m.update(in, out), -1);
  if (again) *again = cols[k_col];
  return first;
}

void expect_gaussian(const std::vector<double>& v, double mean, double sd) {
  const double n = double(v.size());
  double s1 = 0, s2 = 0;
  for (double d : v) s1 += d, s2 += d * d;
  const double m = s1 / n, s = std::sqrt(s2 / n - m * m);
  EXPECT_NEAR(m, mean, 4 * sd / std::sqrt(n));
  EXPECT_NEAR(s, sd, 4 * sd / std::sqrt(2.0 * n));
}

TEST(DeckModelParametersBlocks, GaussianInitialDamageIsDrawnPerPoint) {
  std::string xml = a4_material("", "true");
  const std::string at = "<stability_check";
  xml.insert(xml.find(at), "<initial_scalar_damage_distrib>gauss</initial_scalar_damage_distrib>"
                           "<initial_mean_scalar_damage>0.005</initial_mean_scalar_damage>"
                           "<initial_std_scalar_damage>0.001</initial_std_scalar_damage>"
                           "<scalar_damage_seed>42</scalar_damage_seed>");
  const auto m = parse(xml);
  ASSERT_TRUE(m);
  std::vector<double> again;
  const std::vector<double> first = drawn_column(*m, "damage", 20000, &again);
  expect_gaussian(first, 0.005, 0.001);
  EXPECT_EQ(again, first);  // a second update draws nothing new (the point keeps its value)

  std::string bad = a4_material("", "true");
  bad.insert(bad.find(at), "<initial_scalar_damage_distrib>lognormal</initial_scalar_damage_distrib>");
  EXPECT_THROW(parse(bad), DeckError);
  std::string constant = a4_material("", "true");
  constant.insert(constant.find(at), "<initial_scalar_damage_distrib>constant</initial_scalar_damage_distrib>");
  EXPECT_TRUE(parse(constant));
}

// The same for the porosity tags (VT ch. 12 tags; MetalFailure.h): <initial_porosity_distrib>
// gauss, <initial_mean_porosity> 0.05, <initial_std_porosity> 0.01 (4 standard errors of 20000
// draws); a different <porosity_seed> gives different points with the same distribution.
TEST(DeckModelParametersBlocks, GaussianInitialPorosityIsDrawnPerPoint) {
  auto deck = [](int seed) {
    std::string xml = a4_material("", "true");
    xml.insert(xml.find("<stability_check"),
               "<initial_porosity_distrib>gauss</initial_porosity_distrib>"
               "<initial_mean_porosity>0.05</initial_mean_porosity>"
               "<initial_std_porosity>0.01</initial_std_porosity><porosity_seed>" +
                   std::to_string(seed) + "</porosity_seed>");
    return xml;
  };
  const auto m = parse(deck(7)), m2 = parse(deck(8));
  ASSERT_TRUE(m && m2);
  std::vector<double> again;
  const std::vector<double> first = drawn_column(*m, "porosity", 20000, &again);
  expect_gaussian(first, 0.05, 0.01);
  EXPECT_EQ(again, first);
  const std::vector<double> other = drawn_column(*m2, "porosity", 20000, nullptr);
  expect_gaussian(other, 0.05, 0.01);
  EXPECT_NE(other, first);
}

}  // namespace
}  // namespace tephra
