// MpmComponent: erosion of the particles the material's model flags as failed.
#include "mpm/MpmComponent.h"

namespace tephra {

void MpmComponent::erode(MpmMaterial& m) {
  const std::vector<HistoryVariable> hist = m.model->history();
  for (std::size_t k = 0; k < hist.size(); ++k)
    if (hist[k].name == localized_history_name() && hist[k].components == 1)
      erode_failed_particles(setup_.flags.erosion, m.particles.history[k], m.particles.stress);
}

}  // namespace tephra
