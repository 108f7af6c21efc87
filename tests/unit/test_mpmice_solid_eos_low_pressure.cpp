// The MPMICE solid EOS far below the reference pressure (mpmice/SolidEos,
// models/solid/ModifiedEos.h absolute-pressure hooks). With <useModifiedEOS>
// an expanded solid has p = p_ref (rho/rho0)^n, n = K0/p_ref, and
// rho(p) = rho0 (p/p_ref)^{1/n}: positive and invertible for every p > 0.
// Through the gauge hooks the pressure makes the round trip p_ref + (p - p_ref),
// which leaves nothing of p < eps p_ref (1e-12 Pa read back as rho = 0, the
// sp_vol = inf that stopped guni2dRT.ups at step 19). The absolute hooks keep
// the closed form to round-off down to p = 1e-30 Pa.
#include <gtest/gtest.h>

#include <cmath>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/ModifiedEos.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

constexpr double kK = 173.33e9, kG = 80e9, kRho0 = 7830.0, kPref = 101325.0;

ConstitutiveModelP steel() {
  test::MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", kG}, {"useModifiedEOS", 1.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", 7e8}, {"K", 0.0}});
  p.enclosing = {{"melt_temp", 1793.0}, {"specific_heat", 477.0}, {"density", kRho0}};
  return create_constitutive_model("elastic_plastic_hp", p);
}

TEST(MpmIceSolidEos, ModifiedEosKeepsPressuresFarBelowTheReference) {
  const auto m = steel();
  ASSERT_TRUE(m && m->modified_eos());
  const double n = kK / kPref;  // default_hypo: K0 = K
  for (const double p : {1e-30, 1e-12, 1e-6, 1.0, 1e3, 0.5 * kPref}) {
    const double rho = *mpmice_density_at_absolute_pressure(*m, p, kRho0, 300.0, kPref);
    const double exact = kRho0 * std::pow(p / kPref, 1.0 / n);
    EXPECT_NEAR(rho, exact, 1e-14 * exact) << "p " << p;
    const SolidEosPoint e = *mpmice_absolute_pressure_at_density(*m, rho, kRho0, 300.0, kPref);
    // p = p_ref x^n amplifies the relative round-off of x = rho/rho0 by n ~ 1.7e6.
    EXPECT_NEAR(e.pressure, p, 1e-9 * p) << "p " << p;
    EXPECT_NEAR(e.dp_drho, kK / rho * (p / kPref), 1e-9 * kK / rho * (p / kPref)) << "p " << p;
  }
  // The gauge round trip cannot represent 1e-12 Pa (what SolidEos used before).
  EXPECT_EQ(*mpmice_density_at_pressure(*m, 1e-12 - kPref, kRho0, 300.0, kPref), 0.0);
  // Above p_ref both forms are the model's compression branch: p - p_ref = K ln(rho/rho0).
  const double rho = 1.001 * kRho0;
  EXPECT_NEAR(mpmice_absolute_pressure_at_density(*m, rho, kRho0, 300.0, kPref)->pressure,
              kPref + kK * std::log(1.001), 1e-9 * kK * std::log(1.001));
}

}  // namespace
}  // namespace tephra
