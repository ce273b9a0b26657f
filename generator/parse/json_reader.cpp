#include "parse/json_reader.hpp"

#include <cstdlib>

#include <fmt/format.h>

namespace eomgen {

const JsonValue* JsonValue::find(const std::string& key) const {
  for (const auto& [name, value] : members)
    if (name == key) return &value;
  return nullptr;
}

namespace {

class JsonParser {
 public:
  JsonParser(const std::string& text, const std::string& path) : s_(text), path_(path) {}

  // value: object | array | string | number | true | false | null
  JsonValue value(int depth) {
    skip_space();
    JsonValue v;
    v.where = here();
    if (depth > 200) fail("nesting deeper than 200 levels");
    if (at_end()) fail("a value was expected, the text ended");
    char c = s_[i_];
    if (c == '{') return object(depth);
    if (c == '[') return array(depth);
    if (c == '"') {
      v.kind = JsonValue::string;
      v.text = string();
      return v;
    }
    if (literal("true")) return v.kind = JsonValue::boolean, v.truth = true, v;
    if (literal("false")) return v.kind = JsonValue::boolean, v;
    if (literal("null")) return v;
    const char* start = s_.c_str() + i_;
    char* end = nullptr;
    v.value = std::strtod(start, &end);
    if (end == start || !(c == '-' || (c >= '0' && c <= '9'))) fail(fmt::format("unexpected '{}'", c));
    i_ += static_cast<std::size_t>(end - start);
    column_ += static_cast<int>(end - start);
    v.kind = JsonValue::number;
    return v;
  }

  void finish() {
    skip_space();
    if (!at_end()) fail("text after the end of the JSON value");
  }

  struct Failure {
    SourceLocation where;
    std::string message;
  };

 private:
  JsonValue object(int depth) {
    JsonValue v;
    v.kind = JsonValue::object;
    v.where = here();
    advance();
    skip_space();
    if (peek('}')) return advance(), v;
    for (;;) {
      skip_space();
      if (!peek('"')) fail("a member name in double quotes was expected");
      std::string key = string();
      skip_space();
      expect(':');
      v.members.emplace_back(key, value(depth + 1));
      skip_space();
      if (peek(',')) {
        advance();
        continue;
      }
      expect('}');
      return v;
    }
  }

  JsonValue array(int depth) {
    JsonValue v;
    v.kind = JsonValue::array;
    v.where = here();
    advance();
    skip_space();
    if (peek(']')) return advance(), v;
    for (;;) {
      v.items.push_back(value(depth + 1));
      skip_space();
      if (peek(',')) {
        advance();
        continue;
      }
      expect(']');
      return v;
    }
  }

  std::string string() {
    advance();  // the opening quote
    std::string out;
    for (;;) {
      if (at_end()) fail("a string is not closed");
      char c = s_[i_];
      if (c == '"') {
        advance();
        return out;
      }
      if (c == '\n') fail("a string is not closed before the end of the line");
      if (c != '\\') {
        out += c;
        advance();
        continue;
      }
      advance();
      if (at_end()) fail("a string is not closed");
      char e = s_[i_];
      advance();
      switch (e) {
        case '"': case '\\': case '/': out += e; break;
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': {
          if (i_ + 4 > s_.size()) fail("\\u needs four hex digits");
          unsigned code = static_cast<unsigned>(std::strtoul(s_.substr(i_, 4).c_str(), nullptr, 16));
          for (int k = 0; k < 4; ++k) advance();
          if (code < 0x80) out += static_cast<char>(code);
          else if (code < 0x800) out += static_cast<char>(0xC0 | (code >> 6)), out += static_cast<char>(0x80 | (code & 0x3F));
          else out += static_cast<char>(0xE0 | (code >> 12)), out += static_cast<char>(0x80 | ((code >> 6) & 0x3F)),
                  out += static_cast<char>(0x80 | (code & 0x3F));
          break;
        }
        default: fail(fmt::format("unknown escape \\{}", e));
      }
    }
  }

  bool literal(const char* word) {
    std::string w(word);
    if (s_.compare(i_, w.size(), w) != 0) return false;
    for (std::size_t k = 0; k < w.size(); ++k) advance();
    return true;
  }
  void expect(char c) {
    if (!peek(c)) fail(at_end() ? fmt::format("'{}' was expected, the text ended", c)
                                : fmt::format("'{}' was expected, not '{}'", c, s_[i_]));
    advance();
  }
  bool peek(char c) const { return !at_end() && s_[i_] == c; }
  bool at_end() const { return i_ >= s_.size(); }
  void advance() {
    if (s_[i_] == '\n') ++line_, column_ = 1;
    else ++column_;
    ++i_;
  }
  void skip_space() {
    while (!at_end() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r')) advance();
  }
  SourceLocation here() const { return {path_, line_, column_}; }
  [[noreturn]] void fail(const std::string& message) const { throw Failure{here(), message}; }

  const std::string& s_;
  std::string path_;
  std::size_t i_ = 0;
  int line_ = 1, column_ = 1;
};

}  // namespace

std::optional<JsonValue> parse_json(const std::string& text, const std::string& path, Diagnostics& diagnostics) {
  JsonParser reader(text, path);
  try {
    JsonValue v = reader.value(0);
    reader.finish();
    return v;
  } catch (const JsonParser::Failure& f) {
    diagnostics.error(f.where, "", "not valid JSON: " + f.message, "a derived-equations file is written by `eomgen derive MODEL --format json`");
    return std::nullopt;
  }
}

}  // namespace eomgen
