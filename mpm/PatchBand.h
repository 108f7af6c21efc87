#pragma once
// Node sums in ascending patch order (issue 7; docs/parallel.md "MPM on
// ranks"): the same bits in one process and on any number of MPI ranks.
//
// Every scatter (P2G, internal force, the MUSL velocity) forms, at every
// node n,
//     x_n = ( ... ((0 + X_{P1,n}) + X_{P2,n}) + ... ),   P1 < P2 < ... patch ids,
//     X_{P,n} = sum over the particles of patch P, in the scatter order
//               (colour, block, particle id; mpm/shape/ScatterOrder.h),
// the patch of a particle being MpmComponent::patch_of (the patch of the
// interior cell nearest to it). On ranks every patch's particles live on
// one rank, in that same order, so each X_{P,n} has the one-process bits, and
// the ordered sum over P has them too.
//
// Only the *band* needs partials: a node is in the band when the node reach
// boxes of two or more patches hold it. Patch P's reach box is the node range
// [c_lo - R, c_hi + R] of its cells (with the extra cells where it touches
// the domain boundary), R the stencil reach in nodes beyond a particle's cell
// (from the widest footprint of this step's stencils, plus one node for the
// cell of a position on a cell face). Any other node is reached by one patch
// only: its particles add straight into the node arrays (X_{P,n} = x_n, the
// sum as before this class existed). A particle whose cell's reach cube
// [c - R, c + 1 + R] holds no band node (an *interior* particle) writes
// directly; the others (band particles) look each node up: a band node's
// term goes to the partial of (node, patch), any other node directly.
//
// After a scatter, reduce() adds the partials of every band node in
// ascending patch id (on ranks: after gathering the partials of all ranks'
// patches, one MPI_Allgatherv of the band pairs that hold a non-zero value,
// as (pair index, values) records) and hands the sum to
// the caller, who writes it into its node arrays (whose band entries no
// particle wrote); the partials are zeroed for the next scatter.
//
// Memory: an int per node and per cell (built once, and again only when the
// reach grows), the band pairs x 20 doubles. No allocation per step.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/base/Types.h"
#include "core/grid/Grid.h"

namespace tephra {

struct NodeGrid;

class PatchBand {
 public:
  // The most doubles one pair holds (P2G with sigma_g and f_int: m, V, m v, f_ext, f_int, V sigma).
  static constexpr int kMaxWidth = 20;

  // (Re)builds the band for `level`'s patches on the node grid g with reach
  // R nodes when R exceeds the built reach or the grid changed; otherwise
  // keeps the band (a wider band is as exact). Inactive with one patch.
  void prepare(const Grid& level, const NodeGrid& g, int reach);
  bool active() const { return active_; }
  int reach() const { return reach_; }
  std::size_t band_nodes() const { return band_node_.size(); }
  std::size_t pairs() const { return pair_patch_.size(); }

  // -1: the particle at x is interior (writes directly); else its patch id.
  [[gnu::always_inline]] int tag(const Vec3& x) const {
    std::size_t c = 0, stride = 1;
    for (int d = 0; d < 3; ++d) {
      int i = int(std::floor((x[d] - lower_[d]) / dx_[d])) + off_[d];  // MpmComponent::patch_of's cell
      i = i < 0 ? 0 : i >= cells_[d] ? cells_[d] - 1 : i;
      c += stride * std::size_t(i);
      stride *= std::size_t(cells_[d]);
    }
    return cell_tag_[c];
  }
  // The node-box test of the per-axis stencils: boxes(n) prepares, for
  // every node b, whether the box of n x n x n nodes from b (b the lowest
  // node of a per-axis stencil, AxisStencils.h) holds no band node. Such a
  // particle writes every one of its nodes directly in the band variant of
  // a scatter too (slot() < 0 at each), with the same expressions as
  // without the band: it may skip tag() (3 divisions and floors) and take
  // the plain path, the same bits. Call outside parallel regions, before
  // the scatter; n = 0 (flat stencils) builds nothing.
  void boxes(int n);
  // boxes(n)'s answer for lowest node b: true when the box holds no band node.
  bool box_clear(std::size_t b) const { return clear_[b] != 0; }

  // Band node index of node gi, or -1.
  int slot(std::size_t gi) const { return node_slot_[gi]; }
  // The partial (width doubles) of band node k for patch P (P's reach box holds the node).
  // Marks the buffer written (any thread; relaxed: reduce() runs after the
  // scatter's parallel region has ended, whose barrier orders the stores).
  double* partial(int k, int P) {
    __atomic_store_n(&written_, true, __ATOMIC_RELAXED);
    std::uint32_t j = pair_first_[std::size_t(k)];
    while (pair_patch_[j] != P) ++j;
    return buffer_.data() + std::size_t(j) * kMaxWidth;
  }

  // On ranks: owner[P] the rank of patch P, `me` this rank, and the gather
  // (all_gather of core/parallel/Ranks.h). Unset: one process.
  void set_ranks(std::vector<int> owner, int me, std::function<std::vector<double>(const std::vector<double>&)> gather);

  // sum(gi, s): s the ordered sum (width doubles) at band node gi; the partials are zeroed.
  // sum is called from several threads at once (one band node each): it must
  // touch the data of node gi only (or of what gi alone maps to, e.g. its cell).
  void reduce(int width, const std::function<void(std::size_t gi, const double* s)>& sum);

  // On ranks: the (pair, values) records this rank sent in the last reduce
  // (its pairs with a non-zero value; 0 in one process).
  std::size_t sent_records() const { return sent_records_; }

  // Flat node indices of the band (ascending).
  const std::vector<std::size_t>& band_node_index() const { return band_node_; }

 private:
  bool active_ = false;
  int reach_ = -1;
  Vec3 lower_ = Vec3::Zero(), dx_ = Vec3::Ones();
  IntVec3 off_ = IntVec3::Zero(), cells_ = IntVec3::Ones(), nodes_ = IntVec3::Zero();
  std::size_t patches_ = 0;
  std::vector<int> cell_tag_;               // per node-grid cell
  std::vector<int> node_slot_;              // per node
  std::vector<std::uint8_t> clear_;         // per node: boxes(clear_n_)'s answer
  int clear_n_ = 0;                         // box size clear_ was built for (0: none / stale)
  std::vector<std::size_t> band_node_;      // band node k -> flat node index
  std::vector<std::uint32_t> pair_first_;   // band node k's pairs: [pair_first_[k], pair_first_[k+1])
  std::vector<int> pair_patch_;             // ascending patch id within a node
  std::vector<double> buffer_;              // pairs x kMaxWidth partials
  bool written_ = false;                    // partial() called since the buffer was last all +0
  std::vector<int> owner_;
  int me_ = 0;
  std::function<std::vector<double>(const std::vector<double>&)> gather_;
  std::vector<double> send_;                // scratch of reduce on ranks
  std::size_t sent_records_ = 0;
};

}  // namespace tephra
