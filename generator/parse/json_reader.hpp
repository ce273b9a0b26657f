/// @file A small JSON reader for the derived-equations files eomgen writes
/// (`derive --format json`): values with the line and column they start at, and
/// mistakes reported with theirs.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/diagnostic.hpp"

namespace eomgen {

struct JsonValue {
  enum Kind { null, boolean, number, string, array, object } kind = null;
  bool truth = false;
  double value = 0;
  std::string text;
  std::vector<JsonValue> items;                            // array
  std::vector<std::pair<std::string, JsonValue>> members;  // object, in file order
  SourceLocation where;

  /// The member `key` of an object, or nullptr.
  const JsonValue* find(const std::string& key) const;
};

/// Parses a whole JSON text; on a mistake adds a located diagnostic and returns nothing.
std::optional<JsonValue> parse_json(const std::string& text, const std::string& path, Diagnostics& diagnostics);

}  // namespace eomgen
