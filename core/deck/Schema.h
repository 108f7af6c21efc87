#pragma once
// Tephra's deck schema: which elements a .ups deck may hold, how often, with
// what value type, range or allowed strings, and which attributes.
//
// The schema text (core/deck/schema/ups_schema.txt) is generated from
// Vaango's own input specification (ups_spec.xml and its includes) by
// core/deck/schema/convert_ups_spec.py, plus a hand-written EXTENSIONS section
// for what real Vaango decks use but the spec lacks. It is compiled into the
// library, so nothing outside the executable is read at run time.
//
// Line format (full description at the top of ups_schema.txt):
//   PATH NEED TYPE [key=value ...]     one variant of an element
//   +PATH key=value ...                extension of every variant at PATH
// PATH is "Uintah_specification/a/b" or "$common/a" (a shared, named tag);
// NEED is OPTIONAL | REQUIRED | MULTIPLE; TYPE is NO_DATA, STRING, DOUBLE,
// INTEGER, BOOLEAN, VECTOR, MULTIPLE_DOUBLES/INTEGERS/VECTORS or REF:common;
// keys: values=a|b, range=positive|negative|lo..hi, applies=attr:v1|v2,
// attr=name:NEED:TYPE[:values-or-range], one_of=CHILD|ATTRIBUTE:a|b,
// all_or_none=CHILD|ATTRIBUTE:a|b, alias=sibling, label_ref=attr;
// in extensions also need=NEED and type=TYPE (corrections of the spec).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tephra {

enum class SchemaNeed { Optional, Required, Multiple };
enum class SchemaType {
  NoData, String, Double, Integer, Boolean, Vector,
  MultipleDoubles, MultipleIntegers, MultipleVectors, Ref
};

const char* to_string(SchemaNeed need);
const char* to_string(SchemaType type);

// Allowed values of a number (or of every component of a vector/list).
struct SchemaRange {
  enum class Kind { Any, NonNegative, NonPositive, Interval } kind = Kind::Any;
  double lo = 0, hi = 0;
  bool contains(double v) const;
  std::string describe() const;  // e.g. ">= 0", "in [0, 3.15]"
};

// How a value (element text or attribute) is checked.
struct SchemaValue {
  SchemaType type = SchemaType::NoData;
  std::vector<std::string> values;  // allowed strings (STRING); empty = any
  SchemaRange range;
};

struct SchemaAttribute {
  std::string name;
  SchemaNeed need = SchemaNeed::Optional;
  SchemaValue value;
};

// ONE_OF / ALL_OR_NONE_OF over children or attributes.
struct SchemaGroup {
  enum class Kind { OneOf, AllOrNone } kind = Kind::OneOf;
  bool on_attributes = false;
  std::vector<std::string> names;
};

struct SchemaElement {
  std::string name;
  SchemaNeed need = SchemaNeed::Optional;
  SchemaValue value;
  std::string ref;                      // common tag name when value.type == Ref
  std::string applies_attr;             // parent attribute (empty: always applies)
  std::vector<std::string> applies_values;
  std::vector<SchemaAttribute> attributes;
  std::vector<SchemaGroup> groups;
  std::string alias_of;                 // another spelling of this sibling
  // Name of the attribute by which an element that carries only it (no text,
  // no children, no other attribute) refers to an earlier element of the same
  // name with that label (Vaango's reuse of geometry pieces by label).
  std::string label_ref;
  int schema_line = 0;                  // line in the schema text (diagnostics)
  // Children by name; several variants per name (chosen by applies_*).
  std::map<std::string, std::vector<std::unique_ptr<SchemaElement>>> children;
};

class Schema {
 public:
  // Parses schema text; a malformed line throws std::runtime_error naming
  // `name` and the line (a schema bug, not a deck error).
  static std::unique_ptr<Schema> parse(const std::string& text, const std::string& name);
  // The schema compiled into Tephra (parsed once, on first use).
  static const Schema& builtin();

  const SchemaElement& root() const { return *root_; }
  // The common tag definition, or nullptr.
  const SchemaElement* common(const std::string& name) const;

 private:
  std::unique_ptr<SchemaElement> root_;
  std::map<std::string, std::unique_ptr<SchemaElement>> common_;
  friend struct SchemaParser;
};

// The embedded schema text (generated at build time from ups_schema.txt).
const char* builtin_schema_text();

}  // namespace tephra
