#pragma once
// Vaango's modified EOS for MPMICE (<useModifiedEOS>; UCNH, ElasticPlastic, ElasticPlasticHP and
// ViscoScram computePressEOSCM / computeRhoMicroCM), one mechanism for every model that sets
// ConstitutiveModel::modified_eos():
//   rho >= rho0: the model's own hooks (pressure_at_density / density_at_pressure), gauge p - p_ref;
//   rho <  rho0: absolute p = p_ref (rho/rho0)^n, n = K0/p_ref,
//                dp/drho = (K0/rho)(rho/rho0)^n = c^2,
// with K0 = rho0 dp/drho(rho0) of the compression branch. Both branches give p = p_ref and
// dp/drho = K0/rho0 at rho0: C^1 at J = 1 (as in Vaango, whose branches both use the bulk
// modulus K: for the neo-Hookean branch K/2 (rho/rho0 - rho0/rho) and default_hypo K ln(rho/rho0),
// K0 = K and the tension branch is Vaango's exactly). The pressure stays positive for any
// expansion (p -> 0 as rho -> 0): the point of the modified law, a solid that cannot carry
// tension in the ICE pressure equilibration. Inverse (p_gauge < 0): rho = rho0 ((p_gauge + p_ref)/p_ref)^{1/n}.
// Departure: Vaango's ElasticPlastic(HP) hooks ignore the <equation_of_state> sub-model (always
// neo-Hookean with K); Tephra's compression branch is the sub-model's (PlasticityEos.h), so with
// mie_gruneisen K0 = rho0 C_0^2, not <bulk_modulus>.
#include <optional>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

// The expansion branch alone: gauge p - p_ref at rho (< rho0) for the bulk modulus K0.
SolidEosPoint modified_eos_expansion(double rho, double density0, double K0, double p_ref);
// Its inverse for p_gauge in (-p_ref, 0].
double modified_eos_expansion_density(double p_gauge, double density0, double K0, double p_ref);

// The MPMICE hooks of a model with the run's reference pressure p_ref [Pa]: the model's
// absolute-pressure hooks when it has them (models/solid/AbsolutePressureEos.h, minus p_ref
// here), else the model's gauge hooks when !model.modified_eos(), the two branches
// above otherwise. std::nullopt when the model has
// no hooks.
std::optional<SolidEosPoint> mpmice_pressure_at_density(const ConstitutiveModel& model, double rho, double density0,
                                                        double T, double p_ref);
std::optional<double> mpmice_density_at_pressure(const ConstitutiveModel& model, double p_gauge, double density0,
                                                 double T, double p_ref);

// The same in absolute pressure p (gauge + p_ref), what the MPMICE equilibration needs: the
// expansion branch is evaluated as p = p_ref (rho/rho0)^n and rho = rho0 (p/p_ref)^{1/n}
// directly, without the round trip p_ref + (p - p_ref), which loses every digit of a pressure
// below eps p_ref (a solid expanded to p ~ 1e-12 Pa read back as rho = 0; guni2dRT.ups).
std::optional<SolidEosPoint> mpmice_absolute_pressure_at_density(const ConstitutiveModel& model, double rho,
                                                                 double density0, double T, double p_ref);
std::optional<double> mpmice_density_at_absolute_pressure(const ConstitutiveModel& model, double p, double density0,
                                                          double T, double p_ref);

}  // namespace tephra
