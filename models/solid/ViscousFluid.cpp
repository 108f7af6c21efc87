#include "models/solid/ViscousFluid.h"

#include <cmath>

namespace tephra {

double power_law_energy(double J, double a, double g) {
  const double lnJ = std::log(J);
  if (std::abs(g - 1.0) < 1e-12) return a * (-lnJ + (J - 1.0));
  // (J^{1-g} - 1)/(g - 1) = expm1((1 - g) ln J)/(g - 1): exact 0 at J = 1.
  return a * (std::expm1((1.0 - g) * lnJ) / (g - 1.0) + (J - 1.0));
}

}  // namespace tephra
