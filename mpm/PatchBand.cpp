#include "mpm/PatchBand.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/NodeGrid.h"

namespace tephra {

void PatchBand::prepare(const Grid& level, const NodeGrid& g, int reach) {
  if (level.patches.size() < 2) {
    active_ = false;
    return;
  }
  IntVec3 off;
  for (int d = 0; d < 3; ++d) off[d] = int(std::lround((level.lower[d] - g.origin[d]) / g.h[d]));
  const bool same = active_ && reach <= reach_ && nodes_ == g.n && off_ == off && patches_ == level.patches.size() &&
                    lower_ == level.lower && dx_ == level.dx;
  if (same) return;
  active_ = true;
  clear_n_ = 0;  // the box answers belong to the previous band
  reach_ = std::max(reach, reach_);
  const int R = reach_;
  lower_ = level.lower, dx_ = level.dx, off_ = off, nodes_ = g.n;
  patches_ = level.patches.size();
  for (int d = 0; d < 3; ++d) cells_[d] = std::max(g.n[d] - 1, 1);
  // Reach boxes (inclusive node ranges) of the patches' node-grid cells, the
  // extra cells included where a patch touches the domain boundary.
  const std::size_t np = patches_;
  std::vector<IntVec3> blo(np), bhi(np);
  for (std::size_t P = 0; P < np; ++P) {
    const Patch& q = level.patches[P];
    for (int d = 0; d < 3; ++d) {
      const int clo = q.lo[d] == 0 ? 0 : q.lo[d] + off[d];
      const int chi = q.hi[d] == level.cells[d] ? cells_[d] : q.hi[d] + off[d];  // one past the last cell
      blo[P][d] = std::max(clo - R, 0);
      bhi[P][d] = std::min(chi + R, g.n[d] - 1);
    }
  }
  const std::size_t nn = g.count();
  std::vector<std::uint8_t> count(nn, 0);
  for (std::size_t P = 0; P < np; ++P)
    for (int k = blo[P][2]; k <= bhi[P][2]; ++k)
      for (int j = blo[P][1]; j <= bhi[P][1]; ++j)
        for (int i = blo[P][0]; i <= bhi[P][0]; ++i) {
          std::uint8_t& c = count[g.index(i, j, k)];
          if (c < 2) ++c;
        }
  node_slot_.assign(nn, -1);
  band_node_.clear();
  pair_first_.clear();
  pair_patch_.clear();
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const std::size_t gi = g.index(i, j, k);
        if (count[gi] < 2) continue;
        node_slot_[gi] = int(band_node_.size());
        band_node_.push_back(gi);
        pair_first_.push_back(std::uint32_t(pair_patch_.size()));
        for (std::size_t P = 0; P < np; ++P)
          if (i >= blo[P][0] && i <= bhi[P][0] && j >= blo[P][1] && j <= bhi[P][1] && k >= blo[P][2] &&
              k <= bhi[P][2])
            pair_patch_.push_back(int(P));
      }
  pair_first_.push_back(std::uint32_t(pair_patch_.size()));
  buffer_.assign(pair_patch_.size() * std::size_t(kMaxWidth), 0.0);
  written_ = false;
  // Cell tags: the reach cube [c - R, c + 1 + R] of cell c holds a band node?
  // A summed-volume table of the band flags answers each cell in O(1).
  const std::size_t sx = std::size_t(g.n[0]) + 1, sy = std::size_t(g.n[1]) + 1;
  std::vector<int> S(sx * sy * (std::size_t(g.n[2]) + 1), 0);
  auto at = [&](int i, int j, int k) -> int& { return S[std::size_t(i) + sx * (std::size_t(j) + sy * std::size_t(k))]; };
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i)
        at(i + 1, j + 1, k + 1) = (node_slot_[g.index(i, j, k)] >= 0) + at(i, j + 1, k + 1) + at(i + 1, j, k + 1) +
                                  at(i + 1, j + 1, k) - at(i, j, k + 1) - at(i, j + 1, k) - at(i + 1, j, k) +
                                  at(i, j, k);
  // Band flags in the node box [a, b] (inclusive).
  auto any = [&](const IntVec3& a, const IntVec3& b) {
    const int x0 = a[0], y0 = a[1], z0 = a[2], x1 = b[0] + 1, y1 = b[1] + 1, z1 = b[2] + 1;
    return at(x1, y1, z1) - at(x0, y1, z1) - at(x1, y0, z1) - at(x1, y1, z0) + at(x0, y0, z1) + at(x0, y1, z0) +
               at(x1, y0, z0) - at(x0, y0, z0) >
           0;
  };
  cell_tag_.assign(std::size_t(cells_[0]) * cells_[1] * cells_[2], -1);
  for (int k = 0; k < cells_[2]; ++k)
    for (int j = 0; j < cells_[1]; ++j)
      for (int i = 0; i < cells_[0]; ++i) {
        const IntVec3 c(i, j, k);
        IntVec3 a, b, lc;
        for (int d = 0; d < 3; ++d) {
          a[d] = std::max(c[d] - R, 0);
          b[d] = std::min(c[d] + 1 + R, g.n[d] - 1);
          lc[d] = std::clamp(c[d] - off[d], 0, level.cells[d] - 1);  // patch_of's clamped cell
        }
        if (!any(a, b)) continue;
        const int P = level.patch_owning_cell(lc);
        if (P < 0) throw std::logic_error("PatchBand: no patch owns an interior cell");
        cell_tag_[std::size_t(i) + std::size_t(cells_[0]) * (std::size_t(j) + std::size_t(cells_[1]) * k)] = P;
      }
}

