#include "import/warning_lines.hpp"

#include <algorithm>

namespace eomgen {

namespace {

int line_at(const std::string& xml, std::size_t offset) {
  return offset == std::string::npos ? 0 : 1 + int(std::count(xml.begin(), xml.begin() + std::ptrdiff_t(offset), '\n'));
}

// the k-th (1-based) element inside the section that starts at `at`, comments not counted
std::size_t kth_element(const std::string& xml, std::size_t at, const std::string& section, int k) {
  std::size_t end = xml.find("</" + section, at);
  at = xml.find('>', at);
  for (int found = 0; at != std::string::npos && end != std::string::npos;) {
    at = xml.find('<', at + 1);
    if (at == std::string::npos || at >= end) break;
    if (xml.compare(at, 4, "<!--") == 0) continue;
    if (++found == k) return at;
  }
  return std::string::npos;
}

}  // namespace

int warning_line(const std::string& xml, const RobotWarning& warning) {
  if (warning.section.empty()) return 0;
  std::size_t section = xml.find("<" + warning.section);
  if (section == std::string::npos) return 0;
  if (!warning.name.empty()) return line_at(xml, xml.find("name=\"" + warning.name + "\"", section));
  if (warning.ordinal > 0) return line_at(xml, kth_element(xml, section, warning.section, warning.ordinal));
  return line_at(xml, section);
}

WarningPlace warning_place(const std::vector<std::pair<std::string, std::string>>& sources, const RobotWarning& warning) {
  if (sources.empty()) return {};
  if (int line = warning_line(sources[0].second, warning); line > 0) return {sources[0].first, line};
  std::vector<std::size_t> with_section;
  for (std::size_t k = 0; k < sources.size() && !warning.section.empty(); ++k)
    if (sources[k].second.find("<" + warning.section) != std::string::npos) with_section.push_back(k);
  bool by_place = warning.name.empty() && warning.ordinal > 0;
  if (by_place && !(with_section.size() == 1 && with_section[0] > 0)) return {};
  for (std::size_t k : with_section)
    if (int line = warning_line(sources[k].second, warning); k > 0 && line > 0) return {sources[k].first, line};
  return {};
}

}  // namespace eomgen
