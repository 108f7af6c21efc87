#pragma once
// Small checks shared by the geometry parsers: known children only, positive
// values, nearest-name suggestions. Internal to core/geometry.
#include <initializer_list>
#include <string>
#include <vector>

namespace tephra {

class DeckNode;

namespace geometry_detail {

// The name in `candidates` closest to `name` (edit distance), or "".
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

// DeckError at the first child of `node` whose name is not in `allowed`,
// naming the allowed children and the nearest one.
void require_known_children(const DeckNode& node, std::initializer_list<const char*> allowed);

// The child's value as a double that must be > 0 (DeckError at the child).
double positive_double(const DeckNode& node, const std::string& child);

}  // namespace geometry_detail
}  // namespace tephra
