#include "import/newer_mjcf.hpp"

#include <cctype>

namespace eomgen {

namespace {

struct Known {
  const char* name;
  bool enters_equations;
  const char* consequence;
};

// attributes of MuJoCo 2.3 to 3.x seen in published robots, and what eomgen loses without them
const Known known[] = {
    {"actuatorfrcrange", true, "the clamp of a joint's total actuator force is not carried"},
    {"actuatorfrclimited", true, "the clamp of a joint's total actuator force is not carried"},
    {"actuatorgravcomp", true, "gravity compensation through the actuators is not carried"},
    {"gravcomp", true, "a body's gravity compensation is not carried"},
    {"inheritrange", true, "an actuator's control range taken from its joint's range is not carried"},
    {"dampratio", true, "a position actuator's damping given as a ratio is not carried"},
    {"kv", true, "a position actuator's velocity gain is not carried"},
    {"ls_iterations", false, "a setting of MuJoCo's constraint solver"},
    {"ls_tolerance", false, "a setting of MuJoCo's constraint solver"},
    {"noslip_tolerance", false, "a setting of MuJoCo's constraint solver"},
    {"ccd_iterations", false, "a setting of MuJoCo's collision detection"},
    {"ccd_tolerance", false, "a setting of MuJoCo's collision detection"},
    {"sdf_iterations", false, "a setting of MuJoCo's collision detection"},
    {"sdf_initpoints", false, "a setting of MuJoCo's collision detection"},
    {"eulerdamp", false, "a setting of MuJoCo's Euler integrator"},
    {"maxhullvert", false, "a setting of MuJoCo's convex hulls for contacts"},
    {"implicitfast", false, "MuJoCo's integrator (read as \"implicit\"; eomgen chooses its own)"},
};

// the name quoted after `marker` in the message, or nothing
std::optional<std::string> quoted_after(const std::string& message, const std::string& marker) {
  std::size_t at = message.find(marker);
  if (at == std::string::npos) return std::nullopt;
  std::size_t start = at + marker.size(), end = message.find('\'', start);
  if (end == std::string::npos) return std::nullopt;
  return message.substr(start, end - start);
}

}  // namespace

std::optional<NewerAttribute> newer_attribute_refused(const std::string& mujoco_error) {
  auto name = quoted_after(mujoco_error, "unrecognized attribute: '");
  if (!name) name = quoted_after(mujoco_error, "invalid keyword: '");
  if (!name) return std::nullopt;
  for (const Known& k : known)
    if (*name == k.name) return NewerAttribute{k.name, k.enters_equations, k.consequence};
  return std::nullopt;
}

std::string without_newer_attribute(const std::string& mjcf, const NewerAttribute& attribute) {
  std::string text = mjcf;
  if (attribute.name == "implicitfast") {
    for (std::size_t at = text.find("\"implicitfast\""); at != std::string::npos; at = text.find("\"implicitfast\"", at))
      text.replace(at, 14, "\"implicit\"");
    return text;
  }
  // ` name = "value"` with either quote, where the name stands alone (not the tail of another)
  for (std::size_t at = text.find(attribute.name); at != std::string::npos; at = text.find(attribute.name, at + 1)) {
    if (at == 0 || !std::isspace(static_cast<unsigned char>(text[at - 1]))) continue;
    std::size_t after = at + attribute.name.size();
    while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after])) && text[after] != '\n') ++after;
    if (after >= text.size() || text[after] != '=') continue;
    ++after;
    while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after])) && text[after] != '\n') ++after;
    if (after >= text.size() || (text[after] != '"' && text[after] != '\'')) continue;
    std::size_t close = text.find(text[after], after + 1);
    if (close == std::string::npos || text.find('\n', after) < close) continue;
    text.erase(at, close + 1 - at);
  }
  return text;
}

std::vector<std::string> included_files(const std::string& mjcf) {
  std::vector<std::string> out;
  for (std::size_t at = mjcf.find('<'); at != std::string::npos; at = mjcf.find('<', at + 1)) {
    if (mjcf.compare(at, 4, "<!--") == 0) {
      at = mjcf.find("-->", at);
      if (at == std::string::npos) break;
      continue;
    }
    if (mjcf.compare(at, 8, "<include") != 0 || at + 8 >= mjcf.size() || !std::isspace(static_cast<unsigned char>(mjcf[at + 8])))
      continue;
    std::size_t end = mjcf.find('>', at), file = mjcf.find("file", at);
    if (end == std::string::npos || file == std::string::npos || file > end) continue;
    std::size_t quote = mjcf.find_first_of("\"'", file);
    if (quote == std::string::npos || quote > end) continue;
    std::size_t close = mjcf.find(mjcf[quote], quote + 1);
    if (close == std::string::npos || close > end) continue;
    out.push_back(mjcf.substr(quote + 1, close - quote - 1));
  }
  return out;
}

}  // namespace eomgen
