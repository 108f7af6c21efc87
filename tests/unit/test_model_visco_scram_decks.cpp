// The <constitutive_model type="visco_scram"> blocks of the stock MPMICE burn
// decks (shared/decks/inputs/MPMICE) build through the deck reader's adapter
// (every child read or rejected, mpm/DeckModelParameters.h). The decks
// themselves stop earlier, at SimulationComponent 'mpmice' (issue 6), so this
// is where their PBX 9501 model is exercised.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "models/solid/AbsolutePressureEos.h"
#include "models/solid/ConstitutiveModel.h"
#include "models/solid/ViscoScram.h"
#include "mpm/DeckModelParameters.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

std::vector<const DeckNode*> scram_blocks(const DeckNode& n) {
  std::vector<const DeckNode*> out;
  std::function<void(const DeckNode&)> walk = [&](const DeckNode& d) {
    if (d.name == "constitutive_model" && d.attribute("type").value_or("") == "visco_scram") out.push_back(&d);
    for (const DeckNode& c : d.children) walk(c);
  };
  walk(n);
  return out;
}

ConstitutiveModelP build(const DeckNode& cm) {
  DeckModelParameters params(cm);
  ConstitutiveModelP m = create_constitutive_model("visco_scram", params);
  params.check_all_used("constitutive_model type 'visco_scram'");
  return m;
}

TEST(ViscoScramDecks, PbxBlocksOfTheBurnDecksBuild) {
  for (const char* name : {"guni2dRT.ups", "SteadyBurn_2dRT.ups"}) {
    auto deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/" + name);
    const auto blocks = scram_blocks(deck->root);
    ASSERT_EQ(blocks.size(), 1u) << name;
    const ConstitutiveModelP m = build(*blocks[0]);
    ASSERT_TRUE(m) << name;
    // PBX 9501: G = sum G_i = 2.6411 GPa, PR = 0.3 -> K = 2G(1.3)/(3 0.4) = 5.72238 GPa.
    EXPECT_NEAR(m->shear_modulus(), 2.6411e9, 1e3) << name;
    EXPECT_NEAR(m->bulk_modulus(), 2 * 2.6411e9 * 1.3 / 1.2, 1e3) << name;
    const auto& p = static_cast<const ViscoScram&>(*m).params();
    EXPECT_TRUE(p.modified_eos) << name;
    EXPECT_EQ(p.specific_heat, 996.0) << name;
  }
}

// BurnRate.ups asks for <useJWLEOS> true: the block builds, with the JWL
// constants of the deck in the MPMICE hooks (absolute pressure; the gauge hooks
// are not provided), and the hypoelastic moduli as without the flag.
TEST(ViscoScramDecks, BurnRateBlockBuildsWithTheJwlEos) {
  auto deck = load_deck(test::shared_dir() + "/decks/inputs/MPMICE/BurnRate.ups");
  const auto blocks = scram_blocks(deck->root);
  ASSERT_EQ(blocks.size(), 1u);
  const ConstitutiveModelP m = build(*blocks[0]);
  ASSERT_TRUE(m);
  const auto& p = static_cast<const ViscoScram&>(*m).params();
  ASSERT_TRUE(p.jwl.has_value());
  EXPECT_EQ(p.jwl->A, 732000e9);
  EXPECT_EQ(p.jwl->B, -5.2645e9);
  EXPECT_EQ(p.jwl->R1, 14.1);
  EXPECT_EQ(p.jwl->R2, 1.41);
  EXPECT_EQ(p.jwl->om, 0.8867);
  EXPECT_EQ(p.jwl->Cv, 2.780236e6);
  EXPECT_FALSE(p.jwl->modified);
  EXPECT_FALSE(m->pressure_at_density(1832.0, 1832.0, 298.0).has_value());
  EXPECT_NE(absolute_pressure_eos(*m), nullptr);
}

}  // namespace
}  // namespace tephra
