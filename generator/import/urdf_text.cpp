#include "import/urdf_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "import/xml_text.hpp"

namespace eomgen {

namespace {

// a <joint> of a type URDF does not have (MuJoCo 2.2.2's reader crashes on it)
UrdfTextMistake unknown_joint_type(const std::string& urdf) {
  static const char* const types[] = {"revolute", "continuous", "prismatic", "fixed", "floating", "planar"};
  for (std::size_t at = element_start(urdf, "joint"); at != std::string::npos; at = element_start(urdf, "joint", at + 1)) {
    std::size_t end = urdf.find('>', at);
    if (end == std::string::npos) break;
    // a <transmission>'s <joint> names a joint and has no type
    if (auto type = attribute(urdf, at, end, "type"); type && std::find(std::begin(types), std::end(types), *type) == std::end(types))
      return {line_of(urdf, at),
              fmt::format("joint type '{}' is not URDF's: use revolute, continuous, prismatic, fixed, floating or planar", *type), ""};
  }
  return {};
}

// a <mass value> below zero (MuJoCo says only that a moving body's mass is too small, with no line)
UrdfTextMistake negative_mass(const std::string& urdf) {
  for (std::size_t at = element_start(urdf, "mass"); at != std::string::npos; at = element_start(urdf, "mass", at + 1)) {
    std::size_t end = urdf.find('>', at);
    if (end == std::string::npos) break;
    auto value = attribute(urdf, at, end, "value");
    if (value && std::strtod(value->c_str(), nullptr) < 0)
      return {line_of(urdf, at), fmt::format("a link's mass is {}: a mass is positive, or 0 for a link that only marks a place", *value), ""};
  }
  return {};
}

// joints whose child links lead back to where they started (MuJoCo says "URDF body not found")
UrdfTextMistake cycle(const std::string& urdf) {
  struct Edge {
    std::string joint, parent;
    int line;
  };
  std::map<std::string, Edge> parent_of;  // by child link
  for (const UrdfJoint& j : urdf_joints(urdf))
    if (!j.parent.empty() && !j.child.empty()) parent_of.emplace(j.child, Edge{j.name.empty() ? "?" : j.name, j.parent, j.line});
  for (const auto& [link, edge] : parent_of) {
    std::string path = "'" + edge.joint + "'", up = edge.parent;
    for (std::size_t steps = 0; steps <= parent_of.size(); ++steps) {
      if (up == link)
        return {edge.line, fmt::format("the joints {} lead from link '{}' back to itself: a robot's links form a tree", path, link), ""};
      auto next = parent_of.find(up);
      if (next == parent_of.end()) break;
      path += ", '" + next->second.joint + "'";
      up = next->second.parent;
    }
  }
  return {};
}

// where `needle` first stands outside the text's comments, or npos
std::size_t find_outside_comments(const std::string& text, const std::string& needle) {
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) {
    std::size_t opened = text.rfind("<!--", at);
    if (opened == std::string::npos || text.find("-->", opened) < at) return at;
  }
  return std::string::npos;
}

// a xacro element or a ${...} expression outside comments: the first of them (xacro's output keeps
// the namespace declaration and often comments out macros, so neither of those tells)
UrdfTextMistake xacro_macros(const std::string& urdf, const std::string& file) {
  std::size_t at = std::min(find_outside_comments(urdf, "<xacro:"), find_outside_comments(urdf, "${"));
  if (at == std::string::npos) return {};
  std::string expanded = std::filesystem::path(file).stem().string();
  if (std::filesystem::path(expanded).extension() == ".urdf") expanded = std::filesystem::path(expanded).stem().string();
  return {line_of(urdf, at), "the file is xacro, ROS's macro language for URDF (<xacro:property>, ${...}): a URDF reader does not expand it",
          fmt::format("expand it first with ROS's xacro tool, `xacro {} > {}.urdf`, then give eomgen {}.urdf",
                      std::filesystem::path(file).filename().string(), expanded, expanded)};
}

// a joint whose parent or child is no <link> of the file (MuJoCo says "URDF joint parent or child
// missing", without the name)
UrdfTextMistake missing_link(const std::string& urdf) {
  std::set<std::string> links;
  for (std::size_t at = element_start(urdf, "link"); at != std::string::npos; at = element_start(urdf, "link", at + 1))
    if (auto name = attribute(urdf, at, urdf.find('>', at), "name")) links.insert(*name);
  for (const UrdfJoint& j : urdf_joints(urdf))
    for (const auto& [role, link] : {std::pair{"parent", j.parent}, std::pair{"child", j.child}})
      if (!link.empty() && !links.count(link))
        return {j.line, fmt::format("joint '{}' names the {} link '{}', which the file has no <link> of", j.name, role, link), ""};
  return {};
}

}  // namespace

