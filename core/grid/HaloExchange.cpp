// LocalHaloExchange: ghost filling and node accumulation among the patches
// held in one process. See HaloExchange.h for the rules.
#include "core/grid/HaloExchange.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/grid/HaloIndex.h"
#include "core/grid/Loop.h"

namespace tephra {

namespace {

using halo::owner_index;
using halo::owner_patch;

template <class FieldT>
void check_layout(const Grid& g, const PatchFields<FieldT>& pf) {
  if (pf.size() != g.patches.size() || !pf.holds_all_patches())
    throw std::logic_error("halo exchange: the fields do not hold one field per patch of this grid");
}

template <class FieldT>
void exchange_impl(const Grid& g, PatchFields<FieldT>& pf, bool nodes) {
  check_layout(g, pf);
  // One patch and no periodic direction: every stored entry outside the
  // patch's own box lies beyond the extra cells (owner_index is false), so
  // there is nothing to fill.
  if (pf.size() == 1 && g.periodic == IntVec3::Zero()) return;
  for (size_t n = 0; n < pf.size(); ++n) {
    FieldT& f = pf[n];
    const IndexRange own = f.with_extra();
    // Each thread writes ghosts of f only and reads entries that patches own,
    // which no thread writes: no races. Only the shell outside with_extra()
    // is visited: one task per (j, k) row, and a row that crosses the owned
    // box skips its owned run of i (O(surface) work instead of O(volume)).
    const IndexRange all = f.with_ghosts();
    const IndexRange rows{all.lo, IntVec3(all.lo[0] + 1, all.hi[1], all.hi[2])};
    for_each_cell(rows, [&](int, int j, int k) {
      // A row beyond the level's extra cells in y or z (non-periodic) has no
      // entry owner_index accepts: skip it whole (session 19; the same
      // entries are copied, the per-cell test of its i run is saved).
      for (int d = 1; d < 3; ++d) {
        if (g.periodic[d]) continue;
        const int c = d == 1 ? j : k;
        if (c < -g.extra_cells[d] || c >= g.cells[d] + g.extra_cells[d] + (nodes ? 1 : 0)) return;
      }
      // Cells: the with_extra() boxes of the patches partition the level
      // (interior cells plus the extra cells of domain faces), so s lies in
      // patch q's box exactly when owner_patch(s) == q; the last owner is
      // reused while s stays in its box (one patch lookup per run of a row
      // instead of one per cell; the same entries are copied). Nodes on a
      // patch boundary lie in two node boxes: looked up every time.
      auto fill = [&](int i0, int i1) {
        int q = -1;
        IndexRange box_q{};
        for (int i = i0; i < i1; ++i) {
          const IntVec3 c(i, j, k);
          IntVec3 s;
          if (!owner_index(g, c, nodes, s)) continue;
          if (nodes || q < 0 || !box_q.contains(s)) {
            q = owner_patch(g, s);
            box_q = pf[size_t(q)].with_extra();
          }
          f(c) = pf[size_t(q)](s);
        }
      };
      if (j >= own.lo[1] && j < own.hi[1] && k >= own.lo[2] && k < own.hi[2]) {
        fill(all.lo[0], std::max(all.lo[0], own.lo[0]));
        fill(std::min(all.hi[0], own.hi[0]), all.hi[0]);
      } else {
        fill(all.lo[0], all.hi[0]);
      }
    });
  }
}

inline double zero_of(double) { return 0.0; }
inline Vec3 zero_of(const Vec3&) { return Vec3::Zero(); }

template <class T>
void accumulate_impl(const Grid& g, PatchFields<NodeField<T>>& pf) {
  check_layout(g, pf);
  // One slot per physical node of the level: periodic directions have
  // `cells` distinct nodes, others cells + 1 plus the extra nodes.
  IntVec3 n, off;
  for (int d = 0; d < 3; ++d) {
    n[d] = g.periodic[d] ? g.cells[d] : g.cells[d] + 2 * g.extra_cells[d] + 1;
    off[d] = g.periodic[d] ? 0 : g.extra_cells[d];
  }
  auto slot = [&](const IntVec3& s) {
    return (size_t(s[2] + off[2]) * n[1] + size_t(s[1] + off[1])) * n[0] + size_t(s[0] + off[0]);
  };
  std::vector<T> sum(size_t(n[0]) * n[1] * n[2], zero_of(T()));
  // Gather in patch order (serial: patches share slots), then scatter back.
  for (size_t p = 0; p < pf.size(); ++p) {
    NodeField<T>& f = pf[p];
    for_each_cell_serial(f.with_ghosts(), [&](int i, int j, int k) {
      IntVec3 s;
      if (owner_index(g, IntVec3(i, j, k), true, s)) sum[slot(s)] += f(i, j, k);
    });
  }
  for (size_t p = 0; p < pf.size(); ++p) {
    NodeField<T>& f = pf[p];
    for_each_cell(f.with_ghosts(), [&](int i, int j, int k) {
      IntVec3 s;
      if (owner_index(g, IntVec3(i, j, k), true, s)) f(i, j, k) = sum[slot(s)];
    });
  }
}

}  // namespace

void LocalHaloExchange::exchange(PatchFields<CellField<double>>& f) { exchange_impl(*grid_, f, false); }
void LocalHaloExchange::exchange(PatchFields<CellField<Vec3>>& f) { exchange_impl(*grid_, f, false); }
void LocalHaloExchange::exchange(PatchFields<NodeField<double>>& f) { exchange_impl(*grid_, f, true); }
void LocalHaloExchange::exchange(PatchFields<NodeField<Vec3>>& f) { exchange_impl(*grid_, f, true); }
void LocalHaloExchange::accumulate(PatchFields<NodeField<double>>& f) { accumulate_impl(*grid_, f); }
void LocalHaloExchange::accumulate(PatchFields<NodeField<Vec3>>& f) { accumulate_impl(*grid_, f); }

}  // namespace tephra
