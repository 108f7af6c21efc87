#include "mpm/RankNodeSums.h"

#include <stdexcept>

#include "core/io/ArrayBoxes.h"
#include "core/parallel/OutputGather.h"
#include "core/parallel/Ranks.h"

namespace tephra {

void RankNodeSums::set_boxes(const NodeBox& mine, const IntVec3& nodes) {
  const Ranks r = world_ranks();
  rank_ = r.rank;
  n_ = nodes;
  std::vector<double> local;
  for (int d = 0; d < 3; ++d) local.push_back(mine.lo[d]);
  for (int d = 0; d < 3; ++d) local.push_back(mine.hi[d]);
  const std::vector<double> all = all_gather(local);
  if (all.size() != 6 * std::size_t(r.size)) throw std::logic_error("RankNodeSums: box gather size");
  boxes_.assign(std::size_t(r.size), NodeBox{});
  for (int s = 0; s < r.size; ++s)
    for (int d = 0; d < 3; ++d) {
      boxes_[std::size_t(s)].lo[d] = int(all[6 * std::size_t(s) + std::size_t(d)]);
      boxes_[std::size_t(s)].hi[d] = int(all[6 * std::size_t(s) + 3 + std::size_t(d)]);
    }
}

void RankNodeSums::combine(const std::vector<NodeArray>& arrays) const {
  const int ranks = size();
  if (ranks <= 1) return;
  const NodeBox& mine = boxes_[std::size_t(rank_)];
  // The record of one node: every array's values, in the order of `arrays`.
  std::vector<int> at(arrays.size());
  int width = 0;
  for (std::size_t a = 0; a < arrays.size(); ++a) at[a] = width, width += arrays[a].width;
  const std::size_t w = std::size_t(width);
  // My values on each overlap with another rank's box, i fastest.
  std::vector<std::vector<double>> send(static_cast<std::size_t>(ranks));
  std::vector<NodeBox> overlap(static_cast<std::size_t>(ranks));
  for (int s = 0; s < ranks; ++s) {
    if (s == rank_) continue;
    const NodeBox o = mine.intersect(boxes_[std::size_t(s)]);
    overlap[std::size_t(s)] = o;
    if (o.empty()) continue;
    std::vector<double>& b = send[std::size_t(s)];
    b.reserve(o.count() * w);
    for (int k = o.lo[2]; k < o.hi[2]; ++k)
      for (int j = o.lo[1]; j < o.hi[1]; ++j)
        for (int i = o.lo[0]; i < o.hi[0]; ++i) {
          const std::size_t gi = node_index(i, j, k);
          for (const NodeArray& a : arrays)
            for (int c = 0; c < a.width; ++c) b.push_back(a.data[gi * std::size_t(a.width) + std::size_t(c)]);
        }
  }
  const std::vector<std::vector<double>> recv = exchange_blocks(send);
  for (int s = 0; s < ranks; ++s)
    if (s != rank_ && recv[std::size_t(s)].size() != overlap[std::size_t(s)].count() * w)
      throw std::logic_error("RankNodeSums: rank " + std::to_string(s) + " sent an overlap of another size");
  // Each node of each overlap from the buffers only (never from `data`, which
  // is overwritten), so a node in several overlaps gets the same value each time.
  std::vector<const double*> from;
  from.reserve(std::size_t(ranks));
  for (int s = 0; s < ranks; ++s) {
    const NodeBox& o = overlap[std::size_t(s)];
    if (s == rank_ || o.empty()) continue;
    for (int k = o.lo[2]; k < o.hi[2]; ++k)
      for (int j = o.lo[1]; j < o.hi[1]; ++j)
        for (int i = o.lo[0]; i < o.hi[0]; ++i) {
          from.clear();  // contributions in ascending rank order
          for (int t = 0; t < ranks; ++t) {
            if (t == rank_) from.push_back(send[std::size_t(s)].data() + o.offset(i, j, k) * w);
            else if (boxes_[std::size_t(t)].contains(i, j, k))
              from.push_back(recv[std::size_t(t)].data() + overlap[std::size_t(t)].offset(i, j, k) * w);
          }
          const std::size_t gi = node_index(i, j, k);
          for (std::size_t a = 0; a < arrays.size(); ++a) {
            const NodeArray& arr = arrays[a];
            double* out = arr.data + gi * std::size_t(arr.width);
            if (arr.weight < 0) {
              for (int c = 0; c < arr.width; ++c) {
                double sum = 0.0;
                for (const double* f : from) sum += f[at[a] + c];
                out[c] = sum;
              }
              continue;
            }
            // Weighted mean: sum w_r x_r / sum w_r, or the single contributor's x_r.
            const int wa = at[std::size_t(arr.weight)];
            int contributors = 0;
            const double* single = nullptr;
            double total = 0.0;
            for (const double* f : from) {
              total += f[wa];
              if (f[wa] > 0.0) ++contributors, single = f;
            }
            for (int c = 0; c < arr.width; ++c) {
              if (contributors == 1) {
                out[c] = single[at[a] + c];
              } else if (total > 0.0) {
                double sum = 0.0;
                for (const double* f : from) sum += f[wa] * f[at[a] + c];
                out[c] = sum / total;
              } else {
                out[c] = 0.0;
              }
            }
          }
        }
  }
}

std::vector<double> RankNodeSums::whole(const double* data, int width) const {
  const std::size_t w = std::size_t(width);
  std::vector<double> out(std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]) * w, 0.0);
  const int ranks = size();
  if (ranks <= 1) {
    std::copy(data, data + out.size(), out.begin());
    return out;
  }
  const NodeBox& mine = boxes_[std::size_t(rank_)];
  if (output_per_rank()) {
    for (int k = mine.lo[2]; k < mine.hi[2]; ++k)
      for (int j = mine.lo[1]; j < mine.hi[1]; ++j)
        for (int i = mine.lo[0]; i < mine.hi[0]; ++i)
          for (std::size_t c = 0; c < w; ++c) out[node_index(i, j, k) * w + c] = data[node_index(i, j, k) * w + c];
    return out;
  }
  std::vector<double> local;
  local.reserve(mine.count() * w);
  for (int k = mine.lo[2]; k < mine.hi[2]; ++k)
    for (int j = mine.lo[1]; j < mine.hi[1]; ++j)
      for (int i = mine.lo[0]; i < mine.hi[0]; ++i)
        for (std::size_t c = 0; c < w; ++c) local.push_back(data[node_index(i, j, k) * w + c]);
  // gather_output: to every rank, or to rank 0 alone inside an
  // OutputToRoot scope (the other ranks then return an empty array).
  const std::vector<double> all = gather_output(local);
  if (!output_gather_lands_here()) return {};
  std::vector<std::size_t> start(std::size_t(ranks) + 1, 0);
  for (int s = 0; s < ranks; ++s) start[std::size_t(s) + 1] = start[std::size_t(s)] + boxes_[std::size_t(s)].count() * w;
  if (all.size() != start.back()) throw std::logic_error("RankNodeSums::whole: gathered size");
  for (int s = ranks - 1; s >= 0; --s) {  // the lowest rank written last
    const NodeBox& b = boxes_[std::size_t(s)];
    std::size_t pos = start[std::size_t(s)];
    for (int k = b.lo[2]; k < b.hi[2]; ++k)
      for (int j = b.lo[1]; j < b.hi[1]; ++j)
        for (int i = b.lo[0]; i < b.hi[0]; ++i)
          for (std::size_t c = 0; c < w; ++c) out[node_index(i, j, k) * w + c] = all[pos++];
  }
  return out;
}

std::vector<ArrayBox> RankNodeSums::output_pieces() const {
  std::vector<ArrayBox> boxes;
  for (const NodeBox& b : boxes_) boxes.push_back({b.lo, b.hi});
  if (boxes.empty()) return {ArrayBox{IntVec3::Zero(), n_}};  // no boxes set: one process, every node
  return kept_when_earlier_wins(boxes, std::size_t(rank_));
}

}  // namespace tephra
