#pragma once
// The temperature-dependent JWL law (Jones-Wilkins-Lee with a thermal term),
// shared by the ICE EOS `JWL` (ExplosiveProductEos.cpp) and visco_scram's
// <useJWLEOS> MPMICE hooks (models/solid/ViscoScramJwl.cpp). Uintah/Vaango
// JWL.cc and ViscoScram "temperature dependent JWL"; derivatives re-derived.
//   V = rho0/rho (relative volume), cv the specific heat per unit mass:
//   p = A exp(-R1 V) + B exp(-R2 V) + om cv T rho
//   dp/drho|_T = (R1 V P1 + R2 V P2)/rho + om cv T     (dV/drho = -V/rho)
//   dp/dT|_rho = om cv rho   => dp/de = om rho
// (visco_scram's Cv per unit volume is rho0 cv: om Cv T / V = om cv T rho.)
#include <cmath>

#include "models/eos/PointEos.h"

namespace tephra {

inline PointThermo jwl_point(double A, double B, double R1, double R2, double om, double rho0, double cv,
                             double rho, double T) {
  const double V = rho0 / rho, P1 = A * std::exp(-R1 * V), P2 = B * std::exp(-R2 * V);
  return {P1 + P2 + om * cv * T * rho, (R1 * V * P1 + R2 * V * P2) / rho + om * cv * T, om * cv * rho};
}

}  // namespace tephra
