#pragma once
// A small JSON reader (RFC 8259) for the data files some Vaango models name in
// their decks (tabular_eos: "Vaango_tabular_data" tables, VT ch. 22). Every
// value remembers the 1-based line it starts on, so an error about a table can
// name the file and the line. No writer, no streaming: tables are small.
//
// Numbers are doubles; objects keep their keys in file order (a repeated key is
// an error: JSON leaves it undefined and Vaango's reader keeps one silently).
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tephra {

// A malformed document or a value of the wrong kind, at `line` (1-based).
class JsonError : public std::runtime_error {
 public:
  JsonError(int line, const std::string& what) : std::runtime_error(what), line_(line) {}
  int line() const { return line_; }

 private:
  int line_;
};

struct JsonValue {
  enum class Kind { Null, Bool, Number, String, Array, Object };
  Kind kind = Kind::Null;
  int line = 0;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;

  bool is_object() const { return kind == Kind::Object; }
  bool is_array() const { return kind == Kind::Array; }
  bool is_number() const { return kind == Kind::Number; }
  // The member `key` of an object, nullptr when absent (or not an object).
  const JsonValue* find(const std::string& key) const;
  // The numbers of an array of numbers; JsonError at the offending element otherwise.
  std::vector<double> numbers(const std::string& what) const;
};

const char* json_kind_name(JsonValue::Kind k);

// Parses a whole document (one value, surrounded by white space only).
JsonValue parse_json(std::string_view text);

}  // namespace tephra
