#include "core/parallel/PatchLayout.h"

#include <algorithm>
#include <stdexcept>

#include "core/parallel/LoadBalancer.h"
#include "core/parallel/Ranks.h"

namespace tephra {

PatchLayout PatchLayout::whole(const Grid& level) {
  PatchLayout l;
  l.level = level;
  l.owner.assign(level.patches.size(), 0);
  for (std::size_t p = 0; p < level.patches.size(); ++p) l.own.push_back(static_cast<int>(p));
  return l;
}

PatchLayout PatchLayout::over_world_ranks(const Grid& level, const std::vector<long long>& particles_per_patch) {
  const Ranks r = world_ranks();
  PatchLayout l = whole(level);
  if (r.size == 1) return l;
  l.distributed = true;
  l.owner = assign_patches(level, particles_per_patch, r.size).owner;
  l.own.clear();
  for (std::size_t p = 0; p < l.owner.size(); ++p)
    if (l.owner[p] == r.rank) l.own.push_back(static_cast<int>(p));
  return l;
}

Grid PatchLayout::own_grid() const {
  Grid g = level;
  g.patches.clear();
  for (int p : own) {
    if (level.patches[static_cast<std::size_t>(p)].id != p)
      throw std::logic_error("PatchLayout: patch ids must be the level indices");
    g.patches.push_back(level.patches[static_cast<std::size_t>(p)]);
  }
  return g;
}

double PatchLayout::min(double v) const { return distributed ? all_min(v) : v; }
double PatchLayout::max(double v) const { return distributed ? all_max(v) : v; }
bool PatchLayout::any(bool flag) const { return distributed ? any_rank(flag) : flag; }

std::vector<double> PatchLayout::ordered_sum(const std::vector<PatchPartial>& local, int width) const {
  if (distributed) return ordered_patch_sum(local, width);
  std::vector<const PatchPartial*> sorted;
  for (const PatchPartial& p : local) {
    if (static_cast<int>(p.values.size()) != width)
      throw std::invalid_argument("PatchLayout::ordered_sum: a partial of the wrong width");
    sorted.push_back(&p);
  }
  std::sort(sorted.begin(), sorted.end(), [](const PatchPartial* a, const PatchPartial* b) { return a->patch_id < b->patch_id; });
  std::vector<double> out(static_cast<std::size_t>(width), 0.0);
  for (const PatchPartial* p : sorted)
    for (int k = 0; k < width; ++k) out[static_cast<std::size_t>(k)] += p->values[static_cast<std::size_t>(k)];
  return out;
}

std::vector<std::vector<double>> PatchLayout::gather_blocks(const std::vector<std::vector<double>>& own_blocks) const {
  if (distributed) return gather_patch_blocks(owner, own, own_blocks);
  if (own_blocks.size() != own.size()) throw std::invalid_argument("PatchLayout::gather_blocks: one block per own patch");
  std::vector<std::vector<double>> all(level.patches.size());
  for (std::size_t n = 0; n < own.size(); ++n) all[static_cast<std::size_t>(own[n])] = own_blocks[n];
  return all;
}

}  // namespace tephra
