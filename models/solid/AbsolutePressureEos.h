#pragma once
// Optional interface of a constitutive model whose MPMICE equation of state
// gives the ABSOLUTE pressure itself (visco_scram <useJWLEOS>: Vaango's
// ViscoScram::computePressEOSCM returns the JWL pressure with no p_ref added),
// where the ConstitutiveModel hooks pressure_at_density / density_at_pressure
// are gauge pressures p - p_ref. models/solid/ModifiedEos.cpp's mpmice_*
// functions use it (dynamic_cast) ahead of the gauge hooks and of the generic
// modified EOS; p_ref is the run's reference pressure, for a model's own
// modified-EOS branch. (An interface of its own, so that the widely included
// ConstitutiveModel.h does not change.)
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

class AbsolutePressureEos {
 public:
  virtual ~AbsolutePressureEos() = default;
  // false: the model does not use the absolute form (its gauge hooks apply).
  virtual bool uses_absolute_pressure_eos() const = 0;
  // p(rho, T) [Pa absolute], dp/drho, c^2.
  virtual SolidEosPoint absolute_pressure_at_density(double rho, double density0, double T, double p_ref) const = 0;
  // The inverse: rho with absolute_pressure_at_density(rho).pressure = p.
  virtual double density_at_absolute_pressure(double p, double density0, double T, double p_ref) const = 0;
};

// The interface of `model` when it uses the absolute form, else nullptr.
inline const AbsolutePressureEos* absolute_pressure_eos(const ConstitutiveModel& model) {
  const auto* a = dynamic_cast<const AbsolutePressureEos*>(&model);
  return a && a->uses_absolute_pressure_eos() ? a : nullptr;
}

}  // namespace tephra
