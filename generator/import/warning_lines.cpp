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

}  // namespace eomgen