std::vector<UrdfJoint> urdf_joints(const std::string& urdf) {
  std::vector<UrdfJoint> joints;
  for (std::size_t at = element_start(urdf, "joint"); at != std::string::npos; at = element_start(urdf, "joint", at + 1)) {
    std::size_t close = urdf.find("</joint", at), parent = element_start(urdf, "parent", at), child = element_start(urdf, "child", at);
    // a <transmission>'s <joint> names a joint and has neither parent nor child
    if (close == std::string::npos || parent > close || child > close) continue;
    std::size_t end = urdf.find('>', at);
    UrdfJoint j{attribute(urdf, at, end, "name").value_or(""), attribute(urdf, at, end, "type").value_or(""),
                attribute(urdf, parent, urdf.find('>', parent), "link").value_or(""),
                attribute(urdf, child, urdf.find('>', child), "link").value_or(""), line_of(urdf, at), {0, 0, 0}, {0, 0, 0},
                std::nullopt};
    if (std::size_t origin = element_start(urdf, "origin", at); origin < close) {
      std::size_t origin_end = past_tag(urdf, origin);
      j.xyz = triple_attribute(urdf, origin, origin_end, "xyz");
      j.rpy = triple_attribute(urdf, origin, origin_end, "rpy");
    }
    if (std::size_t limit = element_start(urdf, "limit", at); limit < close)
      if (auto effort = attribute(urdf, limit, past_tag(urdf, limit), "effort")) {
        char* rest = nullptr;
        double value = std::strtod(effort->c_str(), &rest);
        if (rest != effort->c_str()) j.effort = value;
      }
    joints.push_back(j);
  }
  return joints;
}

UrdfTextMistake urdf_text_mistake(const std::string& urdf, const std::string& file) {
  if (UrdfTextMistake m = xacro_macros(urdf, file); m.line > 0) return m;
  for (auto check : {unknown_joint_type, negative_mass, missing_link, cycle})
    if (UrdfTextMistake m = check(urdf); m.line > 0) return m;
  return {};
}

int urdf_joint_count(const std::string& urdf, const std::string& type) {
  int count = 0;
  for (std::size_t at = element_start(urdf, "joint"); at != std::string::npos; at = element_start(urdf, "joint", at + 1))
    if (std::size_t end = urdf.find('>', at); end != std::string::npos && attribute(urdf, at, end, "type") == type) ++count;
  return count;
}

std::vector<UrdfMimic> urdf_mimics(const std::string& urdf) {
  std::vector<UrdfMimic> out;
  for (std::size_t at = element_start(urdf, "joint"); at != std::string::npos; at = element_start(urdf, "joint", at + 1)) {
    std::size_t close = urdf.find("</joint", at), mimic = element_start(urdf, "mimic", at);
    if (close == std::string::npos || mimic == std::string::npos || mimic > close) continue;
    std::size_t end = urdf.find('>', mimic);
    auto name = attribute(urdf, at, urdf.find('>', at), "name");
    auto mimicked = attribute(urdf, mimic, end, "joint");
    if (!name || !mimicked) continue;
    UrdfMimic m{*name, *mimicked, 1, 0, line_of(urdf, at)};
    if (auto v = attribute(urdf, mimic, end, "multiplier")) m.multiplier = std::strtod(v->c_str(), nullptr);
    if (auto v = attribute(urdf, mimic, end, "offset")) m.offset = std::strtod(v->c_str(), nullptr);
    out.push_back(m);
  }
  return out;
}

