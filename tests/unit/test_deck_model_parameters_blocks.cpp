// The deck adapter's sub-model blocks (ModelParameters::block / type_attribute /
// enclosing_double): the OFHC-Cu constitutive model of deck A4
// (adiCuJC4000s696K.ups) with type elastic_plastic_hp creates its model with
// every child read; an unread child inside a block is a DeckError; enabled
// damage starts from the damage model's D0; a Gaussian initial field (a text
// value read through get_string) is a MissingFeature.
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

TEST(DeckModelParametersBlocks, GaussianInitialDamageIsAMissingFeature) {
  std::string xml = a4_material("", "true");
  const std::string at = "<stability_check";
  xml.insert(xml.find(at), "<initial_scalar_damage_distrib>gauss</initial_scalar_damage_distrib>");
  EXPECT_THROW(parse(xml), MissingFeature);
  std::string constant = a4_material("", "true");
  constant.insert(constant.find(at), "<initial_scalar_damage_distrib>constant</initial_scalar_damage_distrib>");
  EXPECT_TRUE(parse(constant));
}

}  // namespace
}  // namespace tephra
