#include "import/joint_force_limits.hpp"

#include <fmt/format.h>

#include "import/mjcf_reader.hpp"
#include "import/xml_text.hpp"

namespace eomgen {

namespace {

// whether the tag at `at` lies inside a <default> element (nested ones counted)
bool inside_default(const std::string& text, std::size_t at) {
  int open = 0;
  for (std::size_t d = element_start(text, "default"); d != std::string::npos && d < at; d = element_start(text, "default", d + 1)) {
    std::size_t end = past_tag(text, d);
    if (end != std::string::npos && text[end - 2] != '/') ++open;
  }
  for (std::size_t c = text.find("</default"); c != std::string::npos && c < at; c = text.find("</default", c + 1)) --open;
  return open > 0;
}

}  // namespace

bool refuses_joint_force_range(const std::string& mujoco_error) {
  bool joint = mujoco_error.find("Element 'joint'") != std::string::npos;
  return joint && (mujoco_error.find("unrecognized attribute: 'actuatorfrcrange'") != std::string::npos ||
                   mujoco_error.find("unrecognized attribute: 'actuatorfrclimited'") != std::string::npos);
}

std::optional<std::string> with_force_range_as_user(const std::string& mjcf) {
  if (any_tag_sets(mjcf, {"joint"}, "user")) return std::nullopt;
  for (std::size_t at = element_start(mjcf, "compiler"); at != std::string::npos; at = element_start(mjcf, "compiler", at + 1))
    if (attribute(mjcf, at, past_tag(mjcf, at), "autolimits").value_or("true") == "false") return std::nullopt;
  std::string text = with_attribute_renamed(mjcf, "joint", "actuatorfrcrange", "user");
  for (std::size_t at = element_start(text, "joint"); at != std::string::npos; at = element_start(text, "joint", at + 1)) {
    std::size_t end = past_tag(text, at);
    if (end == std::string::npos) break;
    bool unclamped = attribute(text, at, end, "actuatorfrclimited").value_or("auto") == "false";
    // a class that switches the clamp off for its joints, whose ranges may come from other classes
    if (unclamped && inside_default(text, at)) return std::nullopt;
    auto erase = [&](const char* name) {
      if (auto span = attribute_span(text, at, end, name)) {
        text.erase(span->first, span->second - span->first);
        end -= span->second - span->first;
      }
    };
    erase("actuatorfrclimited");
    // no clamp on this joint (a free joint's, often): zeros, whatever range its class gives
    if (unclamped) erase("user"), text.insert(at + std::string("<joint").size(), " user=\"0 0\"");
  }
  return text;
}

void read_joint_force_ranges(const mjModel* m, Robot& r) {
  if (m->nuser_jnt < 2) return;
  int limited = 0;
  for (int j = 0; j < m->njnt; ++j) {
    const double* range = m->jnt_user + m->nuser_jnt * j;
    if (range[0] == 0 && range[1] == 0) continue;
    int b = m->jnt_bodyid[j];
    RobotJoint& joint = r.bodies[std::size_t(b - 1)].joints[std::size_t(j - m->body_jntadr[b])];
    if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) {
      r.warnings.push_back({fmt::format("joint '{}': the clamp of its total actuator force (actuatorfrcrange) is carried on hinges "
                                        "and slides only",
                                        joint.name),
                            "joint", joint.name, 0});
      continue;
    }
    joint.actuator_force_limited = true;
    joint.actuator_force_range = {range[0], range[1]};
    ++limited;
  }
  if (limited > 0)
    r.notes.push_back(fmt::format("the actuator force ranges (MuJoCo 3's actuatorfrcrange) of {} joint(s) read through MuJoCo {}'s "
                                  "joint user values, which resolve defaults and classes alike: their actuators' total is clamped",
                                  limited, mj_version_text()));
}

}  // namespace eomgen
