// MesoBurn induction clock (mpmice/MesoBurn.h).
#include "mpmice/MesoBurn.h"

#include <cmath>

namespace tephra {

double meso_induction_time(const MesoInduction& prm, double T) {
  return T * T * prm.Cv / (prm.Ta * prm.Qc) * std::exp(prm.Ta / T) / prm.k;
}

bool meso_advance_clock(MesoClock& clock, const MesoInduction& prm, double T, double dt) {
  clock.tau = 0.99 * clock.tau + 0.01 * meso_induction_time(prm, T);
  if (T > kMesoInductionTemperature) clock.time_induced += dt;
  return clock.time_induced > clock.tau;
}

}  // namespace tephra
