#include "core/deck/Schema.h"

#include <sstream>
#include <stdexcept>

namespace tephra {

const char* to_string(SchemaNeed need) {
  switch (need) {
    case SchemaNeed::Optional: return "OPTIONAL";
    case SchemaNeed::Required: return "REQUIRED";
    case SchemaNeed::Multiple: return "MULTIPLE";
  }
  return "?";
}

const char* to_string(SchemaType type) {
  switch (type) {
    case SchemaType::NoData: return "NO_DATA";
    case SchemaType::String: return "STRING";
    case SchemaType::Double: return "DOUBLE";
    case SchemaType::Integer: return "INTEGER";
    case SchemaType::Boolean: return "BOOLEAN";
    case SchemaType::Vector: return "VECTOR";
    case SchemaType::MultipleDoubles: return "MULTIPLE_DOUBLES";
    case SchemaType::MultipleIntegers: return "MULTIPLE_INTEGERS";
    case SchemaType::MultipleVectors: return "MULTIPLE_VECTORS";
    case SchemaType::Ref: return "REF";
  }
  return "?";
}

bool SchemaRange::contains(double v) const {
  switch (kind) {
    case Kind::Any: return true;
    case Kind::NonNegative: return v >= 0;
    case Kind::NonPositive: return v <= 0;
    case Kind::Interval: return v >= lo && v <= hi;
  }
  return true;
}

std::string SchemaRange::describe() const {
  std::ostringstream s;
  switch (kind) {
    case Kind::Any: return "any value";
    case Kind::NonNegative: return ">= 0";
    case Kind::NonPositive: return "<= 0";
    case Kind::Interval: s << "in [" << lo << ", " << hi << "]"; return s.str();
  }
  return "";
}

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

// Builds the element tree from the schema lines. Errors here are bugs in the
// schema text (which is part of the source), hence std::runtime_error.
struct SchemaParser {
  Schema& schema;
  std::string name;
  int line = 0;

  [[noreturn]] void bad(const std::string& msg) const {
    throw std::runtime_error(name + ":" + std::to_string(line) + ": " + msg);
  }

  SchemaNeed need_of(const std::string& s) const {
    if (s == "OPTIONAL") return SchemaNeed::Optional;
    if (s == "REQUIRED") return SchemaNeed::Required;
    if (s == "MULTIPLE") return SchemaNeed::Multiple;
    bad("unknown need '" + s + "'");
  }

  SchemaType type_of(const std::string& s) const {
    static const std::pair<const char*, SchemaType> table[] = {
        {"NO_DATA", SchemaType::NoData},   {"STRING", SchemaType::String},
        {"DOUBLE", SchemaType::Double},    {"INTEGER", SchemaType::Integer},
        {"BOOLEAN", SchemaType::Boolean},  {"VECTOR", SchemaType::Vector},
        {"MULTIPLE_DOUBLES", SchemaType::MultipleDoubles},
        {"MULTIPLE_INTEGERS", SchemaType::MultipleIntegers},
        {"MULTIPLE_VECTORS", SchemaType::MultipleVectors}};
    for (const auto& [k, t] : table)
      if (s == k) return t;
    bad("unknown type '" + s + "'");
  }

  SchemaRange range_of(const std::string& s) const {
    SchemaRange r;
    if (s == "positive") {
      r.kind = SchemaRange::Kind::NonNegative;
    } else if (s == "negative") {
      r.kind = SchemaRange::Kind::NonPositive;
    } else {
      size_t dots = s.find("..");
      if (dots == std::string::npos) bad("bad range '" + s + "'");
      try {
        r.lo = std::stod(s.substr(0, dots));
        r.hi = std::stod(s.substr(dots + 2));
      } catch (const std::exception&) {
        bad("bad range '" + s + "'");
      }
      r.kind = SchemaRange::Kind::Interval;
    }
    return r;
  }

