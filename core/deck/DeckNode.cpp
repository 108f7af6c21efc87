#include "core/deck/DeckNode.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/base/Log.h"

namespace tephra {

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::optional<double> parse_double(const std::string& raw) {
  std::string t = trim(raw);
  if (t.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(t.c_str(), &end);
  if (end == t.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<long long> parse_integer(const std::string& raw) {
  std::string t = trim(raw);
  if (t.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  long long v = std::strtoll(t.c_str(), &end, 10);
  if (end == t.c_str() || *end != '\0' || errno == ERANGE) return std::nullopt;
  return v;
}

std::optional<bool> parse_bool(const std::string& raw) {
  std::string t = trim(raw);
  if (t == "true" || t == "TRUE" || t == "True") return true;
  if (t == "false" || t == "FALSE" || t == "False") return false;
  return std::nullopt;
}

// Vaango writes lists as "[a, b, c]"; whitespace-separated lists also occur.
std::optional<std::vector<double>> parse_number_list(const std::string& raw) {
  std::string t = trim(raw);
  if (!t.empty() && t.front() == '[') {
    if (t.back() != ']') return std::nullopt;
    t = t.substr(1, t.size() - 2);
  } else if (!t.empty() && t.back() == ']') {
    return std::nullopt;
  }
  for (char& c : t)
    if (c == ',') c = ' ';
  std::istringstream in(t);
  std::vector<double> out;
  std::string tok;
  while (in >> tok) {
    auto v = parse_double(tok);
    if (!v) return std::nullopt;
    out.push_back(*v);
  }
  return out;
}

std::string DeckNode::path() const {
  std::string p = name;
  for (const DeckNode* q = parent; q != nullptr && q->parent != nullptr; q = q->parent)
    p = q->name + "/" + p;
  return p;
}

const DeckNode* DeckNode::child(const std::string& n) const {
  for (const auto& c : children)
    if (c.name == n) return &c;
  return nullptr;
}

const DeckNode& DeckNode::require_child(const std::string& n) const {
  const DeckNode* c = child(n);
  if (!c) fail("missing required element <" + n + ">");
  return *c;
}

std::vector<const DeckNode*> DeckNode::children_named(const std::string& n) const {
  std::vector<const DeckNode*> out;
  for (const auto& c : children)
    if (c.name == n) out.push_back(&c);
  return out;
}

const DeckNode* DeckNode::child_any(std::initializer_list<const char*> spellings) const {
  const DeckNode* found = nullptr;
  for (const char* s : spellings) {
    const DeckNode* c = child(s);
    if (!c) continue;
    if (found) fail(std::string("both <") + found->name + "> and <" + s + "> given; use one");
    found = c;
  }
  if (found && spellings.size() > 1) log::info("read <" + found->path() + "> (spelling '" + found->name + "')");
  return found;
}

std::optional<std::string> DeckNode::attribute(const std::string& n) const {
  for (const auto& [k, v] : attributes)
    if (k == n) return v;
  return std::nullopt;
}

std::string DeckNode::require_attribute(const std::string& n) const {
  auto a = attribute(n);
  if (!a) fail("missing required attribute '" + n + "'");
  return *a;
}

double DeckNode::as_double() const {
  auto v = parse_double(text);
  if (!v) fail("expected a number, found '" + text + "'");
  return *v;
}

int DeckNode::as_int() const {
  auto v = parse_integer(text);
  if (!v || *v < INT32_MIN || *v > INT32_MAX) fail("expected an integer, found '" + text + "'");
  return static_cast<int>(*v);
}

bool DeckNode::as_bool() const {
  auto v = parse_bool(text);
  if (!v) fail("expected true or false, found '" + text + "'");
  return *v;
}

std::vector<double> DeckNode::as_doubles() const {
  auto v = parse_number_list(text);
  if (!v) fail("expected a list of numbers [a, b, ...], found '" + text + "'");
  return *v;
}

Vec3 DeckNode::as_vec3() const {
  auto v = parse_number_list(text);
  if (!v || v->size() != 3) fail("expected a vector [x, y, z], found '" + text + "'");
  return Vec3((*v)[0], (*v)[1], (*v)[2]);
}

IntVec3 DeckNode::as_int_vec3() const {
  Vec3 v = as_vec3();
  IntVec3 out;
  for (int d = 0; d < 3; ++d) {
    if (v[d] != std::floor(v[d]) || std::abs(v[d]) > 1e9)
      fail("expected an integer vector [i, j, k], found '" + text + "'");
    out[d] = static_cast<int>(v[d]);
  }
  return out;
}

double DeckNode::get_double(const std::string& n) const { return require_child(n).as_double(); }
double DeckNode::get_double(const std::string& n, double f) const {
  const DeckNode* c = child(n);
  return c ? c->as_double() : f;
}
int DeckNode::get_int(const std::string& n) const { return require_child(n).as_int(); }
int DeckNode::get_int(const std::string& n, int f) const {
  const DeckNode* c = child(n);
  return c ? c->as_int() : f;
}
bool DeckNode::get_bool(const std::string& n, bool f) const {
  const DeckNode* c = child(n);
  return c ? c->as_bool() : f;
}
Vec3 DeckNode::get_vec3(const std::string& n) const { return require_child(n).as_vec3(); }
Vec3 DeckNode::get_vec3(const std::string& n, const Vec3& f) const {
  const DeckNode* c = child(n);
  return c ? c->as_vec3() : f;
}
IntVec3 DeckNode::get_int_vec3(const std::string& n) const { return require_child(n).as_int_vec3(); }
IntVec3 DeckNode::get_int_vec3(const std::string& n, const IntVec3& f) const {
  const DeckNode* c = child(n);
  return c ? c->as_int_vec3() : f;
}
std::string DeckNode::get_string(const std::string& n) const { return require_child(n).text; }
std::string DeckNode::get_string(const std::string& n, const std::string& f) const {
  const DeckNode* c = child(n);
  return c ? c->text : f;
}

void DeckNode::fail(const std::string& message) const { throw DeckError(location(), message); }
void DeckNode::missing_feature(const std::string& feature) const {
  throw MissingFeature(location(), feature);
}

void DeckNode::finalize_parents() {
  for (auto& c : children) {
    c.parent = this;
    c.finalize_parents();
  }
}

}  // namespace tephra
