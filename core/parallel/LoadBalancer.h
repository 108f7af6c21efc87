#pragma once
// Patches to ranks (issue 7): each rank gets a contiguous run of patches along
// a space-filling (Morton) curve through the patch lower corners, so a rank's
// patches are spatially compact and its ghost surface small, and the runs are
// chosen to minimise the largest rank cost. Deterministic: the same inputs
// give the same owners on every rank.
//
// Cost of a patch = cells * cost_per_cell + particles * cost_per_particle
// (seconds per step, from the measured per-cell and per-particle rates in
// docs/scaling.md; only the ratio matters).
#include <vector>

#include "core/grid/Grid.h"

namespace tephra {

struct LoadWeights {
  double cost_per_cell = 1.0;
  double cost_per_particle = 0.0;
};

struct RankAssignment {
  std::vector<int> owner;            // owner[patch index in grid.patches] = rank
  std::vector<double> rank_cost;     // summed patch cost per rank
  double imbalance() const;          // max rank cost / mean rank cost (1 = perfect)
};

// The patch order along the Morton (Z-order) curve of the patch lower corners
// (ties, impossible for a valid tiling, broken by patch index).
std::vector<int> morton_patch_order(const Grid& grid);

// Splits the weights, taken in `order`, into `ranks` contiguous runs that
// minimise the largest run sum (bisection on the capacity with a greedy
// feasibility test, then the greedy fill at the smallest feasible capacity).
// Every rank gets at least one patch when there are at least `ranks` patches.
std::vector<int> partition_contiguous(const std::vector<double>& weights, const std::vector<int>& order,
                                      int ranks);

// Assigns grid.patches to `ranks` ranks; particles_per_patch may be empty
// (cells only) or hold one count per patch.
RankAssignment assign_patches(const Grid& grid, const std::vector<long long>& particles_per_patch,
                              int ranks, const LoadWeights& weights = {});

}  // namespace tephra
