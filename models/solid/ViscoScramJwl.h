#pragma once
// The JWL volumetric response of visco_scram for MPMICE (<useJWLEOS> true;
// Vaango ViscoScram::computePressEOSCM / computeRhoMicroCM, "temperature
// dependent JWL"). Only the MPMICE hooks use it: Vaango's stress update keeps
// the hypoelastic mean stress p_dot = K tr(d) whatever the flag.
//
//   p(rho, T) = A e^{-R1 V} + B e^{-R2 V} + om Cv T / V,     V = rho0/rho
//   dp/drho   = (R1 rho0 P1 + R2 rho0 P2)/rho^2 + om Cv T/rho0,   c^2 = dp/drho
// (the law of models/eos/JwlLaw.h with cv = Cv/rho0)
// (P1, P2 the A and B terms). p is the ABSOLUTE pressure (no p_ref added);
// Cv is per unit volume [J/(m^3 K)] (the decks give rho0 c_v: BurnRate.ups
// 2.780236e6 = 1832 x 1517.6), om the Gruneisen coefficient.
//
// <useModifiedEOS> with JWL (Vaango computeRhoRef): the reference density
// rho_ref solves p(rho_ref, T) = p_ref, K0 = rho_ref dp/drho(rho_ref) =
// v (A R1 e^{-R1 v} + B R2 e^{-R2 v}) + om Cv T/v, v = rho0/rho_ref; below
// rho_ref p = p_ref (rho/rho_ref)^{K0/p_ref}, dp/drho = (K0/rho)(rho/rho_ref)^{K0/p_ref}
// (C^1 at rho_ref), inverse rho = rho_ref (p/p_ref)^{p_ref/K0}.
//
// Inverse rho(p, T): p(rho) is not monotone for the decks' constants (B < 0:
// PBX 9501 of BurnRate.ups has p > 0 for V > ~2, p < 0 for 1.05 < V < 1.8,
// then the steep compression branch through V = 1), so a small positive p has
// up to three roots. Tephra returns the largest one, the root on the
// compression branch through rho0 (p increases with rho above the dip):
// bracketed by scanning down from rho0 (first sign change from above), then
// the safeguarded Newton of models/eos/DensitySolve.h to 1e-15 relative. Departure: Vaango's
// Newton-bisection starts from the cell's previous density and returns
// whichever root it reaches.
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct ViscoScramJwl {
  double A = 0, B = 0, R1 = 0, R2 = 0, om = 0, Cv = 0;  // Cv [J/(m^3 K)]
  bool modified = false;                                // <useModifiedEOS>

  // The JWL law alone (no modified branch), absolute pressure.
  SolidEosPoint jwl(double rho, double rho0, double T) const;
  // The largest root of jwl(rho) = p; throws NumericalFailure when there is none.
  double jwl_density(double p, double rho0, double T) const;
  // The MPMICE hooks: JWL, or with `modified` the expansion branch below rho_ref(T).
  SolidEosPoint pressure(double rho, double rho0, double T, double p_ref) const;
  double density(double p, double rho0, double T, double p_ref) const;
};

}  // namespace tephra
