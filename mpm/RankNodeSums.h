#pragma once
// MPM node sums over MPI ranks (issue 7; docs/parallel.md "MPM on ranks").
//
// Every rank keeps full-size node arrays (mpm/NodeGrid.h: memory O(grid) per
// rank) but scatters only the particles it owns. Its *box* is the node range
// its particles' stencils can reach this step. A node in one box only holds
// its final sum already; a node in several boxes (near a patch cut) gets the
// contributions of every rank whose box holds it, added in ascending rank
// order from 0, on each of those ranks: the same bits on all of them.
//
// Two kinds of node arrays:
//   sums            (m_g, V_g, f_ext, f_int, mass gradient, ...):
//                   x_g = sum_r x_g,r;
//   weighted means  (v_g = sum m v S / m_g, sigma_g = sum V sigma S / V_g):
//                   each rank holds its own mean x_r = P_r / w_r, so
//                   x_g = sum_r w_r x_r / sum_r w_r; where a single rank has
//                   w_r > 0 its x_r is taken unchanged (exactly the one-rank
//                   value when that rank scattered the same particles in the
//                   same order).
// Against one process the sums at nodes shared by boxes are added in another
// order (per rank, then over ranks), so they agree to round-off, not bits --
// except for P2G, the internal force and the MUSL velocity, which are first
// summed per patch in patch order (mpm/PatchBand.h) and kept on one rank per
// node (MpmComponent::keep_band_on_one_rank): the combine then moves those
// bits unchanged.
#include <cstddef>
#include <vector>

#include "core/base/Types.h"
#include "core/io/OutputFrame.h"
#include "mpm/NodeBox.h"

namespace tephra {

// One node array (NodeGrid index order, `width` doubles per node) to combine.
// weight < 0: a sum; otherwise a weighted mean whose weights are the array
// at position `weight` of the same combine() call (its values before the call).
struct NodeArray {
  double* data = nullptr;
  int width = 1;
  int weight = -1;
};

class RankNodeSums {
 public:
  // Sets this rank's box and gathers every rank's (a collective). `nodes`:
  // nodes per direction of the grids combined (NodeGrid::n).
  void set_boxes(const NodeBox& mine, const IntVec3& nodes);
  int rank() const { return rank_; }
  int size() const { return int(boxes_.size()); }
  const NodeBox& box(int r) const { return boxes_[std::size_t(r)]; }

  // Combines the arrays over the ranks (a collective): afterwards every node
  // of this rank's box holds the global sum / mean defined above.
  void combine(const std::vector<NodeArray>& arrays) const;

  // A whole-grid copy of `data` (width doubles per node) on every rank: each
  // node from the lowest rank whose box holds it, 0 where no box does (a
  // collective; for output and the boundary-force sums). Inside an
  // OutputToRoot scope (core/parallel/OutputGather.h) rank 0 alone receives:
  // the other ranks get an empty vector.
  // Inside an OutputPerRank scope (per-rank output, session 25) no message:
  // this rank's box copied from `data`, 0 elsewhere; it writes the nodes of
  // output_pieces() only.
  std::vector<double> whole(const double* data, int width) const;

  // The nodes whole() takes from this rank: its box minus the boxes of the
  // lower ranks (node offsets, NodeGrid order), as disjoint boxes.
  std::vector<ArrayBox> output_pieces() const;

 private:
  int rank_ = 0;
  IntVec3 n_ = IntVec3::Ones();
  std::vector<NodeBox> boxes_;
  std::size_t node_index(int i, int j, int k) const {
    return std::size_t(i) + std::size_t(n_[0]) * (std::size_t(j) + std::size_t(n_[1]) * std::size_t(k));
  }
};

}  // namespace tephra
