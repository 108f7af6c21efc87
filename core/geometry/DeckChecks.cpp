#include "core/geometry/DeckChecks.h"

#include <algorithm>

#include "core/deck/DeckNode.h"

namespace tephra::geometry_detail {

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

}  // namespace

std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    size_t d = edit_distance(name, c);
    if (d < best_d) best_d = d, best = c;
  }
  // Only suggest a name that is plausibly a misspelling.
  return best_d <= std::max<size_t>(2, name.size() / 3) ? best : "";
}

void require_known_children(const DeckNode& node, std::initializer_list<const char*> allowed) {
  std::vector<std::string> names(allowed.begin(), allowed.end());
  for (const auto& c : node.children) {
    if (std::find(names.begin(), names.end(), c.name) != names.end()) continue;
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    std::string msg = "unknown element <" + c.name + "> in <" + node.name + ">; expected: " + list;
    const std::string near = nearest_name(c.name, names);
    if (!near.empty()) msg += " (did you mean <" + near + ">?)";
    c.fail(msg);
  }
}

double positive_double(const DeckNode& node, const std::string& child) {
  const DeckNode& c = node.require_child(child);
  const double v = c.as_double();
  if (!(v > 0)) c.fail("<" + child + "> must be > 0 (got " + c.text + ")");
  return v;
}

}  // namespace tephra::geometry_detail
