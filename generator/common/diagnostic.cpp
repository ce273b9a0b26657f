#include "common/diagnostic.hpp"

#include <algorithm>
#include <iostream>
#include <cctype>
#include <tuple>

#include <fmt/format.h>

namespace eomgen {

void Diagnostics::error(SourceLocation where, std::string key, std::string message,
                        std::string hint) {
  list_.push_back({std::move(where), std::move(key), std::move(message), std::move(hint)});
}

std::string Diagnostics::format() const {
  std::vector<Diagnostic> sorted = list_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.where.line, a.where.column) < std::tie(b.where.line, b.where.column);
  });
  std::string out;
  for (const Diagnostic& d : sorted) {
    std::string place = d.where.file;
    if (d.where.line > 0) place += fmt::format(":{}:{}", d.where.line, std::max(d.where.column, 1));
    out += fmt::format("{}: error: {}{}\n", place, d.key.empty() ? "" : d.key + ": ", d.message);
    if (!d.hint.empty()) out += fmt::format("  hint: {}\n", d.hint);
  }
  return out;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string nearest_name(const std::string& word, const std::vector<std::string>& candidates) {
  // the same name in another case first: 'L' means 'l' rather than 't'
  for (const std::string& c : candidates)
    if (lowercase(c) == lowercase(word)) return c;
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::string suggest(const std::string& word, const std::vector<std::string>& candidates,
                    const std::string& what) {
  std::string near = nearest_name(word, candidates);
  if (!near.empty()) return fmt::format("did you mean '{}'?", near);
  if (candidates.empty()) return fmt::format("no {} is defined", what);
  std::string all;
  for (const std::string& c : candidates) all += (all.empty() ? "" : ", ") + c;
  return fmt::format("valid {}: {}", what, all);
}

bool report_diagnostics(const Diagnostics& diagnostics, const std::string& model_path) {
  if (diagnostics.empty()) return false;
  std::cerr << diagnostics.format();
  std::cerr << fmt::format("eomgen: {} error{} in {}; nothing written\n", diagnostics.size(),
                           diagnostics.size() == 1 ? "" : "s", model_path);
  return true;
}

}  // namespace eomgen