  // "values" or "range" payload depending on the type.
  void restrict(SchemaValue& v, const std::string& payload, bool is_range) const {
    if (is_range) {
      if (v.type == SchemaType::String || v.type == SchemaType::NoData ||
          v.type == SchemaType::Boolean)
        bad("a range needs a numeric type");
      v.range = range_of(payload);
    } else {
      if (v.type != SchemaType::String) bad("allowed values need type STRING");
      for (auto& w : split(payload, '|'))
        if (!w.empty()) v.values.push_back(w);
    }
  }

  SchemaAttribute attribute_of(const std::string& s) const {
    auto f = split(s, ':');
    if (f.size() < 3 || f.size() > 4) bad("bad attr '" + s + "'");
    SchemaAttribute a;
    a.name = f[0];
    a.need = need_of(f[1]);
    if (a.need == SchemaNeed::Multiple) bad("an attribute cannot be MULTIPLE");
    a.value.type = type_of(f[2]);
    if (f.size() == 4) {
      bool numeric = a.value.type != SchemaType::String;
      restrict(a.value, f[3], numeric);
    }
    return a;
  }

  SchemaGroup group_of(SchemaGroup::Kind kind, const std::string& s) const {
    auto f = split(s, ':');
    if (f.size() != 2 || (f[0] != "CHILD" && f[0] != "ATTRIBUTE")) bad("bad group '" + s + "'");
    SchemaGroup g;
    g.kind = kind;
    g.on_attributes = f[0] == "ATTRIBUTE";
    g.names = split(f[1], '|');
    return g;
  }

  void apply_key(SchemaElement& e, const std::string& kv, bool extending) const {
    size_t eq = kv.find('=');
    if (eq == std::string::npos) bad("expected key=value, found '" + kv + "'");
    std::string key = kv.substr(0, eq), val = kv.substr(eq + 1);
    if (key == "values" || key == "range") {
      restrict(e.value, val, key == "range");
    } else if (key == "applies") {
      auto f = split(val, ':');
      if (f.size() != 2) bad("bad applies '" + val + "'");
      if (!e.applies_attr.empty() && e.applies_attr != f[0]) bad("applies on two attributes");
      e.applies_attr = f[0];
      for (auto& w : split(f[1], '|'))
        if (!w.empty()) e.applies_values.push_back(w);
    } else if (key == "attr") {
      SchemaAttribute a = attribute_of(val);
      for (auto& old : e.attributes)
        if (old.name == a.name) {
          if (!extending) bad("attribute '" + a.name + "' declared twice");
          old = a;
          return;
        }
      e.attributes.push_back(a);
    } else if (key == "one_of") {
      e.groups.push_back(group_of(SchemaGroup::Kind::OneOf, val));
    } else if (key == "all_or_none") {
      e.groups.push_back(group_of(SchemaGroup::Kind::AllOrNone, val));
    } else if (key == "alias") {
      e.alias_of = val;
    } else if (key == "need" && extending) {
      e.need = need_of(val);
    } else if (key == "type" && extending) {
      // a corrected type drops restrictions that belonged to the old one
      e.value = SchemaValue{};
      e.value.type = type_of(val);
    } else if (key == "label_ref") {
      e.label_ref = val;
    } else {
      bad("unknown key '" + key + "'");
    }
  }

