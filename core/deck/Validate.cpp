#include "core/deck/Validate.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

#include "core/deck/Schema.h"

namespace tephra {

size_t edit_distance(const std::string& a, const std::string& b) {
  // Optimal string alignment distance (Levenshtein plus adjacent
  // transposition, the commonest typo), by the Wagner–Fischer dynamic
  // programme over the full table d[i][j] = distance(a[0..i), b[0..j)).
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    size_t d = edit_distance(name, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

namespace {

std::string join(const std::vector<std::string>& v, size_t max_items = 40) {
  std::string s;
  for (size_t i = 0; i < v.size() && i < max_items; ++i) s += (i ? ", " : "") + v[i];
  if (v.size() > max_items) s += ", ... (" + std::to_string(v.size() - max_items) + " more)";
  return s;
}

std::string suggestion(const std::string& name, const std::vector<std::string>& valid) {
  std::string near = nearest_name(name, valid);
  std::string s;
  if (!near.empty()) s = "; did you mean '" + near + "'?";
  s += " Valid: " + join(valid);
  return s;
}

// Numbers of a MULTIPLE_VECTORS value: "[[a,b,c],[d,e,f]]" or "[a,b,c] [d,e,f]".
std::optional<std::vector<std::vector<double>>> parse_vector_list(const std::string& raw) {
  std::string t = raw;
  size_t b = t.find_first_not_of(" \t\r\n"), e = t.find_last_not_of(" \t\r\n");
  if (b == std::string::npos) return std::nullopt;
  t = t.substr(b, e - b + 1);
  // strip one outer bracket pair if the text starts with "[[".
  if (t.size() >= 2 && t[0] == '[' && t.find_first_not_of(" \t\r\n", 1) != std::string::npos &&
      t[t.find_first_not_of(" \t\r\n", 1)] == '[') {
    if (t.back() != ']') return std::nullopt;
    t = t.substr(1, t.size() - 2);
  }
  std::vector<std::vector<double>> out;
  size_t i = 0;
  while (true) {
    i = t.find_first_not_of(" \t\r\n,", i);
    if (i == std::string::npos) break;
    if (t[i] != '[') return std::nullopt;
    size_t close = t.find(']', i);
    if (close == std::string::npos) return std::nullopt;
    auto v = parse_number_list(t.substr(i, close - i + 1));
    if (!v || v->size() != 3) return std::nullopt;
    out.push_back(*v);
    i = close + 1;
  }
  if (out.empty()) return std::nullopt;
  return out;
}

bool is_integral(double v) { return v == static_cast<double>(static_cast<long long>(v)); }

// Checks one value against its declaration; returns "" or what is wrong.
std::string check_value(const SchemaValue& decl, const std::string& text) {
  auto in_range = [&](const std::vector<double>& xs) -> std::string {
    for (double x : xs)
      if (!decl.range.contains(x)) {
        std::ostringstream s;
        s << "value " << x << " out of range: expected " << decl.range.describe();
        return s.str();
      }
    return "";
  };
  switch (decl.type) {
    case SchemaType::NoData:
    case SchemaType::Ref:
      if (!text.empty()) return "expected no text, found '" + text + "'";
      return "";
    case SchemaType::String:
      if (text.empty()) return "expected a value, found nothing";
      if (!decl.values.empty() &&
          std::find(decl.values.begin(), decl.values.end(), text) == decl.values.end())
        return "'" + text + "' is not an allowed value" + suggestion(text, decl.values);
      return "";
    case SchemaType::Double: {
      auto v = parse_double(text);
      if (!v) return "expected a number, found '" + text + "'";
      return in_range({*v});
    }
    case SchemaType::Integer: {
      auto v = parse_integer(text);
      if (!v) return "expected an integer, found '" + text + "'";
      return in_range({static_cast<double>(*v)});
    }
    case SchemaType::Boolean:
      if (!parse_bool(text)) return "expected true or false, found '" + text + "'";
      return "";
    case SchemaType::Vector: {
      auto v = parse_number_list(text);
      if (!v || v->size() != 3) return "expected a vector [x, y, z], found '" + text + "'";
      return in_range(*v);
    }
    case SchemaType::MultipleDoubles:
    case SchemaType::MultipleIntegers: {
      auto v = parse_number_list(text);
      if (!v || v->empty()) return "expected a list of numbers [a, b, ...], found '" + text + "'";
      if (decl.type == SchemaType::MultipleIntegers)
        for (double x : *v)
          if (!is_integral(x)) return "expected a list of integers, found '" + text + "'";
      return in_range(*v);
    }
    case SchemaType::MultipleVectors: {
      auto v = parse_vector_list(text);
      if (!v) return "expected a list of vectors [[x, y, z], ...], found '" + text + "'";
      for (const auto& x : *v) {
        std::string r = in_range(x);
        if (!r.empty()) return r;
      }
      return "";
    }
  }
  return "";
}

// The declaration of one element with its common tag (if any) folded in.
struct Effective {
  const SchemaElement* own;
  const SchemaElement* common;  // nullptr unless own is a REF

  const SchemaValue& value() const { return common ? common->value : own->value; }

  std::vector<const SchemaAttribute*> attributes() const {
    std::vector<const SchemaAttribute*> out;
    for (const auto& a : own->attributes) out.push_back(&a);
    if (common)
      for (const auto& a : common->attributes)
        if (std::none_of(out.begin(), out.end(), [&](auto* o) { return o->name == a.name; }))
          out.push_back(&a);
    return out;
  }

  std::vector<const SchemaGroup*> groups() const {
    std::vector<const SchemaGroup*> out;
    for (const auto& g : own->groups) out.push_back(&g);
    if (common)
      for (const auto& g : common->groups) out.push_back(&g);
    return out;
  }

  // Child variants by name (own declarations take precedence).
  const std::vector<std::unique_ptr<SchemaElement>>* child(const std::string& n) const {
    auto it = own->children.find(n);
    if (it != own->children.end()) return &it->second;
    if (common) {
      auto jt = common->children.find(n);
      if (jt != common->children.end()) return &jt->second;
    }
    return nullptr;
  }

  std::vector<std::string> child_names() const {
    std::vector<std::string> out;
    for (const auto& [n, v] : own->children) out.push_back(n);
    if (common)
      for (const auto& [n, v] : common->children)
        if (!own->children.count(n)) out.push_back(n);
    std::sort(out.begin(), out.end());
    return out;
  }
};

class Checker {
 public:
  Checker(const Schema& s) : schema_(s) {}
  std::vector<DeckProblem> problems;

  void element(const DeckNode& node, const SchemaElement& decl) {
    Effective eff{&decl, nullptr};
    if (decl.value.type == SchemaType::Ref) eff.common = schema_.common(decl.ref);
    if (label_reference(node, eff)) return;
    // text
    std::string v = check_value(eff.value(), node.text);
    if (!v.empty()) report(node, v);
    attributes(node, eff);
    children(node, eff);
  }

 private:
  const Schema& schema_;

  // Labels of elements defined so far, per element name (document order).
  std::map<std::string, std::map<std::string, const DeckNode*>> labels_;

  // An element such as <cylinder label="inner"/> that holds nothing but its
  // label refers to the piece of that name defined earlier in the deck
  // (Vaango's GeometryPieceFactory keeps named pieces for reuse). Returns true
  // if `node` is such a reference (checked here); records definitions.
  bool label_reference(const DeckNode& node, const Effective& eff) {
    const std::string& key =
        !eff.own->label_ref.empty() ? eff.own->label_ref
                                    : (eff.common ? eff.common->label_ref : eff.own->label_ref);
    if (key.empty()) return false;
    auto label = node.attribute(key);
    if (!label) return false;
    auto& defined = labels_[node.name];
    if (node.children.empty() && node.text.empty() && node.attributes.size() == 1) {
      if (!defined.count(*label)) {
        std::vector<std::string> known;
        for (const auto& [l, n] : defined) known.push_back(l);
        report(node, "<" + node.name + " " + key + "=\"" + *label +
                         "\"/> refers to a piece not defined before it" +
                         (known.empty() ? std::string("; no <" + node.name + "> has a label yet")
                                        : suggestion(*label, known)));
      }
      return true;
    }
    auto [it, fresh] = defined.emplace(*label, &node);
    if (!fresh)
      report(node, "label '" + *label + "' of <" + node.name + "> already defined at " +
                       it->second->file + ":" + std::to_string(it->second->line));
    return false;
  }

  void report(const DeckNode& node, const std::string& msg) {
    problems.push_back({node.location(), msg});
  }

  static bool applies(const SchemaElement& variant, const DeckNode& parent) {
    if (variant.applies_attr.empty()) return true;
    auto a = parent.attribute(variant.applies_attr);
    if (!a) return false;
    return std::find(variant.applies_values.begin(), variant.applies_values.end(), *a) !=
           variant.applies_values.end();
  }

  void attributes(const DeckNode& node, const Effective& eff) {
    auto decls = eff.attributes();
    std::vector<std::string> names;
    for (auto* a : decls) names.push_back(a->name);
    std::map<std::string, int> seen;
    for (const auto& [k, val] : node.attributes) {
      auto it = std::find_if(decls.begin(), decls.end(), [&](auto* a) { return a->name == k; });
      if (it == decls.end()) {
        report(node, "unknown attribute '" + k + "'" +
                         (names.empty() ? std::string("; this element takes no attributes")
                                        : suggestion(k, names)));
        continue;
      }
      std::string v = check_value((*it)->value, val);
      if (!v.empty()) report(node, "attribute '" + k + "': " + v);
      seen[k]++;
    }
    for (auto* a : decls)
      if (a->need == SchemaNeed::Required && !seen.count(a->name))
        report(node, "missing required attribute '" + a->name + "'");
    for (auto* g : eff.groups()) {
      if (!g->on_attributes) continue;
      group(node, *g, [&](const std::string& n) { return seen.count(n) ? 1 : 0; }, "attribute");
    }
  }

  template <class Count>
  void group(const DeckNode& node, const SchemaGroup& g, Count count, const char* what) {
    size_t present = 0;
    for (const auto& n : g.names) present += count(n) > 0 ? 1 : 0;
    std::string list = join(g.names);
    if (g.kind == SchemaGroup::Kind::OneOf && present != 1)
      report(node, std::string("needs exactly one ") + what + " of " + list + ", found " +
                       std::to_string(present));
    if (g.kind == SchemaGroup::Kind::AllOrNone && present != 0 && present != g.names.size())
      report(node, std::string("needs all or none of the ") + what + "s " + list);
  }

  void children(const DeckNode& node, const Effective& eff) {
    std::map<std::string, int> count;               // by canonical name
    std::map<std::string, const DeckNode*> first;   // first occurrence
    for (const auto& c : node.children) {
      const auto* variants = eff.child(c.name);
      if (!variants) {
        auto names = eff.child_names();
        report(c, "unknown element <" + c.name + "> in <" + node.name + ">" +
                      (names.empty() ? std::string("; it takes no child elements")
                                     : suggestion(c.name, names)));
        continue;
      }
      const SchemaElement* chosen = nullptr;
      for (const auto& v : *variants)
        if (applies(*v, node)) {
          chosen = v.get();
          break;
        }
      if (!chosen) {
        const SchemaElement& v0 = *variants->front();
        std::vector<std::string> vals;
        for (const auto& v : *variants)
          for (const auto& s : v->applies_values) vals.push_back(s);
        auto a = node.attribute(v0.applies_attr);
        report(c, "<" + c.name + "> is only allowed when <" + node.name + "> has " +
                      v0.applies_attr + " = one of " + join(vals) + " (here " + v0.applies_attr +
                      (a ? " = '" + *a + "'" : std::string(" is missing")) + ")");
        continue;
      }
      std::string canon = chosen->alias_of.empty() ? c.name : chosen->alias_of;
      if (++count[canon] == 1) {
        first[canon] = &c;
      } else if (chosen->need != SchemaNeed::Multiple) {
        const DeckNode* f = first[canon];
        report(c, "<" + canon + "> given more than once (first at " + f->file + ":" +
                      std::to_string(f->line) +
                      (f->name != c.name ? " as <" + f->name + ">" : std::string()) +
                      "); it may appear at most once");
      }
      element(c, *chosen);
    }
    // required children (aliases count for the name they stand for)
    for (const auto& n : eff.child_names()) {
      for (const auto& v : *eff.child(n)) {
        if (v->need != SchemaNeed::Required || !v->alias_of.empty() || !applies(*v, node))
          continue;
        if (!count.count(n))
          report(node, "missing required element <" + n + ">" +
                           (v->applies_attr.empty()
                                ? std::string()
                                : " (required when " + v->applies_attr + " = '" +
                                      *node.attribute(v->applies_attr) + "')"));
        break;
      }
    }
    for (auto* g : eff.groups()) {
      if (g->on_attributes) continue;
      group(node, *g, [&](const std::string& n) { return count.count(n) ? count[n] : 0; },
            "child element");
    }
  }
};

}  // namespace

std::vector<DeckProblem> check_deck(const DeckNode& root, const Schema& schema) {
  Checker c(schema);
  if (root.name != schema.root().name) {
    c.problems.push_back({root.location(), "the root element must be <" + schema.root().name +
                                               ">, found <" + root.name + ">"});
    return c.problems;
  }
  c.element(root, schema.root());
  return c.problems;
}

void validate_deck(const Deck& deck) {
  auto problems = check_deck(deck.root, Schema::builtin());
  if (problems.empty()) return;
  std::string msg = problems.front().message;
  if (problems.size() > 1) {
    msg += "\n(" + std::to_string(problems.size()) + " problems in this deck; all of them:)";
    const size_t max_listed = 50;
    for (size_t i = 0; i < problems.size() && i < max_listed; ++i)
      msg += "\n  " + problems[i].where.str() + ": " + problems[i].message;
    if (problems.size() > max_listed)
      msg += "\n  ... " + std::to_string(problems.size() - max_listed) + " more";
  }
  throw DeckError(problems.front().where, msg);
}

}  // namespace tephra
