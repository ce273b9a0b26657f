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

}  // namespace

std::string diff_text(const EquationDiff& d) {
  std::string out = fmt::format("eomgen diff {} {}: {}\n", d.old_path, d.new_path, d.verdict);
  for (const std::string& a : d.added) out += "  added:   " + a + "\n";
  for (const std::string& r : d.removed) out += "  removed: " + r + "\n";
  for (const auto& [from, to] : d.renamed) out += fmt::format("  renamed: {} -> {}\n", from, to);
  for (const std::string& e : d.entries_only_new) out += "  only in new: " + e + "\n";
  for (const std::string& e : d.entries_only_old) out += "  only in old: " + e + "\n";
  for (const DefaultChange& c : d.defaults_changed)
    out += fmt::format("  default changed: {} = {:.17g} -> {:.17g}\n", c.name, c.old_value, c.new_value);
  std::map<std::string, int> counts;
  for (const EntryComparison& c : d.entries) ++counts[c.status];
  for (const EntryComparison& c : d.entries)
    if (c.status == "different")
      out += fmt::format("  different: {} (largest difference {} absolute, {} relative at the random points)\n"
                         "    old: {}\n    new: {}\n",
                         c.entry, rounded_number(c.max_abs_difference), rounded_number(c.max_rel_difference), c.old_text, c.new_text);
  for (const EntryComparison& c : d.entries)
    if (c.status == "equivalent")
      out += fmt::format("  equivalent: {} ({})\n    old: {}\n    new: {}\n", c.entry, level(c), c.old_text, c.new_text);
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
    defaults += fmt::format("{}{{\"name\": {}, \"old\": {:.17g}, \"new\": {:.17g}}}", defaults.empty() ? "" : ", ", quote(c.name),
                            c.old_value, c.new_value);
  for (const EntryComparison& c : d.entries)
    entries += fmt::format("{}{{\"entry\": {}, \"status\": \"{}\", \"decided_by\": \"{}\", \"old\": {}, \"new\": {}, "
                           "\"max_abs_difference\": {}, \"max_rel_difference\": {}}}",
                           entries.empty() ? "" : ", ", quote(c.entry), c.status, c.decided_by, quote(c.old_text),
                           quote(c.new_text), rounded_number(c.max_abs_difference), rounded_number(c.max_rel_difference));
  return fmt::format("{{\"verdict\": \"{}\", \"old\": {}, \"new\": {}, \"symbols\": {{\"added\": {}, \"removed\": {}, "
                     "\"renamed\": [{}], \"defaults_changed\": [{}]}}, \"entries\": [{}], \"entries_only_old\": {}, "
                     "\"entries_only_new\": {}, \"motion\": {}}}\n",
                     d.verdict, quote(d.old_path), quote(d.new_path), strings(d.added), strings(d.removed), renamed, defaults,
                     entries, strings(d.entries_only_old), strings(d.entries_only_new), d.motion.empty() ? "null" : quote(d.motion));
}

}  // namespace eomgen
