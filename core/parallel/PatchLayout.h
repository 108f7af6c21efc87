#pragma once
// Which patches of a level this process holds, and the collectives a
// component needs over them (issue 7). A component keeps the whole level
// (`level`), every patch's rank (`owner`) and its own patches (`own`, level
// indices, ascending). Two modes:
//   distributed: the patches are spread over the world's ranks (the load
//                balancer's owners); the reductions below are MPI collectives
//                whose results are the same bits on every rank and for every
//                rank count (sums in ascending patch id);
//   whole:       this process holds every patch and talks to no one (a run
//                without mpirun, or a reference run inside an MPI test).
// The reductions give the same bits in both modes for the same per-patch
// partials, so a 1-rank run and an N-rank run agree.
#include <vector>

#include "core/grid/Grid.h"
#include "core/parallel/OrderedReduction.h"

namespace tephra {

struct PatchLayout {
  Grid level;
  std::vector<int> owner;  // owner[p] = rank of level.patches[p]
  std::vector<int> own;    // level indices of this process's patches, ascending
  bool distributed = false;

  // Every patch here, no messages.
  static PatchLayout whole(const Grid& level);
  // The patches cut over the world's ranks by assign_patches (cost: cells,
  // plus particles when `particles_per_patch` is given, one count per patch).
  static PatchLayout over_world_ranks(const Grid& level, const std::vector<long long>& particles_per_patch = {});

  // `level` with only the own patches (ids kept: Patch::id is the level index).
  Grid own_grid() const;

  double min(double v) const;
  double max(double v) const;
  bool any(bool flag) const;
  // Sum over all patches in ascending patch id, starting from 0
  // (ordered_patch_sum when distributed).
  std::vector<double> ordered_sum(const std::vector<PatchPartial>& local, int width) const;
  // One block per level patch, in level order, from this process's blocks
  // (own_blocks[n] belongs to own[n]); every process gets every block.
  std::vector<std::vector<double>> gather_blocks(const std::vector<std::vector<double>>& own_blocks) const;
};

}  // namespace tephra
