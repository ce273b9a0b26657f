/// @file `eomgen diff OLD NEW`: the derived equations of two versions of a model (model
/// files or derived-equations JSON) compared entry by entry; and `--self OLD_EOMGEN`,
/// what another eomgen executable derives from the same models against this one.
#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "compare/diff_report.hpp"
#include "studies/diff_study.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

namespace {

constexpr int exit_diff_internal_error = 4;

// equal on the sampled region only is not shown to be the same: like different, it exits 1, unless
// --region says that region is all the user asks about
int status_of(const EquationDiff& d, bool region_is_enough) {
  return d.verdict == "different" || (d.verdict == "equal_on_samples" && !region_is_enough) ? 1 : 0;
}

// OLD NEW: one comparison, reported in full
int diff_pair(const ComparisonOptions& o) {
  Diagnostics diagnostics;
  auto a = read_derivation(o.inputs[0], diagnostics);
  auto b = read_derivation(o.inputs[1], diagnostics);
  if (!a || !b) {
    std::cerr << diagnostics.format();
    return exit_user_error;
  }
  EquationDiff d = compare_derivations(*a, *b, o.options, diagnostics);
  if (!diagnostics.empty()) {
    std::cerr << diagnostics.format();
    return exit_user_error;
  }
  std::cout << (o.json ? diff_json(d) : diff_text(d));
  return status_of(d, o.region_is_enough);
}

std::vector<std::string> model_files(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const std::string& input : inputs) {
    if (!std::filesystem::is_directory(input)) {
      files.push_back(input);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(input))
      if (entry.path().extension() == ".toml") found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// --self OLD_EOMGEN MODELS...: one line per model
int diff_self(const ComparisonOptions& o) {
  std::string scratch = (std::filesystem::temp_directory_path() / fmt::format("eomgen-diff-{}", ::getpid())).string();
  std::filesystem::create_directories(scratch);
  int worst = 0;
  std::vector<std::string> files = model_files(o.inputs);
  for (const std::string& model : files) {
    std::string baseline = scratch + "/" + std::filesystem::path(model).stem().string() + ".json";
    std::string command = fmt::format("{} derive {} --format json -o {} 2>/dev/null", shell_quoted(o.self), shell_quoted(model),
                                      shell_quoted(baseline));
    Diagnostics diagnostics;
    std::optional<DerivationRecord> a, b;
    if (std::system(command.c_str()) == 0) a = read_derivation(baseline, diagnostics);
    b = read_derivation(model, diagnostics);
    if (!a || !b) {
      std::cout << fmt::format("{}: not compared: {}\n", model,
                               !a ? o.self + " could not derive it" : "this eomgen could not derive it");
      worst = std::max(worst, static_cast<int>(exit_user_error));
      continue;
    }
    EquationDiff d = compare_derivations(*a, *b, o.options, diagnostics);
    std::size_t different = 0;
    for (const EntryComparison& c : d.entries) different += c.status == "different";
    std::cout << fmt::format("{}: {}{}\n", model, d.verdict,
                             d.verdict == "different" ? fmt::format(" ({} entries differ, {} symbols added or removed)", different,
                                                                    d.added.size() + d.removed.size())
                                                      : "");
    worst = std::max(worst, status_of(d, o.region_is_enough));
  }
  std::filesystem::remove_all(scratch);
  std::cerr << fmt::format("eomgen diff --self: {} models compared with {}\n", files.size(), o.self);
  return worst;
}

}  // namespace

int diff(ComparisonOptions o) {
  std::vector<Assignment> renames;
  for (const std::string& r : o.renames) {
    std::size_t eq = r.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == r.size()) {
      std::cerr << fmt::format("eomgen: error: --rename '{}': expected OLD=NEW, e.g. --rename k=stiffness\n", r);
      return exit_user_error;
    }
    o.options.renames.emplace_back(r.substr(0, eq), r.substr(eq + 1));
  }
  if (o.self.empty() && o.inputs.size() != 2) {
    std::cerr << "eomgen: error: diff compares two inputs: eomgen diff OLD NEW (model files, robot files or derived-equations JSON)\n";
    return exit_user_error;
  }
  if (!(o.options.tolerance > 0) || o.options.samples < 1) {
    std::cerr << "eomgen: error: need --tolerance > 0 and --samples >= 1\n";
    return exit_user_error;
  }
  try {
    return o.self.empty() ? diff_pair(o) : diff_self(o);
  } catch (const std::exception& e) {
    std::cerr << "eomgen: internal error: " << e.what()
              << "\nThis is a bug in eomgen. Please report it with both inputs and the command line.\n";
    return exit_diff_internal_error;
  }
}

}  // namespace eomgen::studies
