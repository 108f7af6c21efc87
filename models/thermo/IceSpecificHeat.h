#pragma once
// Temperature-dependent specific heat c_v(T) of an ICE material
// (<SpecificHeatModel type="Debye|Component|Polynomial"> beside <EOS>).
// Facts from Uintah's ICE SpecificHeatModel (Debye.cc, Component.cc,
// Polynomial.cc); formulas in IceSpecificHeat.cpp. ICE evaluates c_v per cell
// from the cell temperature at the start of each step and uses it where the
// constant <specific_heat> was used (Uintah ICE.cc: cv = cvModel->getSpecificHeat(T)).
// One virtual call per cell and step (no per-particle dispatch involved).
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tephra {

class IceSpecificHeat {
 public:
  virtual ~IceSpecificHeat() = default;
  virtual const char* type() const = 0;
  // c_v(T) [J/(kg K)], T > 0.
  virtual double cv(double T) const = 0;
  // The ratio of specific heats the model defines (Component: the mole-fraction
  // mix), or nullopt when the material's <gamma> stays in force (Debye,
  // Polynomial: Uintah returns a hard-coded 1.4 "should be the input file value").
  virtual std::optional<double> gamma() const { return std::nullopt; }
};
using IceSpecificHeatP = std::shared_ptr<const IceSpecificHeat>;

// Polynomial: c_v = sum_{i=0}^{m} a_i T^(i-m), T clamped to [Tmin, Tmax]
// (Uintah's header formula; its code returns the reciprocal, see the .cpp).
IceSpecificHeatP make_polynomial_cv(int max_order, std::vector<double> a, double Tmin, double Tmax);
// Debye: c_v = 9 N k_B (T/T_D)^3 int_0^{T_D/T} x^4 e^x/(e^x-1)^2 dx.
IceSpecificHeatP make_debye_cv(int atoms, double debye_temperature);
// Component: NASA-style c_p fits of 10 gases (Heywood 1988, p. 131) mixed by
// mole fraction; c_v = c_p/gamma_mix. Fractions in the order of component_cv_species().
IceSpecificHeatP make_component_cv(const std::vector<double>& mole_fractions);
const std::vector<std::string>& component_cv_species();  // XCO2, XH2O, XCO, XH2, XO2, XN2, XOH, XNO, XO, XH

}  // namespace tephra