bool is_urdf_path(const std::string& path) {
  if (path.size() < 5) return false;
  std::string tail = path.substr(path.size() - 5);
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return tail == ".urdf";
}

bool has_robot_root(const std::string& text) {
  // past the declaration, comments and other <?...?> or <!...> parts
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string::npos) return false;
      continue;
    }
    if (at + 1 < text.size() && (text[at + 1] == '?' || text[at + 1] == '!')) continue;
    return text.compare(at, 6, "<robot") == 0 && at + 6 < text.size() &&
           (std::isspace(static_cast<unsigned char>(text[at + 6])) || text[at + 6] == '>');
  }
  return false;
}

std::string without_mesh_geometry(const std::string& urdf, int& left_out) {
  std::string text = urdf;
  left_out = 0;
  for (const char* name : {"visual", "collision"}) {
    std::string closing = fmt::format("</{}", name);
    for (std::size_t at = element_start(text, name); at != std::string::npos; at = element_start(text, name, at + 1)) {
      std::size_t open_end = text.find('>', at);
      if (open_end == std::string::npos || text[open_end - 1] == '/') continue;
      std::size_t close = text.find(closing, open_end), end = close == std::string::npos ? close : past_tag(text, close);
      if (end == std::string::npos) break;
      std::size_t mesh = element_start(text, "mesh", open_end);
      if (mesh == std::string::npos || mesh > close) continue;
      std::string breaks(std::size_t(std::count(text.begin() + long(at), text.begin() + long(end), '\n')), '\n');
      text.replace(at, end - at, breaks);
      ++left_out;
    }
  }
  return text;
}

std::string with_static_links_kept(const std::string& urdf) {
  if (element_start(urdf, "robot") == std::string::npos || urdf.find("fusestatic") != std::string::npos ||
      urdf_joint_count(urdf, "floating") > 0)
    return urdf;
  return with_compiler_attributes(urdf, " fusestatic=\"false\"", {"fusestatic"});
}

std::string with_own_fusestatic_off(const std::string& urdf) {
  std::string text = urdf;
  for (std::size_t at = element_start(text, "compiler"); at != std::string::npos; at = element_start(text, "compiler", at + 1)) {
    std::size_t end = past_tag(text, at);
    if (attribute(text, at, end, "fusestatic") != "true") continue;
    if (auto span = attribute_span(text, at, end, "fusestatic")) text.replace(span->first, span->second - span->first, "fusestatic=\"false\"");
  }
  return text;
}

std::string without_masses_from_geometry(const std::string& urdf) {
  if (element_start(urdf, "robot") == std::string::npos) return urdf;
  return with_compiler_attributes(urdf, " inertiafromgeom=\"false\"", {"inertiafromgeom"});
}

std::vector<std::string> colliding_links_without_inertial(const std::string& urdf) {
  std::vector<std::string> links;
  for (std::size_t at = element_start(urdf, "link"); at != std::string::npos; at = element_start(urdf, "link", at + 1)) {
    std::size_t open_end = past_tag(urdf, at);
    if (open_end == std::string::npos || urdf[open_end - 2] == '/') continue;
    std::size_t close = urdf.find("</link", open_end);
    std::optional<std::string> name = attribute(urdf, at, open_end, "name");
    if (!name || close == std::string::npos || element_start(urdf, "inertial", open_end) < close) continue;
    if (element_start(urdf, "collision", open_end) < close) links.push_back(*name);
  }
  return links;
}

}  // namespace eomgen
