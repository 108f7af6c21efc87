#include "core/parallel/LoadBalancer.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>

namespace tephra {
namespace {

// Interleaves the bits of three 21-bit non-negative integers (x lowest).
std::uint64_t morton3(std::uint64_t x, std::uint64_t y, std::uint64_t z) {
  std::uint64_t code = 0;
  for (int b = 0; b < 21; ++b) {
    code |= ((x >> b) & 1u) << (3 * b);
    code |= ((y >> b) & 1u) << (3 * b + 1);
    code |= ((z >> b) & 1u) << (3 * b + 2);
  }
  return code;
}

// Greedy fill at capacity `cap`: the number of runs needed, each run as long
// as it fits (a single weight above cap still forms its own run).
int runs_needed(const std::vector<double>& w, const std::vector<int>& order, double cap) {
  int runs = 1;
  double sum = 0.0;
  for (int p : order) {
    if (sum > 0.0 && sum + w[p] > cap) {
      ++runs;
      sum = 0.0;
    }
    sum += w[p];
  }
  return runs;
}

}  // namespace

double RankAssignment::imbalance() const {
  if (rank_cost.empty()) return 1.0;
  const double total = std::accumulate(rank_cost.begin(), rank_cost.end(), 0.0);
  if (total <= 0.0) return 1.0;
  return *std::max_element(rank_cost.begin(), rank_cost.end()) / (total / rank_cost.size());
}

std::vector<int> morton_patch_order(const Grid& grid) {
  std::vector<int> order(grid.patches.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::uint64_t> code(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const IntVec3& lo = grid.patches[i].lo;
    code[i] = morton3(std::uint64_t(lo[0]), std::uint64_t(lo[1]), std::uint64_t(lo[2]));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return code[a] < code[b]; });
  return order;
}

std::vector<int> partition_contiguous(const std::vector<double>& w, const std::vector<int>& order, int ranks) {
  if (ranks < 1) throw std::invalid_argument("partition_contiguous: ranks must be >= 1");
  std::vector<int> owner(w.size(), 0);
  if (order.empty()) return owner;
  double lo = *std::max_element(w.begin(), w.end());
  double hi = std::accumulate(w.begin(), w.end(), 0.0);
  // runs_needed is non-increasing in the capacity; find the smallest feasible.
  for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (runs_needed(w, order, mid) <= ranks) hi = mid;
    else lo = mid;
  }
  const int n = static_cast<int>(order.size());
  int rank = 0, in_run = 0;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const int p = order[k];
    // Start a new run when the capacity is exceeded, or when the patches left
    // are only just enough to give every remaining rank one patch.
    const bool full = in_run > 0 && sum + w[p] > hi;
    const bool must_split = in_run > 0 && (n - k) <= (ranks - 1 - rank);
    if ((full || must_split) && rank < ranks - 1) {
      ++rank;
      sum = 0.0;
      in_run = 0;
    }
    owner[p] = rank;
    sum += w[p];
    ++in_run;
  }
  return owner;
}

RankAssignment assign_patches(const Grid& grid, const std::vector<long long>& particles_per_patch, int ranks,
                              const LoadWeights& weights) {
  const std::size_t np = grid.patches.size();
  if (!particles_per_patch.empty() && particles_per_patch.size() != np)
    throw std::invalid_argument("assign_patches: one particle count per patch expected");
  std::vector<double> cost(np);
  for (std::size_t i = 0; i < np; ++i) {
    const IntVec3 n = grid.patches[i].num_cells();
    cost[i] = weights.cost_per_cell * double(n[0]) * n[1] * n[2] +
              (particles_per_patch.empty() ? 0.0 : weights.cost_per_particle * particles_per_patch[i]);
  }
  RankAssignment a;
  a.owner = partition_contiguous(cost, morton_patch_order(grid), ranks);
  a.rank_cost.assign(ranks, 0.0);
  for (std::size_t i = 0; i < np; ++i) a.rank_cost[a.owner[i]] += cost[i];
  return a;
}

}  // namespace tephra
