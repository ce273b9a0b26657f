#include "import/xml_text.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace eomgen {

namespace {

bool space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

}  // namespace

int line_of(const std::string& text, std::size_t at) { return 1 + int(std::count(text.begin(), text.begin() + long(at), '\n')); }

std::size_t element_start(const std::string& text, const std::string& name, std::size_t from) {
  for (std::size_t at = text.find('<', from); at != std::string::npos; at = text.find('<', at + 1)) {
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string::npos) return at;
      continue;
    }
    std::size_t end = at + 1 + name.size();
    if (text.compare(at + 1, name.size(), name) == 0 && end < text.size() && (space(text[end]) || text[end] == '>' || text[end] == '/'))
      return at;
  }
  return std::string::npos;
}

std::size_t past_tag(const std::string& text, std::size_t start) {
  std::size_t end = text.find('>', start);
  return end == std::string::npos ? end : end + 1;
}

std::optional<std::pair<std::size_t, std::size_t>> attribute_span(const std::string& text, std::size_t start,
                                                                  std::size_t end, const std::string& name) {
  for (std::size_t at = text.find(name, start); at != std::string::npos && at < end; at = text.find(name, at + 1)) {
    if (at == 0 || !space(text[at - 1])) continue;
    std::size_t after = at + name.size();
    while (after < end && space(text[after])) ++after;
    if (after >= end || text[after] != '=') continue;
    ++after;
    while (after < end && space(text[after])) ++after;
    if (after >= end || (text[after] != '"' && text[after] != '\'')) continue;
    std::size_t close = text.find(text[after], after + 1);
    if (close == std::string::npos || close > end) return std::nullopt;
    return std::make_pair(at, close + 1);
  }
  return std::nullopt;
}

std::optional<std::string> attribute(const std::string& text, std::size_t start, std::size_t end, const std::string& name) {
  auto span = attribute_span(text, start, end, name);
  if (!span) return std::nullopt;
  std::size_t open = text.find_first_of("\"'", span->first + name.size());
  return text.substr(open + 1, span->second - open - 2);
}

bool any_tag_sets(const std::string& text, const std::vector<std::string>& elements, const std::string& name) {
  for (const std::string& element : elements)
    for (std::size_t at = element_start(text, element); at != std::string::npos; at = element_start(text, element, at + 1)) {
      std::size_t end = past_tag(text, at);
      if (end == std::string::npos) break;
      if (attribute_span(text, at, end, name)) return true;
    }
  return false;
}

std::string with_attribute_removed(const std::string& text, const std::string& element, const std::string& name) {
  std::string out = text;
  for (std::size_t at = element_start(out, element); at != std::string::npos; at = element_start(out, element, at + 1)) {
    std::size_t end = past_tag(out, at);
    if (end == std::string::npos) break;
    if (auto span = attribute_span(out, at, end, name)) out.erase(span->first, span->second - span->first);
  }
  return out;
}

const std::vector<std::string>& mjcf_actuator_elements() {
  static const std::vector<std::string> elements{"general", "motor",  "position", "velocity", "intvelocity",
                                                 "damper",  "cylinder", "muscle",  "adhesion"};
  return elements;
}

std::string with_attribute_renamed(const std::string& text, const std::string& element, const std::string& from, const std::string& to) {
  std::string out = text;
  for (std::size_t at = element_start(out, element); at != std::string::npos; at = element_start(out, element, at + 1)) {
    std::size_t end = past_tag(out, at);
    if (end == std::string::npos) break;
    if (auto span = attribute_span(out, at, end, from)) out.replace(span->first, from.size(), to);
  }
  return out;
}

std::array<double, 3> triple_attribute(const std::string& text, std::size_t start, std::size_t end, const std::string& name) {
  std::array<double, 3> t{0, 0, 0};
  if (std::optional<std::string> value = attribute(text, start, end, name)) {
    std::istringstream in(*value);
    in >> t[0] >> t[1] >> t[2];
  }
  return t;
}

std::string with_compiler_attributes(const std::string& text, const std::string& attributes, const std::vector<std::string>& names) {
  std::string out = text;
  std::size_t mujoco = element_start(out, "mujoco");
  if (mujoco == std::string::npos) {
    std::size_t robot = element_start(out, "robot");
    std::size_t inside = robot == std::string::npos ? robot : past_tag(out, robot);
    if (inside == std::string::npos || out[inside - 2] == '/') return text;
    return out.insert(inside, "<mujoco><compiler" + attributes + "/></mujoco>");
  }
  std::size_t compiler = element_start(out.substr(0, out.find("</mujoco", mujoco)), "compiler", mujoco);
  if (compiler != std::string::npos) {
    std::size_t end = past_tag(out, compiler);
    for (const std::string& name : names)
      if (attribute(out, compiler, end, name)) return text;
    return out.insert(compiler + 9, attributes);
  }
  std::size_t inside = past_tag(out, mujoco);
  if (inside == std::string::npos || out[inside - 2] == '/') return text;
  return out.insert(inside, "<compiler" + attributes + "/>");
}

}  // namespace eomgen
