/// @file Typed, located access to toml++ nodes; every mismatch becomes a
/// diagnostic naming the key path and the expected type.
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "parse/model_file.hpp"

namespace eomgen::toml_reader {

/// A key of a table with its node, in file order.
struct Entry {
  std::string name;
  const toml::node* node;
  SourceLocation where;  // of the key
};

class Reader {
 public:
  Reader(std::string path, Diagnostics& diagnostics) : path_(std::move(path)), d_(diagnostics) {}

  SourceLocation at(const toml::source_region& region) const;
  SourceLocation at(const toml::node& node) const { return at(node.source()); }

  /// The entries of a table in the order they appear in the file.
  std::vector<Entry> entries(const toml::table& table) const;

  /// Reports keys that are not in `allowed`, with the nearest valid key as hint.
  void check_keys(const toml::table& table, const std::string& key,
                  const std::vector<std::string>& allowed);

  const toml::table* table(const toml::node& node, const std::string& key, const char* what);
  const toml::array* array(const toml::node& node, const std::string& key, const char* what);
  bool string(const toml::node& node, const std::string& key, std::string& out);
  bool number(const toml::node& node, const std::string& key, double& out);
  bool boolean(const toml::node& node, const std::string& key, bool& out);

  /// An expression: a string, or a number written as such.
  bool expression(const toml::node& node, const std::string& key, ExpressionText& out);
  /// A vector of `length` expressions; a 3-vector may also be the name of a vector or point.
  bool vector(const toml::node& node, const std::string& key, std::size_t length,
              std::vector<ExpressionText>& out);
  /// A 3×3 array of expressions.
  bool matrix3(const toml::node& node, const std::string& key,
               std::vector<std::vector<ExpressionText>>& out);

  /// Mistaken values that were replaced by a stand-in so that the rest of the file can
  /// still be checked (a parameter given as a string): their diagnostics are already made.
  int stand_ins = 0;

  void error(SourceLocation where, std::string key, std::string message, std::string hint = {}) {
    d_.error(std::move(where), std::move(key), std::move(message), std::move(hint));
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  Diagnostics& d_;
};

/// "a string", "an integer", ... for messages.
std::string type_name(const toml::node& node);

}  // namespace eomgen::toml_reader
