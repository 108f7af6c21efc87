#pragma once
// The update() loop shared by the composed metal models (elastic_plastic,
// elastic_plastic_hp): copy the point's history columns into a local array,
// call the model's update_point, write history and outputs back. Included
// only by those two models' .cpp files.
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/MetalFailure.h"
#include "models/solid/PointLoop.h"

namespace tephra {

// MaxHistory: the largest number of history values of the model (the local array
// size; a tensor column counts 9); the first nh columns of model.history() are used,
// laid out flat in the local array (column k's components after column k-1's). Scalar
// columns placed before any tensor column keep their column index as flat offset.
// Random initial fields (MetalFailure.h):
// when k_drawn >= 0, a point whose column k_drawn is 0 gets its Gaussian porosity
// (column k_phi) and damage (column k_D) drawn from its index i, and the flag is set.
template <int MaxHistory, class Model>
long update_metal_points(const Model& model, int nh, const SolidUpdateInput& in, const SolidUpdateOutput& out,
                         int k_drawn = -1, int k_phi = -1, int k_D = -1) {
  int comps[MaxHistory];
  {
    const std::vector<HistoryVariable> declared = model.history();
    int total = 0;
    for (int k = 0; k < nh; ++k) total += comps[k] = declared[k].components;
    if (total > MaxHistory) throw std::logic_error("update_metal_points: history larger than MaxHistory");
  }
  return for_each_point(in.F_new.size(), [&](std::size_t i) {
    double hist[MaxHistory];
    for (int k = 0, o = 0; k < nh; ++k)
      for (int c = 0; c < comps[k]; ++c) hist[o++] = out.history[k][i * comps[k] + c];
    if (k_drawn >= 0 && hist[k_drawn] == 0.0) {
      draw_initial_fields(model.failure_, i, hist[k_phi], hist[k_D]);
      hist[k_drawn] = 1.0;
    }
    typename Model::PointOut po;
    if (!model.update_point(in.F_old[i], in.F_new[i], in.stress_old[i], in.temperature[i], in.dt, in.density0, hist,
                            po))
      return false;
    for (int k = 0, o = 0; k < nh; ++k)
      for (int c = 0; c < comps[k]; ++c) out.history[k][i * comps[k] + c] = hist[o++];
    out.stress[i] = po.r.stress;
    out.wave_speed[i] = po.r.wave_speed;
    out.energy_density[i] = po.r.energy_density;
    out.plastic_work[i] = po.plastic_work;
    out.heating[i] = po.heating;
    return true;
  });
}

}  // namespace tephra
