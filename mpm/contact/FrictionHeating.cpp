#include "mpm/contact/FrictionHeating.h"

#include "mpm/shape/AxisStencils.h"

namespace tephra {

void friction_heat_to_particles(const Stencils& s, const NodeGrid& g, const std::vector<double>& work,
                                double specific_heat, Particles& p) {
  // The node temperature increment W_g / (c_v m_g), then S-weighted to the particles.
  std::vector<double> dT(g.count(), 0.0);
  bool any = false;
  for (std::size_t gi = 0; gi < g.count(); ++gi)
    if (work[gi] != 0.0 && g.mass[gi] > 0.0) dT[gi] = work[gi] / (specific_heat * g.mass[gi]), any = true;
  if (!any) return;
  visit_stencils(s, [&](const auto& view) {
    const long np = long(p.size());
#pragma omp parallel for schedule(static) if (np >= 4096)
    for (long i = 0; i < np; ++i) {
      double sum = 0.0;
      view.weights(std::size_t(i), [&](std::size_t gi, double w) { sum += w * dT[gi]; });
      p.temperature[std::size_t(i)] += sum;
    }
  });
}

}  // namespace tephra
