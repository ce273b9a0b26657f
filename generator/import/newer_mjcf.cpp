#include "import/newer_mjcf.hpp"

#include "import/xml_text.hpp"

namespace eomgen {

namespace {

struct Known {
  const char* name;
  bool enters_equations;
  const char* consequence;
};

// attributes of MuJoCo 2.3 to 3.x seen in published robots, and what eomgen loses without them
const Known known[] = {
    {"actuatorfrcrange", true,
     "the clamp of a joint's total actuator force is not carried (where the file has joint user values of its own, "
     "actuatorfrclimited=\"false\" or autolimits off: joint_force_limits.hpp)"},
    {"actuatorfrclimited", true, "the clamp of a joint's total actuator force is not carried (as for actuatorfrcrange)"},
    {"actuatorgravcomp", true,
     "the joint's gravity compensation is carried as a passive force, not through its actuators: the same unless the "
     "joint's actuatorfrcrange would clamp their sum"},
    {"inheritrange", true,
     "an actuator's control range taken from its joint's range is not carried (where the value is not a whole number or "
     "the file groups its actuators itself: inherited_ranges.hpp)"},
    {"dampratio", true, "a position actuator's damping given as a ratio is not carried"},
    {"kv", true,
     "a position actuator's velocity gain is not carried (the file's own user values leave no place to read it through: "
     "servo_damping.hpp)"},
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
  // in every tag, outside comments
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string::npos) break;
      continue;
    }
    std::size_t end = text.find('>', at);
    if (end == std::string::npos) break;
    while (auto span = attribute_span(text, at, end, attribute.name)) {
      text.erase(span->first, span->second - span->first);
      end -= span->second - span->first;
    }
  }
  return text;
}

std::vector<std::string> included_files(const std::string& mjcf) {
  std::vector<std::string> out;
  for (std::size_t at = element_start(mjcf, "include"); at != std::string::npos; at = element_start(mjcf, "include", at + 1))
    if (auto file = attribute(mjcf, at, past_tag(mjcf, at), "file")) out.push_back(*file);
  return out;
}

}  // namespace eomgen
