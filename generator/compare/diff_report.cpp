#include "compare/diff_report.hpp"

#include <cmath>
#include <map>

#include <fmt/format.h>

#include "emit/formats.hpp"

namespace eomgen {

namespace {

std::string quote(const std::string& s) { return json_quoted(s); }

std::string rounded_number(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "null"; }

std::string strings(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "" : ", ") + quote(s);
  return "[" + out + "]";
}

std::string level(const EntryComparison& c) {
  if (c.decided_by == "text") return "same canonical text";
  if (c.decided_by == "symbolic") return "the difference simplifies to 0";
  if (c.decided_by == "numeric on the samples")
    return "equal at every random point (50 digits), but abs, atan2 or a fractional power has branches: equal on the "
           "sampled region only (coordinates in (0.2, 1.3) and (-4, 4), velocities in (-2, 2), parameters 0.5 to 2 times "
           "their defaults)";
  return c.status == "equivalent" ? "equal at every random point (50 digits)" : "differs at the random points";
}

// An expression as the text report shows it: a robot's entries written out ran to thousands of
// terms, which no one reads in a terminal; --format json keeps every expression whole.
std::string shown(const std::string& expression) {
  constexpr std::size_t longest = 1000;
  if (expression.size() <= longest) return expression;
  return fmt::format("{} … (an expression of {} characters; --format json gives it whole)", expression.substr(0, 200),
                     expression.size());
}

// the two sides of an entry, one line where their texts agree: the same expression of a tree's
// quantities, which differ (identical entries are only counted)
// where the decimals hide a difference, the new side says so
constexpr const char* beyond_the_decimals = " (its numbers differ beyond 17 digits)";

std::string sides(const EntryComparison& c) {
  if (c.beyond_the_decimals) return fmt::format("    old: {}\n    new: {}{}\n", shown(c.old_text), shown(c.new_text), beyond_the_decimals);
  if (c.old_text == c.new_text) return fmt::format("    both: {} (of the tree's quantities, which differ: below)\n", shown(c.old_text));
  return fmt::format("    old: {}\n    new: {}\n", shown(c.old_text), shown(c.new_text));
}

std::string changed_quantities(const std::vector<IntermediateChange>& changes) {
  if (changes.empty()) return "";
  constexpr std::size_t listed = 12;
  std::string out = fmt::format("  the tree's quantities that differ ({}{}):\n", changes.size(),
                                changes.size() > listed ? fmt::format(", the first {}; --format json lists all", listed) : "");
  for (std::size_t i = 0; i < changes.size() && i < listed; ++i) {
    const IntermediateChange& c = changes[i];
    out += fmt::format("    {}\n      old: {}\n      new: {}{}\n", c.name, c.old_text.empty() ? "(none)" : shown(c.old_text),
                       c.new_text.empty() ? "(none)" : shown(c.new_text), c.beyond_the_decimals ? beyond_the_decimals : "");
  }
  return out;
}

}  // namespace

std::string diff_text(const EquationDiff& d) {
  std::string out = fmt::format("eomgen diff {} {}: {}\n", d.old_path, d.new_path, d.verdict);
  for (const std::string& a : d.added) out += "  added:   " + a + "\n";
  for (const std::string& r : d.removed) out += "  removed: " + r + "\n";
  for (const auto& [from, to] : d.renamed) out += fmt::format("  renamed: {} -> {}\n", from, to);
  for (const std::string& e : d.entries_only_new) out += "  only in new: " + e + "\n";
  for (const std::string& e : d.entries_only_old) out += "  only in old: " + e + "\n";
  for (const DefaultChange& c : d.defaults_changed)
    out += fmt::format("  default changed: {} = {} -> {}\n", c.name, c.old_value, c.new_value);
  std::map<std::string, int> counts;
  for (const EntryComparison& c : d.entries) ++counts[c.status];
  // a robot's hundreds of entries are listed up to these counts, the rest counted (--format json
  // lists every one)
  constexpr int listed_different = 40, listed_equivalent = 20;
  int shown = 0;
  for (const EntryComparison& c : d.entries)
    if (c.status == "different" && shown++ < listed_different)
      out += fmt::format("  different: {} (largest difference {} absolute, {} relative at the random points)\n", c.entry,
                         rounded_number(c.max_abs_difference), rounded_number(c.max_rel_difference)) +
             sides(c);
  if (shown > listed_different) out += fmt::format("  … and {} more different (--format json lists them)\n", shown - listed_different);
  shown = 0;
  for (const EntryComparison& c : d.entries)
    if (c.status == "equivalent" && shown++ < listed_equivalent)
      out += fmt::format("  equivalent: {} ({})\n", c.entry, level(c)) + sides(c);
  if (shown > listed_equivalent)
    out += fmt::format("  … and {} more equivalent (--format json lists them)\n", shown - listed_equivalent);
  out += changed_quantities(d.intermediates_changed);
  if (!d.motion.empty()) out += "  motion: " + d.motion + "\n";
  out += fmt::format("  {} entries compared: {} identical, {} equivalent, {} different\n", d.entries.size(), counts["identical"],
                     counts["equivalent"], counts["different"]);
  return out;
}

std::string diff_json(const EquationDiff& d) {
  std::string renamed, defaults, entries;
  for (const auto& [from, to] : d.renamed)
    renamed += fmt::format("{}{{\"old\": {}, \"new\": {}}}", renamed.empty() ? "" : ", ", quote(from), quote(to));
  for (const DefaultChange& c : d.defaults_changed)
    defaults += fmt::format("{}{{\"name\": {}, \"old\": {}, \"new\": {}}}", defaults.empty() ? "" : ", ", quote(c.name),
                            c.old_value, c.new_value);
  for (const EntryComparison& c : d.entries)
    entries += fmt::format("{}{{\"entry\": {}, \"status\": \"{}\", \"decided_by\": \"{}\", \"old\": {}, \"new\": {}, "
                           "\"max_abs_difference\": {}, \"max_rel_difference\": {}, \"beyond_the_decimals\": {}}}",
                           entries.empty() ? "" : ", ", quote(c.entry), c.status, c.decided_by, quote(c.old_text),
                           quote(c.new_text), rounded_number(c.max_abs_difference), rounded_number(c.max_rel_difference),
                           c.beyond_the_decimals);
  std::string intermediates;
  for (const IntermediateChange& c : d.intermediates_changed)
    intermediates += fmt::format("{}{{\"name\": {}, \"old\": {}, \"new\": {}, \"beyond_the_decimals\": {}}}",
                                 intermediates.empty() ? "" : ", ", quote(c.name), c.old_text.empty() ? "null" : quote(c.old_text),
                                 c.new_text.empty() ? "null" : quote(c.new_text), c.beyond_the_decimals);
  return fmt::format("{{\"verdict\": \"{}\", \"old\": {}, \"new\": {}, \"symbols\": {{\"added\": {}, \"removed\": {}, "
                     "\"renamed\": [{}], \"defaults_changed\": [{}]}}, \"entries\": [{}], \"entries_only_old\": {}, "
                     "\"entries_only_new\": {}, \"intermediates_changed\": [{}], \"motion\": {}}}\n",
                     d.verdict, quote(d.old_path), quote(d.new_path), strings(d.added), strings(d.removed), renamed, defaults,
                     entries, strings(d.entries_only_old), strings(d.entries_only_new), intermediates,
                     d.motion.empty() ? "null" : quote(d.motion));
}

}  // namespace eomgen
