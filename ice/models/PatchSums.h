#pragma once
// A source model's reduction sums kept per patch (issue 7, docs/parallel.md
// "ICE source models on ranks"): row pi holds the partial of own patch pi
// (setup grid order, Patch::id = level index), each row summed in the
// patch's own cell order. The component adds the rows of all ranks in
// ascending patch id (PatchLayout::ordered_sum), so the total is the same
// bits on 1 and N ranks: a single running sum over all cells of one process
// would be rounded differently from N per-rank sums.
#include <cstddef>
#include <vector>

#include "core/grid/Grid.h"
#include "core/parallel/OrderedReduction.h"

namespace tephra {

class PatchSums {
 public:
  // `width` values per patch, all zero.
  void reset(const Grid& g, int width) {
    width_ = width;
    rows_.assign(g.patches.size(), PatchPartial{});
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      rows_[pi].patch_id = g.patches[pi].id;
      rows_[pi].values.assign(std::size_t(width), 0.0);
    }
  }
  // Keeps the rows, zeroes the values (the start of a step).
  void zero() {
    for (PatchPartial& r : rows_) r.values.assign(std::size_t(width_), 0.0);
  }
  double& at(std::size_t pi, int k) { return rows_[pi].values[std::size_t(k)]; }
  const std::vector<PatchPartial>& partials() const { return rows_; }
  int width() const { return width_; }
  // A restart: the totals of the archive go to the row of level patch 0 when
  // this process holds it, zeros elsewhere; the ordered sum then gives the
  // totals exactly (adding zeros is exact) on any rank count.
  void restore_totals(const std::vector<double>& totals) {
    zero();
    for (PatchPartial& r : rows_)
      if (r.patch_id == 0)
        for (std::size_t k = 0; k < r.values.size() && k < totals.size(); ++k) r.values[k] = totals[k];
  }

 private:
  int width_ = 0;
  std::vector<PatchPartial> rows_;
};

}  // namespace tephra
