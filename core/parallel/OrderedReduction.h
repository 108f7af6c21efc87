#pragma once
// Global sums that give the same bits on any number of ranks and threads
// (issue 7, "deterministic answers"): every rank reduces each of its patches
// to one partial (summed in the patch's own fixed particle/cell order), the
// partials of all ranks are gathered, and every rank adds them in ascending
// patch id. Floating-point addition is not associative, so this fixed order,
// not the rank layout, decides the rounding: 1, 2 or 4 ranks give identical
// results as long as the per-patch partials are identical.
#include <vector>

namespace tephra {

struct PatchPartial {
  int patch_id = 0;
  std::vector<double> values;  // the same length on every patch of every rank
};

// Sums `values` over all patches of all ranks in ascending patch id.
// `width` is the number of values per patch (needed when a rank owns no
// patch). Throws std::invalid_argument if a partial has another length or a
// patch id appears twice.
std::vector<double> ordered_patch_sum(const std::vector<PatchPartial>& local, int width);

// The same order, but for max / min (exact in any order; provided so callers
// use one interface): element-wise over every patch of every rank.
std::vector<double> patch_max(const std::vector<PatchPartial>& local, int width);
std::vector<double> patch_min(const std::vector<PatchPartial>& local, int width);

}  // namespace tephra
