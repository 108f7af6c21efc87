#include "models/solid/RigidMaterial.h"

#include "models/ModelParameters.h"

namespace tephra {

long RigidMaterial::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const size_t n = in.F_new.size();
  for (size_t i = 0; i < n; ++i) {
    out.stress[i].setZero();  // VT eq. 3.1
    out.wave_speed[i] = 0.0;
    out.energy_density[i] = 0.0;
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
  }
  return -1;
}

std::optional<SolidEosPoint> RigidMaterial::pressure_at_density(double, double density0, double) const {
  SolidEosPoint e;
  e.pressure = 0.0;
  e.dp_drho = K_ / density0;
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> RigidMaterial::density_at_pressure(double, double density0, double) const {
  return density0;
}

ConstitutiveModelP RigidMaterial::create(const ModelParameters& params) {
  const double G = params.get_double("shear_modulus", 1.0e200);
  const double K = params.get_double("bulk_modulus", 1.0e200);
  if (!(G > 0.0)) params.fail("shear_modulus", "shear_modulus must be > 0");
  if (!(K > 0.0)) params.fail("bulk_modulus", "bulk_modulus must be > 0");
  // A rigid body has no strain, thermal or other: the expansion coefficient (deck A4) is accepted, unused.
  params.get_double("coeff_thermal_expansion", 0.0);
  return std::make_shared<RigidMaterial>(K, G);
}

}  // namespace tephra
