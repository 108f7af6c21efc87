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
// share_above (axisymmetric runs, else null): per node of ng, the share of
// its mass the projection gave the cell above it in r (CellProjection.h);
// the cell above then weighs share/4, the one below (1 - share)/4, y and z
// keeping their 1/2: the node takes back the cells' changes with the weights
// its mass went to them (momentum conserved; a node whose mass all went to
// the cell below does not take the change of the trace solid above it).
//
// The storage position of cell (x, y, z) is linear in each index
// (GridArray::offset), offset = base + X(x) + Y(y) + Z(z); the clamped cell
// indices a and a - 1 of each node coordinate and their offset terms are
// tabulated per axis once per patch, so a node costs 8 loads and adds
// (session 19; before, 8 clamps of an IntVec3 and 8 offset products per
// node). The 8 terms are added in the same order c = 0..7 (cell a - (c&1,
// c>>1&1, c>>2&1)) from the same values: the same bits.
template <class T, class Want>
void own_node_averages(const Grid& g, const PatchFields<CellField<T>>& f, const NodeGrid& ng, const IntVec3& off,
                       const IndexRange& clamp, Want&& want, std::vector<T>& out,
                       const std::vector<double>* share_above = nullptr) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& P = g.patches[pi];
    IntVec3 lo, hi;
    for (int d = 0; d < 3; ++d) {
      lo[d] = P.lo[d] == 0 ? 0 : P.lo[d] + off[d];
      hi[d] = P.hi[d] == g.cells[d] ? ng.n[d] : P.hi[d] + off[d];
    }
    if (lo[0] >= hi[0] || lo[1] >= hi[1] || lo[2] >= hi[2]) continue;
    const CellField<T>& fp = f[pi];
    // The clamped cell index of node coordinate n along d, for bit b = 0 (a)
    // and b = 1 (a - 1), a = n - off[d].
    auto cell_index = [&](int d, int n, int b) { return std::clamp(n - off[d] - b, clamp.lo[d], clamp.hi[d] - 1); };
    const IntVec3 r(cell_index(0, lo[0], 0), cell_index(1, lo[1], 0), cell_index(2, lo[2], 0));
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(fp.offset(r[0], r[1], r[2]));
    std::vector<std::ptrdiff_t> terms[3];  // per axis: 2 offset terms per node coordinate
    for (int d = 0; d < 3; ++d) {
      terms[d].resize(2 * static_cast<std::size_t>(hi[d] - lo[d]));
      for (int n = lo[d]; n < hi[d]; ++n)
        for (int b = 0; b < 2; ++b) {
          IntVec3 c = r;
          c[d] = cell_index(d, n, b);
          terms[d][2 * static_cast<std::size_t>(n - lo[d]) + b] =
              static_cast<std::ptrdiff_t>(fp.offset(c[0], c[1], c[2])) - base;
        }
    }
    const T* data = fp.data() + base;
    for (int k = lo[2]; k < hi[2]; ++k) {
      const std::ptrdiff_t* Z = &terms[2][2 * static_cast<std::size_t>(k - lo[2])];
      for (int j = lo[1]; j < hi[1]; ++j) {
        const std::ptrdiff_t* Y = &terms[1][2 * static_cast<std::size_t>(j - lo[1])];
        for (int i = lo[0]; i < hi[0]; ++i) {
          const std::size_t gi = ng.index(i, j, k);
          if (!want(gi)) continue;
          const std::ptrdiff_t* X = &terms[0][2 * static_cast<std::size_t>(i - lo[0])];
          T s = zero_of<T>();
          if (share_above) {
            const double wx[2] = {0.25 * (*share_above)[gi], 0.25 * (1.0 - (*share_above)[gi])};
            for (int c = 0; c < 8; ++c) s += wx[c & 1] * data[X[c & 1] + Y[(c >> 1) & 1] + Z[(c >> 2) & 1]];
          } else {
            for (int c = 0; c < 8; ++c) s += 0.125 * data[X[c & 1] + Y[(c >> 1) & 1] + Z[(c >> 2) & 1]];
          }
          out[gi] = s;
        }
      }
    }
  }
}

}  // namespace tephra