// clear_[b] = no band node in [b, b + n - 1] per axis (clipped to the grid):
// the band flags OR-ed over a forward window of n nodes, one axis at a time
// (a separable box filter; O(nodes x n)).
void PatchBand::boxes(int n) {
  if (!active_ || n <= 0 || n == clear_n_) return;
  const std::size_t nn = node_slot_.size();
  std::vector<std::uint8_t> hit(nn), tmp(nn);
  for (std::size_t gi = 0; gi < nn; ++gi) hit[gi] = node_slot_[gi] >= 0;
  const std::size_t stride[3] = {1, std::size_t(nodes_[0]), std::size_t(nodes_[0]) * std::size_t(nodes_[1])};
  for (int d = 0; d < 3; ++d) {
    for (int k = 0; k < nodes_[2]; ++k)
      for (int j = 0; j < nodes_[1]; ++j)
        for (int i = 0; i < nodes_[0]; ++i) {
          const int at[3] = {i, j, k};
          const std::size_t gi = std::size_t(i) + stride[1] * std::size_t(j) + stride[2] * std::size_t(k);
          std::uint8_t any = 0;
          for (int t = 0; t < n && at[d] + t < nodes_[d]; ++t) any |= hit[gi + std::size_t(t) * stride[d]];
          tmp[gi] = any;
        }
    hit.swap(tmp);
  }
  clear_.resize(nn);
  for (std::size_t gi = 0; gi < nn; ++gi) clear_[gi] = !hit[gi];
  clear_n_ = n;
}

void PatchBand::set_ranks(std::vector<int> owner, int me,
                          std::function<std::vector<double>(const std::vector<double>&)> gather) {
  owner_ = std::move(owner);
  me_ = me;
  gather_ = std::move(gather);
}

void PatchBand::reduce(int width, const std::function<void(std::size_t gi, const double* s)>& sum) {
  if (!active_) return;
  const std::size_t W = std::size_t(kMaxWidth), w = std::size_t(width);
  if (gather_) {
    // This rank's pairs (its patches') that hold a non-zero value, each as
    // (pair index, width values), after their count; every rank's records,
    // in rank order, written into the pairs. A pair left out is all zeros
    // (+0 or -0) and its slot on the receiver holds +0 already (zeroed by the
    // last reduce; no rank writes another rank's pairs): the ordered sum
    // below starts at +0 and never is -0 (x + -x = +0 when rounding to
    // nearest), and s + (+-0) = s for every s != -0, so leaving a zero pair
    // out gives the same bits. Only the pairs a rank's particles reached
    // travel (before: every pair of the rank, ~9,245 band nodes x 14 doubles
    // per reduce on spheres.ups, whether or not a particle was near the cut).
    send_.assign(1, 0.0);
    std::size_t records = 0;
    for (std::size_t j = 0; j < pair_patch_.size(); ++j) {
      if (owner_[std::size_t(pair_patch_[j])] != me_) continue;
      const double* q = &buffer_[j * W];
      bool any = false;
      for (std::size_t c = 0; c < w; ++c) any = any || q[c] != 0.0;
      if (!any) continue;
      send_.push_back(double(j));  // exact: pair indices < 2^53
      send_.insert(send_.end(), q, q + w);
      ++records;
    }
    send_[0] = double(records);
    sent_records_ = records;
    const std::vector<double> all = gather_(send_);
    std::size_t at = 0;
    // One chunk per rank (a rank without patches or reached pairs sends its count 0).
    while (at < all.size()) {
      const std::size_t n = std::size_t(all[at++]);
      for (std::size_t k = 0; k < n; ++k) {
        if (at + 1 + w > all.size()) throw std::logic_error("PatchBand: a band record past the gathered data");
        const std::size_t j = std::size_t(all[at++]);
        if (j >= pair_patch_.size()) throw std::logic_error("PatchBand: a band record of an unknown pair");
        std::copy(all.begin() + long(at), all.begin() + long(at + w), &buffer_[j * W]);
        at += w;
      }
    }
  }
  // The band nodes are independent (node k sums its own pairs' partials, and
  // sum() touches node gi's data only: PatchBand.h), so they are shared
  // among the threads: the same calls with the same values for any thread
  // count. (Serial, this was ~0.1 % of a two-thread spheres step left on
  // the main thread: ~9,000 band nodes per reduce, three reduces per step.)
  const long nodes = long(band_node_.size());
  // One process, no partial() since the buffer was all +0 (prepare, or the
  // zeroing below): every ordered sum is +0 + +0 + ... = +0, so sum() gets
  // +0s without reading the buffer (the same calls, the same bits).
  if (!gather_ && !written_) {
    double z[kMaxWidth];
    for (std::size_t c = 0; c < w; ++c) z[c] = 0.0;
#pragma omp parallel for schedule(static) if (nodes >= 4096)
    for (long k = 0; k < nodes; ++k) sum(band_node_[std::size_t(k)], z);
    return;
  }
  written_ = false;  // zeroed below
#pragma omp parallel for schedule(static) if (nodes >= 4096)
  for (long k = 0; k < nodes; ++k) {
    double s[kMaxWidth];
    for (std::size_t c = 0; c < w; ++c) s[c] = 0.0;
    for (std::uint32_t j = pair_first_[std::size_t(k)]; j < pair_first_[std::size_t(k) + 1]; ++j) {  // ascending patch id
      double* q = &buffer_[std::size_t(j) * W];
      for (std::size_t c = 0; c < w; ++c) s[c] += q[c], q[c] = 0.0;
    }
    sum(band_node_[std::size_t(k)], s);
  }
}

}  // namespace tephra
