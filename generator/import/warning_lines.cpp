#include "import/warning_lines.hpp"

#include <algorithm>
#include <cstdlib>
#include <regex>

namespace eomgen {

namespace {

int line_at(const std::string& xml, std::size_t offset) {
  return offset == std::string::npos ? 0 : 1 + int(std::count(xml.begin(), xml.begin() + std::ptrdiff_t(offset), '\n'));
}

// the first `what` after the opening of the section `section`
std::size_t in_section(const std::string& xml, const std::string& section, const std::string& what) {
  std::size_t start = xml.find("<" + section);
  return start == std::string::npos ? start : xml.find(what, start);
}

// the k-th (1-based) element inside <section>, of any of the given tags
std::size_t kth_element(const std::string& xml, const std::string& section, int k) {
  std::size_t at = xml.find("<" + section), end = xml.find("</" + section, at);
  if (at == std::string::npos || end == std::string::npos) return std::string::npos;
  at = xml.find('>', at);
  for (int found = 0; at != std::string::npos && at < end;) {
    at = xml.find('<', at + 1);
    if (at == std::string::npos || at >= end) break;
    if (xml.compare(at, 4, "<!--") == 0) continue;
    if (++found == k) return at;
  }
  return std::string::npos;
}

}  // namespace

int warning_line(const std::string& xml, const std::string& warning) {
  std::smatch m;
  if (std::regex_search(warning, m, std::regex("^actuator '([^']+)'")))
    return line_at(xml, in_section(xml, "actuator", "name=\"" + m[1].str() + "\""));
  if (std::regex_search(warning, m, std::regex("^equality constraint '([^']+)'")))
    return line_at(xml, in_section(xml, "equality", "name=\"" + m[1].str() + "\""));
  if (std::regex_search(warning, m, std::regex("^equality constraint ([0-9]+) of")))
    return line_at(xml, kth_element(xml, "equality", std::atoi(m[1].str().c_str())));
  if (warning.find("tendon(s)") != std::string::npos) return line_at(xml, xml.find("<tendon"));
  if (warning.find("actuator(s) with a control range") != std::string::npos) return line_at(xml, xml.find("<actuator"));
  return 0;
}

}  // namespace eomgen
