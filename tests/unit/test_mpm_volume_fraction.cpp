// MPM <geom_object><volumeFraction> (mpm/MpmDeck.cpp): Uintah's
// ParticleCreator gives a particle the mass rho0 V volumeFraction. Tephra
// reads only the values that change nothing (1, and Uintah's "absent" -1:
// BurnRate.ups gives 1.0); any other value is a MissingFeature (exit 3)
// naming the element, not a silent full-density particle.
#include <gtest/gtest.h>

#include <string>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

std::string deck(const std::string& volume_fraction) {
  return "<Uintah_specification><MPM><interpolator>gimp</interpolator></MPM>"
         "<MaterialProperties><MPM><material><density>1000</density>"
         "<constitutive_model type='hypo_elastic'><G>1e6</G><K>2e6</K>"
         "</constitutive_model><thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
         "<geom_object><box><min>[0.1,0.1,0.1]</min><max>[0.3,0.4,0.2]</max></box><res>[2,2,2]</res>"
         "<velocity>[0,0,0]</velocity><temperature>300</temperature>" +
         volume_fraction +
         "</geom_object></material></MPM>"
         "</MaterialProperties><Grid><Level><Box><lower>[0,0,0]</lower><upper>[0.5,0.5,0.5]</upper>"
         "<resolution>[5,5,5]</resolution><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box></Level>"
         "</Grid></Uintah_specification>";
}

TEST(MpmVolumeFraction, OneAndAbsentAreReadOtherValuesAreMissing) {
  for (const char* ok : {"", "<volumeFraction>1.0</volumeFraction>", "<volumeFraction>-1</volumeFraction>"}) {
    auto d = load_deck_from_string(deck(ok), "vf.ups", ".");
    EXPECT_NO_THROW(make_mpm_component(*d)) << ok;
  }
  auto d = load_deck_from_string(deck("<volumeFraction>0.9</volumeFraction>"), "vf.ups", ".");
  try {
    make_mpm_component(*d);
    ADD_FAILURE() << "volumeFraction 0.9 accepted";
  } catch (const MissingFeature& e) {
    EXPECT_NE(std::string(e.what()).find("volumeFraction"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tephra
