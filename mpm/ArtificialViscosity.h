#pragma once
// Artificial bulk viscosity of explicit MPM (<MPM><artificial_viscosity>),
// as Vaango computes it (ConstitutiveModel::artificialBulkViscosity, called
// from each model's computeStressTensor; used in SerialMPM's
// computeInternalForce): a von Neumann-Richtmyer quadratic plus a Landshoff
// linear term acting only in compression,
//   q = rho (A1 c_b |tr D| h + A2 (tr D h)^2)   if tr D < 0,   q = 0 otherwise,
// with D = sym(l) the rate of deformation of the step, rho = m/V the current
// density, c_b = sqrt(K/rho) the bulk sound speed (K the model's bulk
// modulus), h = (h_x + h_y + h_z)/3. The stress that enters the internal
// force of the NEXT step is sigma - q I; the stored stress (p.stress) stays
// the model's. q smears a shock over a few cells (damps the Gibbs ringing of
// a velocity jump) and is O(h) where the flow is smooth.
#include <vector>

#include "core/base/Types.h"

namespace tephra {

struct ArtificialViscosityCoefficients {
  double A1 = 0.2;  // linear   (<artificial_viscosity_coeff1>, Vaango default)
  double A2 = 2.0;  // quadratic (<artificial_viscosity_coeff2>, Vaango default)
};

// q of one point (see above).
inline double artificial_bulk_viscosity(double trace_D, double bulk_sound_speed, double rho, double h,
                                        const ArtificialViscosityCoefficients& a) {
  if (!(trace_D < 0.0)) return 0.0;
  const double rate = trace_D * h;  // [m/s]
  return rho * (a.A1 * bulk_sound_speed * -rate + a.A2 * rate * rate);
}

}  // namespace tephra
