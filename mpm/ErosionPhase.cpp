// MpmComponent: erosion of the particles the material's model flags as failed.
#include "mpm/MpmComponent.h"

#include <cmath>

namespace tephra {

void MpmComponent::erode(MpmMaterial& m) {
  const std::vector<HistoryVariable> hist = m.model->history();
  // The material's dilatational wave speed at rest (mpm/Erosion.h, ZeroStress).
  const double c0 = std::sqrt((m.model->bulk_modulus() + 4.0 * m.model->shear_modulus() / 3.0) / m.density);
  for (std::size_t k = 0; k < hist.size(); ++k)
    if (hist[k].name == localized_history_name() && hist[k].components == 1)
      erode_failed_particles(setup_.flags.erosion, m.particles.history[k], m.particles.stress, m.particles.wave_speed, c0);
}

}  // namespace tephra
