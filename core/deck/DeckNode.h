#pragma once
// The deck as an owned tree of elements, after <include> resolution. Every
// node remembers the file and line it came from, so that any error about it
// can name file:line and the element (DESIGN.md §2.8).
//
// Typed getters parse Vaango's value syntax: numbers, vectors "[a, b, c]",
// booleans "true|false" and lists "[a, b, ...]". A value that does not parse
// is a DeckError naming the element.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/base/Errors.h"
#include "core/base/Types.h"

namespace tephra {

class DeckNode {
 public:
  std::string name;                                        // element name
  std::string text;                                        // trimmed text content
  std::vector<std::pair<std::string, std::string>> attributes;  // in document order
  std::vector<DeckNode> children;                          // in document order
  std::string file;                                        // file it was read from
  int line = 0;                                            // 1-based line in that file
  const DeckNode* parent = nullptr;                        // set by finalize_parents()

  // Element path from the root, e.g. "Grid/Level/Box".
  std::string path() const;
  SourceLocation location() const { return {file, line, path()}; }

  // ---- children
  const DeckNode* child(const std::string& child_name) const;  // first, or nullptr
  const DeckNode& require_child(const std::string& child_name) const;  // DeckError if missing
  std::vector<const DeckNode*> children_named(const std::string& child_name) const;
  bool has_child(const std::string& child_name) const { return child(child_name) != nullptr; }
  // The first child present among alternative spellings (e.g. max_Timesteps /
  // max_timesteps); logs which spelling was read when more than one exists.
  const DeckNode* child_any(std::initializer_list<const char*> spellings) const;

  // ---- attributes
  std::optional<std::string> attribute(const std::string& attr_name) const;
  std::string require_attribute(const std::string& attr_name) const;

  // ---- this node's own text as a typed value
  double as_double() const;
  int as_int() const;
  bool as_bool() const;
  Vec3 as_vec3() const;
  IntVec3 as_int_vec3() const;
  std::vector<double> as_doubles() const;  // "[a, b, ...]" or "a b ..."
  std::string as_string() const { return text; }

  // ---- a child's text as a typed value: required, or with a default
  double get_double(const std::string& child_name) const;
  double get_double(const std::string& child_name, double fallback) const;
  int get_int(const std::string& child_name) const;
  int get_int(const std::string& child_name, int fallback) const;
  bool get_bool(const std::string& child_name, bool fallback) const;
  Vec3 get_vec3(const std::string& child_name) const;
  Vec3 get_vec3(const std::string& child_name, const Vec3& fallback) const;
  IntVec3 get_int_vec3(const std::string& child_name) const;
  IntVec3 get_int_vec3(const std::string& child_name, const IntVec3& fallback) const;
  std::string get_string(const std::string& child_name) const;
  std::string get_string(const std::string& child_name, const std::string& fallback) const;

  // A DeckError located at this node.
  [[noreturn]] void fail(const std::string& message) const;
  // A MissingFeature (exit 3) located at this node.
  [[noreturn]] void missing_feature(const std::string& feature) const;

  // Re-link parent pointers after the tree was built or copied.
  void finalize_parents();
};

// Value parsers shared by the getters and the schema validator. They return
// nullopt when the text does not parse.
// Text without leading/trailing blanks (space, tab, CR, LF).
std::string trim(const std::string& s);
std::optional<double> parse_double(const std::string& text);
std::optional<long long> parse_integer(const std::string& text);
std::optional<bool> parse_bool(const std::string& text);
std::optional<std::vector<double>> parse_number_list(const std::string& text);

}  // namespace tephra
