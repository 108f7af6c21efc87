#pragma once
// Which patch holds a stored index: the rules shared by the halo exchanges
// (HaloExchange.h states them; LocalHaloExchange and MpiHaloExchange apply
// them, so the two agree entry for entry).
#include <algorithm>

#include "core/grid/Grid.h"

namespace tephra::halo {

inline int wrap(int c, int n) {
  const int m = c % n;
  return m < 0 ? m + n : m;
}

// The level index that a stored index stands for: wrapped in periodic
// directions; false when it lies beyond the extra cells (or extra nodes) of a
// non-periodic face. `nodes` adds the one extra node per direction.
inline bool owner_index(const Grid& g, const IntVec3& c, bool nodes, IntVec3& out) {
  for (int d = 0; d < 3; ++d) {
    if (g.periodic[d]) {
      out[d] = wrap(c[d], g.cells[d]);
    } else {
      const int lo = -g.extra_cells[d], hi = g.cells[d] + g.extra_cells[d] + (nodes ? 1 : 0);
      if (c[d] < lo || c[d] >= hi) return false;
      out[d] = c[d];
    }
  }
  return true;
}

// The patch holding level index s (cells: the patch whose cells_with_extra()
// contains s; nodes: one of the patches whose node range contains s). Extra
// cells belong to the patch of the nearest interior cell, so clamping s into
// the interior finds the owner.
inline int owner_patch(const Grid& g, const IntVec3& s) {
  IntVec3 c;
  for (int d = 0; d < 3; ++d) c[d] = std::min(std::max(s[d], 0), g.cells[d] - 1);
  return g.patch_owning_cell(c);
}

}  // namespace tephra::halo
