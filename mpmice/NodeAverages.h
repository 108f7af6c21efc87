#pragma once
// The cell -> node averages of the coupled step (Vaango theory manual sec.
// 26.1.3 steps 7 and 13; mpmice/MpmIceTransfers.cpp): the value at node n is
// 1/8 of the 8 cells around it, each cell index clamped into `clamp` (the
// zero-gradient extension for nodes on the outer layer).
//
// Computed per own patch, at the nodes the patch owns: node n belongs to the
// patch that owns the interior cell clamp(n - off, interior) (so every node
// of the grid to exactly one patch). Its 8 cells then lie in that patch's
// cells, extra cells or first ghost layer, which the halo exchange filled
// with the owners' values: the average has the bits of a one-process run.
// Nodes of other patches (other MPI ranks) are left as they are (0): a sum
// over the ranks (MpmComponent::sum_node_*; x + 0 = x exactly) then gives
// every node of a rank's node box its owner's value (docs/parallel.md
// "MPMICE on ranks").
#include <algorithm>
#include <vector>

#include "core/grid/Fields.h"
#include "core/grid/Grid.h"
#include "mpm/NodeGrid.h"

namespace tephra {

template <class T>
T zero_of();
template <>
inline double zero_of<double>() { return 0.0; }
template <>
inline Vec3 zero_of<Vec3>() { return Vec3::Zero(); }

// out[gi] = 1/8 sum_8 f(clamped cell) at the nodes of g's patches with want(gi).
template <class T, class Want>
void own_node_averages(const Grid& g, const PatchFields<CellField<T>>& f, const NodeGrid& ng, const IntVec3& off,
                       const IndexRange& clamp, Want&& want, std::vector<T>& out) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& P = g.patches[pi];
    IntVec3 lo, hi;
    for (int d = 0; d < 3; ++d) {
      lo[d] = P.lo[d] == 0 ? 0 : P.lo[d] + off[d];
      hi[d] = P.hi[d] == g.cells[d] ? ng.n[d] : P.hi[d] + off[d];
    }
    const CellField<T>& fp = f[pi];
    for (int k = lo[2]; k < hi[2]; ++k)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int i = lo[0]; i < hi[0]; ++i) {
          const std::size_t gi = ng.index(i, j, k);
          if (!want(gi)) continue;
          const IntVec3 a = IntVec3(i, j, k) - off;
          T s = zero_of<T>();
          for (int c = 0; c < 8; ++c) {
            IntVec3 cell = a - IntVec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
            for (int d = 0; d < 3; ++d) cell[d] = std::clamp(cell[d], clamp.lo[d], clamp.hi[d] - 1);
            s += 0.125 * fp(cell);
          }
          out[gi] = s;
        }
  }
}

}  // namespace tephra