  // The element a path names (last variant of each step); nullptr if absent.
  // With `create_last`, appends a new variant for the last step instead.
  SchemaElement* walk(const std::vector<std::string>& parts, bool create_last) {
    SchemaElement* e = nullptr;
    size_t first = 1;
    if (parts[0].size() > 1 && parts[0][0] == '$') {
      std::string cname = parts[0].substr(1);
      auto it = schema.common_.find(cname);
      if (it == schema.common_.end()) {
        if (!create_last || parts.size() != 1) bad("common tag '" + cname + "' not defined yet");
        auto el = std::make_unique<SchemaElement>();
        el->name = cname;
        e = el.get();
        schema.common_[cname] = std::move(el);
        return e;
      }
      e = it->second.get();
      if (parts.size() == 1) {
        if (create_last) bad("common tag '" + cname + "' defined twice");
        return e;
      }
    } else if (parts[0] == "Uintah_specification") {
      if (!schema.root_) {
        if (!create_last || parts.size() != 1) bad("the root must be defined first");
        schema.root_ = std::make_unique<SchemaElement>();
        schema.root_->name = parts[0];
        return schema.root_.get();
      }
      e = schema.root_.get();
      if (parts.size() == 1) {
        if (create_last) bad("root defined twice");
        return e;
      }
    } else {
      bad("a path starts with Uintah_specification or $common");
    }
    for (size_t i = first; i < parts.size(); ++i) {
      auto& variants = e->children[parts[i]];
      if (i + 1 == parts.size() && create_last) {
        variants.push_back(std::make_unique<SchemaElement>());
        variants.back()->name = parts[i];
        return variants.back().get();
      }
      if (variants.empty()) {
        e->children.erase(parts[i]);
        return nullptr;
      }
      e = variants.back().get();
    }
    return e;
  }

  std::vector<SchemaElement*> all_variants(const std::vector<std::string>& parts) {
    if (parts.size() == 1) {
      SchemaElement* e = walk(parts, false);
      return {e};
    }
    std::vector<std::string> up(parts.begin(), parts.end() - 1);
    SchemaElement* parent = walk(up, false);
    if (!parent) return {};
    auto it = parent->children.find(parts.back());
    if (it == parent->children.end()) return {};
    std::vector<SchemaElement*> out;
    for (auto& v : it->second) out.push_back(v.get());
    return out;
  }

  void parse_line(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> f;
    std::string w;
    while (in >> w) f.push_back(w);
    if (f.empty() || f[0][0] == '#') return;
    if (f[0][0] == '+') {
      auto parts = split(f[0].substr(1), '/');
      auto variants = all_variants(parts);
      if (variants.empty() || !variants[0]) bad("extension of unknown element '" + f[0] + "'");
      for (SchemaElement* e : variants)
        for (size_t i = 1; i < f.size(); ++i) apply_key(*e, f[i], true);
      return;
    }
    if (f.size() < 3) bad("expected PATH NEED TYPE");
    auto parts = split(f[0], '/');
    for (auto& p : parts)
      if (p.empty()) bad("empty name in path '" + f[0] + "'");
    SchemaElement* e = walk(parts, true);
    if (!e) bad("parent of '" + f[0] + "' not defined");
    e->schema_line = line;
    e->need = need_of(f[1]);
    if (f[2].rfind("REF:", 0) == 0) {
      e->value.type = SchemaType::Ref;
      e->ref = f[2].substr(4);
    } else {
      e->value.type = type_of(f[2]);
    }
    for (size_t i = 3; i < f.size(); ++i) apply_key(*e, f[i], false);
  }

  void check_refs(const SchemaElement& e) const {
    if (e.value.type == SchemaType::Ref && !schema.common(e.ref))
      throw std::runtime_error(name + ":" + std::to_string(e.schema_line) +
                               ": reference to unknown common tag '" + e.ref + "'");
    for (const auto& [n, vs] : e.children)
      for (const auto& v : vs) check_refs(*v);
  }
};

const SchemaElement* Schema::common(const std::string& cname) const {
  auto it = common_.find(cname);
  return it == common_.end() ? nullptr : it->second.get();
}

std::unique_ptr<Schema> Schema::parse(const std::string& text, const std::string& name) {
  auto schema = std::unique_ptr<Schema>(new Schema());
  SchemaParser p{*schema, name};
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l)) {
    ++p.line;
    p.parse_line(l);
  }
  if (!schema->root_) throw std::runtime_error(name + ": no Uintah_specification element");
  p.check_refs(*schema->root_);
  for (const auto& [n, c] : schema->common_) p.check_refs(*c);
  return schema;
}

const Schema& Schema::builtin() {
  static const std::unique_ptr<Schema> schema = parse(builtin_schema_text(), "ups_schema.txt");
  return *schema;
}

}  // namespace tephra
