#include "models/JsonValue.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace tephra {

namespace {

// Recursive descent over the grammar of RFC 8259 §2-7, tracking the line.
class Parser {
 public:
  explicit Parser(std::string_view t) : t_(t) {}

  JsonValue document() {
    JsonValue v = value(0);
    skip_space();
    if (i_ < t_.size()) fail("unexpected text after the JSON value");
    return v;
  }

 private:
  std::string_view t_;
  std::size_t i_ = 0;
  int line_ = 1;

  [[noreturn]] void fail(const std::string& what) const { throw JsonError(line_, what); }

  void skip_space() {
    while (i_ < t_.size()) {
      const char c = t_[i_];
      if (c == '\n') ++line_;
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return;
      ++i_;
    }
  }

  char peek() const { return i_ < t_.size() ? t_[i_] : '\0'; }

  void expect(char c) {
    skip_space();
    if (peek() != c) fail(std::string("expected '") + c + "'" + found());
    ++i_;
  }

  std::string found() const {
    if (i_ >= t_.size()) return " at the end of the file";
    return std::string(", found '") + t_[i_] + "'";
  }

  JsonValue value(int depth) {
    if (depth > 200) fail("JSON nested deeper than 200 levels");
    skip_space();
    JsonValue v;
    v.line = line_;
    const char c = peek();
    if (c == '{') {
      v.kind = JsonValue::Kind::Object;
      ++i_;
      skip_space();
      if (peek() == '}') { ++i_; return v; }
      for (;;) {
        skip_space();
        if (peek() != '"') fail("expected a string key" + found());
        const int key_line = line_;
        std::string key = string_literal();
        for (const auto& [k, unused] : v.object)
          if (k == key) throw JsonError(key_line, "key \"" + key + "\" repeated in one object");
        expect(':');
        v.object.emplace_back(std::move(key), value(depth + 1));
        skip_space();
        if (peek() == ',') { ++i_; continue; }
        if (peek() == '}') { ++i_; return v; }
        fail("expected ',' or '}' in an object" + found());
      }
    }
    if (c == '[') {
      v.kind = JsonValue::Kind::Array;
      ++i_;
      skip_space();
      if (peek() == ']') { ++i_; return v; }
      for (;;) {
        v.array.push_back(value(depth + 1));
        skip_space();
        if (peek() == ',') { ++i_; continue; }
        if (peek() == ']') { ++i_; return v; }
        fail("expected ',' or ']' in an array" + found());
      }
    }
    if (c == '"') {
      v.kind = JsonValue::Kind::String;
      v.string = string_literal();
      return v;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      v.kind = JsonValue::Kind::Number;
      v.number = number();
      return v;
    }
    for (const char* word : {"true", "false", "null"}) {
      const std::string_view w(word);
      if (t_.substr(i_, w.size()) == w) {
        i_ += w.size();
        v.kind = w == "null" ? JsonValue::Kind::Null : JsonValue::Kind::Bool;
        v.boolean = w == "true";
        return v;
      }
    }
    fail("expected a JSON value" + found());
  }

  // number = [ minus ] int [ frac ] [ exp ]  (RFC 8259 §6; no NaN, no Infinity, no leading '+')
  double number() {
    const std::size_t start = i_;
    auto digits = [&] {
      const std::size_t d = i_;
      while (i_ < t_.size() && t_[i_] >= '0' && t_[i_] <= '9') ++i_;
      return i_ - d;
    };
    if (peek() == '-') ++i_;
    if (peek() == '0') ++i_;
    else if (digits() == 0) fail("malformed number");
    if (peek() == '.') {
      ++i_;
      if (digits() == 0) fail("malformed number: no digit after '.'");
    }
    if (peek() == 'e' || peek() == 'E') {
      ++i_;
      if (peek() == '+' || peek() == '-') ++i_;
      if (digits() == 0) fail("malformed number: no digit in the exponent");
    }
    const std::string text(t_.substr(start, i_ - start));
    errno = 0;
    const double x = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(x)) fail("number " + text + " out of the range of a double");
    return x;
  }

  static void append_utf8(std::string& s, unsigned cp) {
    if (cp < 0x80) {
      s += static_cast<char>(cp);
    } else if (cp < 0x800) {
      s += static_cast<char>(0xC0 | (cp >> 6));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      s += static_cast<char>(0xE0 | (cp >> 12));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      s += static_cast<char>(0xF0 | (cp >> 18));
      s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  unsigned hex4() {
    if (i_ + 4 > t_.size()) fail("truncated \\u escape");
    unsigned cp = 0;
    for (int k = 0; k < 4; ++k) {
      const char h = t_[i_++];
      cp <<= 4;
      if (h >= '0' && h <= '9') cp |= unsigned(h - '0');
      else if (h >= 'a' && h <= 'f') cp |= unsigned(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F') cp |= unsigned(h - 'A' + 10);
      else fail("bad hex digit in a \\u escape");
    }
    return cp;
  }

  std::string string_literal() {
    ++i_;  // opening quote
    std::string s;
    for (;;) {
      if (i_ >= t_.size()) fail("unterminated string");
      const char c = t_[i_++];
      if (c == '"') return s;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character inside a string (a missing closing quote?)");
      if (c != '\\') {
        s += c;
        continue;
      }
      if (i_ >= t_.size()) fail("unterminated string");
      const char e = t_[i_++];
      switch (e) {
        case '"': s += '"'; break;
        case '\\': s += '\\'; break;
        case '/': s += '/'; break;
        case 'b': s += '\b'; break;
        case 'f': s += '\f'; break;
        case 'n': s += '\n'; break;
        case 'r': s += '\r'; break;
        case 't': s += '\t'; break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00) {  // surrogate pair
            if (t_.substr(i_, 2) != "\\u") fail("lone high surrogate in a \\u escape");
            i_ += 2;
            const unsigned lo = hex4();
            if (lo < 0xDC00 || lo >= 0xE000) fail("bad low surrogate in a \\u escape");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          }
          append_utf8(s, cp);
          break;
        }
        default: fail(std::string("bad escape '\\") + e + "' in a string");
      }
    }
  }
};

}  // namespace

const char* json_kind_name(JsonValue::Kind k) {
  switch (k) {
    case JsonValue::Kind::Null: return "null";
    case JsonValue::Kind::Bool: return "a boolean";
    case JsonValue::Kind::Number: return "a number";
    case JsonValue::Kind::String: return "a string";
    case JsonValue::Kind::Array: return "an array";
    case JsonValue::Kind::Object: return "an object";
  }
  return "?";
}

const JsonValue* JsonValue::find(const std::string& key) const {
  if (kind != Kind::Object) return nullptr;
  for (const auto& [k, v] : object)
    if (k == key) return &v;
  return nullptr;
}

std::vector<double> JsonValue::numbers(const std::string& what) const {
  if (kind != Kind::Array) throw JsonError(line, what + " must be an array of numbers, not " + json_kind_name(kind));
  std::vector<double> out;
  out.reserve(array.size());
  for (std::size_t k = 0; k < array.size(); ++k) {
    if (!array[k].is_number())
      throw JsonError(array[k].line, what + "[" + std::to_string(k) + "] is " + json_kind_name(array[k].kind) +
                                         ", not a number");
    out.push_back(array[k].number);
  }
  return out;
}

JsonValue parse_json(std::string_view text) { return Parser(text).document(); }

}  // namespace tephra
