// MPMICE hooks of elastic_plastic and elastic_plastic_hp (PlasticityEos.h,
// EosPressureHooks.cpp): the gauge pressure p̄(ρ) = -(p(J) - p(1)), J = ρ0/ρ, of every
// EOS sub-model against its closed form, dp̄/dρ against central differences, and the
// round trip ρ -> p̄ -> ρ to 1e-10.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/base/Errors.h"
#include "models/solid/ConstitutiveModel.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using test::MapModelParameters;

constexpr double kRho0 = 7830.0, kK = 173.3e9;  // 4340 steel (Table 26.1)

ConstitutiveModelP metal(const std::string& type, const std::string& eos, std::map<std::string, double> eos_values) {
  MapModelParameters p({{"bulk_modulus", kK}, {"shear_modulus", 80e9}, {"isothermal", 1.0}});
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", 792e6}, {"K", 510e6}});
  p.add_block("equation_of_state", eos, std::move(eos_values));
  p.enclosing = {{"melt_temp", 1793.0}, {"specific_heat", 477.0}, {"density", kRho0}};
  return create_constitutive_model(type, p);
}

struct EosCase {
  std::string key;
  std::map<std::string, double> values;
  double (*closed_form)(double J);  // gauge p̄(J) [Pa], compression positive
  bool tension;                     // the EOS has a tensile branch (air has none)
};

// Closed forms (VT ch. 6; PlasticityEosModels.cpp):
//   default_hypo  p̄ = -K ln J (p_dot = K tr d integrated from J = 1)
//   default_hyper p̄ = -K/2 (J - 1/J)                                  (6.8)
//   mie_gruneisen p̄ = ρ0 C0² x (1 - Γ0 x/2)/(1 - S x)², x = 1 - J, E = 0   (6.10)
//   air           p̄ = p_r (J^-γ - 1) in compression                    (6.18)
//   water         p̄ = K0/n (J^-n - 1), K0 = 2.21e9, n = 6.029 (gauge: p_0 cancels)
//   granite       p̄ = K0/n (J^-n - 1), K0 = 40e9, n = 4
double hypo(double J) { return -kK * std::log(J); }
double hyper(double J) { return -0.5 * kK * (J - 1 / J); }
double mg(double J) {
  const double x = 1 - J, K0 = kRho0 * 3574.0 * 3574.0;
  return K0 * x * (1 - 0.5 * 1.69 * x) / ((1 - 1.92 * x) * (1 - 1.92 * x));
}
double air(double J) { return 101325.0 * (std::pow(J, -1.4) - 1); }
double water(double J) { return 2.21e9 / 6.029 * (std::pow(J, -6.029) - 1); }
double granite(double J) { return 40e9 / 4.0 * (std::pow(J, -4.0) - 1); }

TEST(PlasticityEosHooks, PressureDerivativeAndRoundTripForEveryEos) {
  const std::map<std::string, double> mgv = {{"C_0", 3574.0}, {"Gamma_0", 1.69}, {"S_alpha", 1.92}};
  const EosCase cases[] = {{"default_hypo", {}, &hypo, true},       {"default_hyper", {}, &hyper, true},
                           {"mie_gruneisen", mgv, &mg, true},       {"mie_gruneisen_energy", mgv, &mg, true},
                           {"air", {}, &air, false},                {"water", {}, &water, true},
                           {"granite", {}, &granite, true}};
  for (const char* type : {"elastic_plastic", "elastic_plastic_hp"})
    for (const EosCase& c : cases) {
      const auto m = metal(type, c.key, c.values);
      ASSERT_TRUE(m) << type << " " << c.key;
      EXPECT_EQ(m->pressure_at_density(kRho0, kRho0, 300.0)->pressure, 0.0) << c.key;
      for (const double J : {0.8, 0.9, 0.95, 0.999, 1.001, 1.05, 1.1}) {
        if (J > 1 && !c.tension) continue;
        const double rho = kRho0 / J;
        const auto e = m->pressure_at_density(rho, kRho0, 300.0);
        ASSERT_TRUE(e);
        const double scale = std::abs(c.closed_form(0.95));
        EXPECT_NEAR(e->pressure, c.closed_form(J), 1e-12 * scale) << type << " " << c.key << " J " << J;
        // dp̄/dρ against a central difference (relative step 1e-6: O(h²) ~ 1e-12 plus round-off 1e-10).
        const double h = 1e-6 * rho;
        const double fd = (m->pressure_at_density(rho + h, kRho0, 300.0)->pressure -
                           m->pressure_at_density(rho - h, kRho0, 300.0)->pressure) / (2 * h);
        EXPECT_NEAR(e->dp_drho / fd, 1.0, 1e-6) << type << " " << c.key << " J " << J;
        EXPECT_EQ(e->c2, e->dp_drho);
        const auto back = m->density_at_pressure(e->pressure, kRho0, 300.0);
        ASSERT_TRUE(back);
        EXPECT_NEAR(*back / rho, 1.0, 1e-10) << type << " " << c.key << " J " << J;
      }
    }
}

// The inventory's Mie-Grüneisen table (4340, E = 0): p(0.9) = -1.402512e10 Pa (mean stress)
// is p̄ = 1.402512e10, dp/dJ = 1.939601e11 -> dp̄/dρ = (dp/dJ) ρ0/ρ² = 1.939601e11 J²/ρ0.
TEST(PlasticityEosHooks, MieGruneisenAgainstTheInventoryTable) {
  const auto m = metal("elastic_plastic_hp", "mie_gruneisen", {{"C_0", 3574.0}, {"Gamma_0", 1.69}, {"S_alpha", 1.92}});
  const auto e = m->pressure_at_density(kRho0 / 0.9, kRho0, 300.0);
  EXPECT_NEAR(e->pressure / 1.402512e10, 1.0, 1e-6);
  EXPECT_NEAR(e->dp_drho / (1.939601e11 * 0.81 / kRho0), 1.0, 1e-6);
}

// air has no tension: a negative gauge pressure has no density (NumericalFailure).
TEST(PlasticityEosHooks, UnreachablePressureIsANumericalFailure) {
  const auto m = metal("elastic_plastic", "air", {});
  EXPECT_THROW(m->density_at_pressure(-1e5, kRho0, 300.0), NumericalFailure);
}

}  // namespace
}  // namespace tephra
