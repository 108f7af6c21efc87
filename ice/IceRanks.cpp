// IceComponent on MPI ranks (issue 7, docs/parallel.md): which patches this
// process holds, the halo exchange that fills their ghosts, and the checks
// every rank must decide together.
//
// Under mpirun the level's patches are cut over the ranks by the load
// balancer (core/parallel/LoadBalancer, cost = cells); setup_.grid then holds
// only this rank's patches (ids kept = level indices), so every loop of the
// step (`for pi < g.patches.size()`) runs over the own patches unchanged and
// every field is PatchFields over them. MpiHaloExchange fills the ghosts
// from the other ranks with the same bits LocalHaloExchange copies in one
// process. The reductions (stable dt, .dat sums, implicit residual, restart
// decisions) go through layout_ (core/parallel/PatchLayout). Source models
// (<Models>) compute their per-cell sources on the own patches and keep their
// sums per patch (ice/models/PatchSums.h), added in patch order over the
// ranks (IceComponent::model_reductions).
#include <memory>
#include <stdexcept>

#include "core/base/Errors.h"
#include "core/grid/MpiHaloExchange.h"
#include "ice/IceComponent.h"

namespace tephra {

void IceComponent::lay_out_patches() {
  if (!laid_out_) {
    laid_out_ = true;
    layout_ = keep_whole_level_ ? PatchLayout::whole(setup_.grid) : PatchLayout::over_world_ranks(setup_.grid);
    if (layout_.distributed) {
      for (const IceMaterialSpec& m : setup_.materials)
        if (m.lagrangian)  // MPMICE hands its MPM layout over first (adopt_layout)
          throw std::logic_error("IceComponent: lagrangian materials on ranks without the MPM layout");
      setup_.grid = layout_.own_grid();
    }
  }
  if (layout_.distributed)
    halo_ = std::make_unique<MpiHaloExchange>(layout_.level, layout_.owner);
  else
    halo_ = std::make_unique<LocalHaloExchange>(setup_.grid);
}

void IceComponent::adopt_layout(const PatchLayout& layout) {
  if (laid_out_) throw std::logic_error("IceComponent::adopt_layout after the patches were laid out");
  if (layout.level.patches.size() != setup_.grid.patches.size())
    throw std::logic_error("IceComponent::adopt_layout: another level");
  laid_out_ = true;
  layout_ = layout;
  if (layout_.distributed) setup_.grid = layout_.own_grid();
}

// Every rank throws when any rank finds a bad cell, so that none waits in the
// next collective (the last-state output after a NumericalFailure is one).
void IceComponent::check_state(int step, const char* phase) const {
  std::string failure;
  try {
    check_state_here(step, phase);
  } catch (const NumericalFailure& e) {
    failure = e.what();
  }
  if (layout_.any(!failure.empty()))
    throw NumericalFailure(!failure.empty() ? failure
                                            : "ICE " + std::string(phase) + " at step " + std::to_string(step) +
                                                  ": a bad cell on another MPI rank (its message is above)");
}

}  // namespace tephra
