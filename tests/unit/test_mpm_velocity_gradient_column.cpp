// The per-particle L column is kept only when something reads it
// (MpmComponent::keeps_L, session 24): hypo_elastic forms its strain from
// U_n, U_{n+1} (reads_velocity_gradient() false), so the step forms F without
// storing L (first_order_F). Oracle: the same deck with L kept (artificial
// viscosity on with both coefficients 0: q = 0, so the physics is the same)
// gives the same particle states bit for bit; comp_neo_hook (reads L by
// default) keeps it.
#include <gtest/gtest.h>

#include <string>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

// Two blocks of one material meeting head-on (one velocity field): a
// non-uniform velocity gradient from the first steps.
std::string deck(const std::string& model, const std::string& mpm_flags) {
  return "<Uintah_specification><MPM><interpolator>linear</interpolator>" + mpm_flags +
         "</MPM><MaterialProperties><MPM><material><density>1000</density>"
         "<constitutive_model type='" + model + "'>" +
         (model == "hypo_elastic" ? "<G>1e6</G><K>2e6</K>" : "<bulk_modulus>2e6</bulk_modulus><shear_modulus>1e6</shear_modulus>") +
         "</constitutive_model><thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
         "<geom_object><box><min>[0.1,0.1,0.1]</min><max>[0.3,0.3,0.3]</max></box><res>[2,2,2]</res>"
         "<velocity>[3,1,0]</velocity><temperature>300</temperature></geom_object>"
         "<geom_object><box><min>[0.3,0.1,0.1]</min><max>[0.5,0.3,0.3]</max></box><res>[2,2,2]</res>"
         "<velocity>[-3,0,0.5]</velocity><temperature>300</temperature></geom_object></material></MPM>"
         "</MaterialProperties><Grid><Level><Box><lower>[0,0,0]</lower><upper>[0.6,0.4,0.4]</upper>"
         "<resolution>[12,8,8]</resolution><extraCells>[0,0,0]</extraCells><patches>[1,1,1]</patches></Box></Level>"
         "</Grid></Uintah_specification>";
}

std::unique_ptr<MpmComponent> run(const std::string& model, const std::string& flags) {
  auto d = load_deck_from_string(deck(model, flags), "l.ups", ".");
  auto c = make_mpm_component(*d);
  c->initialize();
  double t = 0.0;
  for (int k = 1; k <= 8; ++k) {
    const double dt = 1e-4;
    c->advance(t, dt, k);
    t += dt;
  }
  return c;
}

TEST(MpmVelocityGradientColumn, HypoElasticStepsWithoutLAndGivesTheBitsOfTheStepWithL) {
  const auto without = run("hypo_elastic", "");
  const auto with = run("hypo_elastic",
                        "<artificial_viscosity>true</artificial_viscosity>"
                        "<artificial_viscosity_coeff1>0</artificial_viscosity_coeff1>"
                        "<artificial_viscosity_coeff2>0</artificial_viscosity_coeff2>");
  const MpmMaterial& a = without->materials()[0];
  const MpmMaterial& b = with->materials()[0];
  EXPECT_TRUE(a.L.empty());
  ASSERT_EQ(b.L.size(), b.particles.size());
  double max_l = 0.0;
  for (const Mat3& l : b.L) max_l = std::max(max_l, l.cwiseAbs().maxCoeff());
  EXPECT_GT(max_l, 1.0);  // the blocks deform: F depends on L
  ASSERT_EQ(a.particles.size(), b.particles.size());
  ASSERT_GT(a.particles.size(), 100u);
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    ASSERT_EQ(a.particles.id[i], b.particles.id[i]) << i;
    ASSERT_EQ(a.particles.F[i], b.particles.F[i]) << i;
    ASSERT_EQ(a.particles.stress[i], b.particles.stress[i]) << i;
    ASSERT_EQ(a.particles.x[i], b.particles.x[i]) << i;
    ASSERT_EQ(a.particles.v[i], b.particles.v[i]) << i;
  }
}

TEST(MpmVelocityGradientColumn, AModelThatReadsLKeepsIt) {
  const auto c = run("comp_neo_hook", "");
  const MpmMaterial& m = c->materials()[0];
  EXPECT_EQ(m.L.size(), m.particles.size());
}

}  // namespace
}  // namespace tephra
