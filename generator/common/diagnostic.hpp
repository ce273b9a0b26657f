/// @file Diagnostics: mistakes in a model file or on the command line, kept
/// as values (file, line, column, key, message, hint) and reported together.
#pragma once

#include <string>
#include <vector>

namespace eomgen {

struct SourceLocation {
  std::string file;
  int line = 0;    // 1-based; 0 when unknown
  int column = 0;  // 1-based; 0 when unknown
};

struct Diagnostic {
  SourceLocation where;
  std::string key;      // e.g. particles[1].position[0]
  std::string message;  // what is wrong
  std::string hint;     // how to fix it; may be empty
};

/// All mistakes found in one input, in the order found.
class Diagnostics {
 public:
  void error(SourceLocation where, std::string key, std::string message, std::string hint = {});
  bool empty() const { return list_.empty(); }
  std::size_t size() const { return list_.size(); }
  const std::vector<Diagnostic>& list() const { return list_; }
  /// Compiler format: `file:line:column: error: key: message` and `  hint: ...`.
  std::string format() const;

 private:
  std::vector<Diagnostic> list_;
};

/// A mistake of the user that stops a command (exit status 2).
struct UserError {
  Diagnostics diagnostics;
};

/// Levenshtein distance, for "did you mean" hints.
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The candidate closest to `word`, or empty if none is close enough.
std::string nearest_name(const std::string& word, const std::vector<std::string>& candidates);

/// "did you mean 'x'?" when a near name exists, else a list of the valid names.
std::string suggest(const std::string& word, const std::vector<std::string>& candidates,
                    const std::string& what);

/// Shows a derivation's diagnostics on stderr, once, with the closing "nothing written" line;
/// true when there were any.
bool report_diagnostics(const Diagnostics& diagnostics, const std::string& model_path);

}  // namespace eomgen
