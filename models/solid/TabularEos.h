#pragma once
// Vaango's tabular equation of state, type "tabular_eos" (VT §22.2; Vaango class
// TabularEquationOfState). A pressure-only solid:
//   sigma = -p(eta) I,  eta = rho/rho0 = 1/J,
// p(eta) (positive in compression) linearly interpolated in a table read from a
// JSON file (models/solid/PressureTable.h, VT eqs. 22.1-22.4).
//
// Deck:
//   <constitutive_model type="tabular_eos">
//     <filename>table.json</filename>             (beside the deck, else the working directory)
//     <independent_variables>DensityRatio</independent_variables>
//     <dependent_variables>Pressure</dependent_variables>
//     <interpolation type="linear"/>
//   </constitutive_model>
// File (Vaango TabularData, one independent variable):
//   {"Vaango_tabular_data": {"Meta": {"title": "..."},
//                            "Data": {"DensityRatio": [..], "Pressure": [..]}}}
// The names are the deck's; the independent variable is read as eta whatever its
// name (Vaango's stress update passes rho/rho0). eta strictly increasing and > 0,
// the pressures strictly increasing (a positive bulk modulus on every segment),
// at least two rows, every value finite: anything else is a DeckError naming the
// table file, its line and the deck element <filename>.
//
// Bulk modulus and wave speed: K = rho dp/drho = eta dp/deta, c^2 = K/rho = dp/drho
// = (dp/deta)/rho0 with dp/deta the slope of the segment holding eta.
// ERRATUM (VT eq. 22.5 and Vaango's computeBulkModulus): K = rho [p(eta+e) - p(eta-e)]/(2e)
// multiplies dp/deta [Pa] by rho [kg/m^3]; the bulk modulus is eta dp/deta (Tephra).
// Vaango's central difference with e = 1e-6 is the segment slope except within 1e-6
// of a knot (the mean of the two slopes there); Tephra takes the segment's slope.
// Stored energy: W(J) = -int_1^J p dJ' exactly (Vaango reports 0.5 p ln(rho0/rho)).
// MPMICE hooks (missing in Vaango, which prints a message and returns 0):
//   p_gauge = p(rho/rho0), dp/drho = c^2 above, rho(p) the inverse of the same table.
// Not implemented: <interpolation type="cubic"> (Vaango's schema allows it; its
// code interpolates linearly whatever the type) -> MissingFeature; more than one
// dependent variable (only the first would have a role) -> MissingFeature.
#include <string>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/PressureTable.h"

namespace tephra {

class TabularEos final : public ConstitutiveModel {
 public:
  explicit TabularEos(PressureTable table) : table_(std::move(table)) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "tabular_eos"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return table_.slope(1.0); }  // eta dp/deta at eta = 1
  double shear_modulus() const override { return 0.0; }
  bool hyperelastic() const override { return true; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;
  const PressureTable& table() const { return table_; }

 private:
  PressureTable table_;
};

// Reads and checks a Vaango tabular-data JSON text with one independent
// variable `x_name` and one dependent variable `p_name`; throws JsonError
// (with the line) when the structure or the values are wrong.
PressureTable read_pressure_table(const std::string& json_text, const std::string& x_name,
                                  const std::string& p_name);

}  // namespace tephra
