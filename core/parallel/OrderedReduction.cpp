#include "core/parallel/OrderedReduction.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/parallel/Ranks.h"

namespace tephra {
namespace {

// Every rank's partials as rows (patch id, values...), sorted by patch id.
std::vector<PatchPartial> gather_sorted(const std::vector<PatchPartial>& local, int width) {
  std::vector<double> packed;
  packed.reserve(local.size() * (width + 1));
  for (const PatchPartial& p : local) {
    if (static_cast<int>(p.values.size()) != width)
      throw std::invalid_argument("ordered_patch_sum: patch " + std::to_string(p.patch_id) + " has " +
                                  std::to_string(p.values.size()) + " values, expected " +
                                  std::to_string(width));
    packed.push_back(static_cast<double>(p.patch_id));  // exact: ids < 2^53
    packed.insert(packed.end(), p.values.begin(), p.values.end());
  }
  const std::vector<double> all = all_gather(packed);
  std::vector<PatchPartial> rows(all.size() / (width + 1));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double* row = all.data() + r * (width + 1);
    rows[r].patch_id = static_cast<int>(row[0]);
    rows[r].values.assign(row + 1, row + 1 + width);
  }
  std::sort(rows.begin(), rows.end(),
            [](const PatchPartial& a, const PatchPartial& b) { return a.patch_id < b.patch_id; });
  for (std::size_t r = 1; r < rows.size(); ++r)
    if (rows[r].patch_id == rows[r - 1].patch_id)
      throw std::invalid_argument("ordered_patch_sum: patch " + std::to_string(rows[r].patch_id) +
                                  " reduced by two ranks");
  return rows;
}

template <class Combine>
std::vector<double> fold(const std::vector<PatchPartial>& local, int width, double start, Combine f) {
  std::vector<double> out(width, start);
  for (const PatchPartial& p : gather_sorted(local, width))
    for (int k = 0; k < width; ++k) out[k] = f(out[k], p.values[k]);
  return out;
}

}  // namespace

std::vector<double> ordered_patch_sum(const std::vector<PatchPartial>& local, int width) {
  return fold(local, width, 0.0, [](double a, double b) { return a + b; });
}

std::vector<double> patch_max(const std::vector<PatchPartial>& local, int width) {
  return fold(local, width, -std::numeric_limits<double>::infinity(),
              [](double a, double b) { return std::max(a, b); });
}

std::vector<double> patch_min(const std::vector<PatchPartial>& local, int width) {
  return fold(local, width, std::numeric_limits<double>::infinity(),
              [](double a, double b) { return std::min(a, b); });
}

}  // namespace tephra
