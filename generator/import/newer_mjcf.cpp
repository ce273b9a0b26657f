#include "import/newer_mjcf.hpp"

#include <algorithm>

#include "import/xml_text.hpp"

namespace eomgen {

namespace {

struct Known {
  const char* name;
  bool enters_equations;
  const char* consequence;
  const char* element = nullptr;  // the one element that has it, where the name is common (a light's type)
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
    {"dampratio", true,
     "a position actuator's damping given as a ratio is not carried (the file's own user values leave no place to read it "
     "through, or the ratio is negative: servo_damping.hpp)"},
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
    // MuJoCo 3.x's, each tried on 2.2.2
    {"island", false, "a setting of MuJoCo's constraint solver"},
    {"nativeccd", false, "a setting of MuJoCo's collision detection"},
    {"midphase", false, "a setting of MuJoCo's collision detection"},
    {"o_friction", false, "an override of MuJoCo's contact friction"},
    {"invdiscrete", false, "a setting of MuJoCo's inverse dynamics"},
    {"autoreset", false, "a setting of MuJoCo's simulation loop"},
    {"sleep", false, "a setting of MuJoCo's sleeping bodies"},
    {"sleep_tolerance", false, "a setting of MuJoCo's sleeping bodies"},
    {"memory", false, "MuJoCo's memory allocation"},
    {"saveinertial", false, "an output of MuJoCo's compiler"},
    {"assetdir", false,
     "where MuJoCo finds meshes and textures (a mesh it cannot read is then a placeholder, where no body takes its inertia "
     "from it)"},
    {"content_type", false, "a file's format named (MuJoCo 2.2.2 takes it from the file's extension)"},
    {"alignfree", true, "free joints stay in their bodies' frames, not turned to the principal axes (the same motion)"},
    {"realtime", false, "a setting of MuJoCo's viewer"},
    {"ellipsoidinertia", false, "a setting of MuJoCo's viewer"},
    {"bvactive", false, "a setting of MuJoCo's viewer"},
    {"cameraid", false, "a setting of MuJoCo's viewer"},
    {"orthographic", false, "a setting of MuJoCo's cameras"},
    {"resolution", false, "a setting of MuJoCo's cameras"},
    {"sensorsize", false, "a setting of MuJoCo's cameras"},
    {"focal", false, "a setting of MuJoCo's cameras"},
    {"focalpixel", false, "a setting of MuJoCo's cameras"},
    {"principal", false, "a setting of MuJoCo's cameras"},
    {"principalpixel", false, "a setting of MuJoCo's cameras"},
    {"bulbradius", false, "a setting of MuJoCo's lights"},
    {"intensity", false, "a setting of MuJoCo's lights"},
    {"range", false, "a setting of MuJoCo's lights", "light"},
    {"type", false, "a setting of MuJoCo's lights", "light"},
};

// MuJoCo 3's sensors, which 2.2.2's schema refuses (tried one by one); a sensor measures and never
// acts, and eomgen's import reads none
const char* const newer_sensors[] = {"jointactuatorfrc", "tendonactuatorfrc", "camprojection", "insidesite", "distance",
                                     "normal",           "fromto",            "contact",       "e_potential", "e_kinetic",
                                     "tactile"};

// the name quoted after `marker` in the message, or nothing
std::optional<std::string> quoted_after(const std::string& message, const std::string& marker) {
  std::size_t at = message.find(marker);
  if (at == std::string::npos) return std::nullopt;
  std::size_t start = at + marker.size(), end = message.find('\'', start);
  if (end == std::string::npos) return std::nullopt;
  return message.substr(start, end - start);
}

// the text without each `element` of its <sensor> sections, each replaced by its line breaks
std::string without_sensor(const std::string& mjcf, const std::string& element) {
  std::string text = mjcf;
  for (std::size_t section = element_start(text, "sensor"); section != std::string::npos;
       section = element_start(text, "sensor", section + 1)) {
    std::size_t close = text.find("</sensor", section);
    if (close == std::string::npos) break;
    for (std::size_t at = element_start(text, element, section); at != std::string::npos && at < close;
         at = element_start(text, element, at + 1)) {
      std::size_t end = past_tag(text, at);
      if (end == std::string::npos) return text;
      if (text[end - 2] != '/') {
        std::size_t closing = text.find("</" + element, end);
        if (closing == std::string::npos || closing > close) return text;
        end = past_tag(text, closing);
      }
      std::string breaks(std::size_t(std::count(text.begin() + long(at), text.begin() + long(end), '\n')), '\n');
      text.replace(at, end - at, breaks);
      close -= end - at - breaks.size();
    }
  }
  return text;
}

}  // namespace

std::optional<NewerMjcf> newer_mjcf_refused(const std::string& mujoco_error) {
  if (mujoco_error.find("unrecognized element") != std::string::npos) {
    auto element = quoted_after(mujoco_error, "Element '");
    for (const char* sensor : newer_sensors)
      if (element && *element == sensor)
        return NewerMjcf{sensor, false, "a sensor (eomgen's import reads none from any file)", true, ""};
    return std::nullopt;
  }
  auto name = quoted_after(mujoco_error, "unrecognized attribute: '");
  if (!name) name = quoted_after(mujoco_error, "invalid keyword: '");
  if (!name) return std::nullopt;
  auto element = quoted_after(mujoco_error, "Element '");
  for (const Known& k : known)
    if (*name == k.name && (!k.element || element == std::string(k.element)))
      return NewerMjcf{k.name, k.enters_equations, k.consequence, false, k.element ? k.element : ""};
  return std::nullopt;
}

std::optional<std::string> newer_element_hint(const std::string& mujoco_error) {
  if (mujoco_error.find("unrecognized element") == std::string::npos) return std::nullopt;
  auto element = quoted_after(mujoco_error, "Element '");
  if (!element) return std::nullopt;
  const std::pair<const char*, const char*> hints[] = {
      {"replicate", "MuJoCo 3's <replicate> is not carried: write its copies out as bodies"},
      {"attach", "MuJoCo 3's <attach> is not carried: write the attached model's bodies into the file"},
      {"flexcomp", "MuJoCo 3's deformable bodies (flexes) are not carried: eomgen models rigid bodies"},
      {"flex", "MuJoCo 3's deformable bodies (flexes) are not carried: eomgen models rigid bodies"},
      {"plugin", "MuJoCo's plugins are not carried: leave them out, or write what they do as forces of the model"},
      {"extension", "MuJoCo's plugins are not carried: leave them out, or write what they do as forces of the model"},
      {"instance", "MuJoCo's plugins are not carried: leave them out, or write what they do as forces of the model"},
      {"frame", "a <frame> is read as a body welded to its parent, which a joint or an <inertial> inside it would move: "
                "put them in a <body> of their own"}};
  for (const auto& [name, hint] : hints)
    if (*element == name) return std::string(hint);
  return std::nullopt;
}

std::string without_newer_mjcf(const std::string& mjcf, const NewerMjcf& attribute) {
  if (attribute.sensor) return without_sensor(mjcf, attribute.name);
  if (!attribute.element.empty()) return with_attribute_removed(mjcf, attribute.element, attribute.name);
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
