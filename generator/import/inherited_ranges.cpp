#include "import/inherited_ranges.hpp"

#include <cmath>
#include <cstdlib>

#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_inheritrange(const std::string& mujoco_error) {
  return mujoco_error.find("unrecognized attribute: 'inheritrange'") != std::string::npos &&
         mujoco_error.find("Element 'position'") != std::string::npos;
}

std::optional<std::string> with_inheritrange_as_group(const std::string& mjcf) {
  if (any_tag_sets(mjcf, mjcf_actuator_elements(), "group")) return std::nullopt;
  std::string text = mjcf;
  for (std::size_t at = element_start(text, "position"); at != std::string::npos; at = element_start(text, "position", at + 1)) {
    std::size_t end = past_tag(text, at);
    if (end == std::string::npos) break;
    std::optional<std::string> value = attribute(text, at, end, "inheritrange");
    if (!value) continue;
    char* rest = nullptr;
    double scale = std::strtod(value->c_str(), &rest);
    if (rest == value->c_str() || scale != std::floor(scale) || scale < 0 || scale > 1000) return std::nullopt;
    auto span = attribute_span(text, at, end, "inheritrange");
    text.replace(span->first, span->second - span->first, "group=\"" + std::to_string(int(scale)) + "\"");
  }
  return text;
}

std::optional<std::array<double, 2>> inherited_control_range(const mjModel* m, int a, std::string& why_not) {
  int scale = m->actuator_group[a];
  if (scale <= 0) return std::nullopt;
  int id = m->actuator_trnid[2 * a];
  const double* range = nullptr;
  bool on_joint = m->actuator_trntype[a] == mjTRN_JOINT || m->actuator_trntype[a] == mjTRN_JOINTINPARENT;
  if (on_joint && m->jnt_limited[id]) range = m->jnt_range + 2 * id;
  if (m->actuator_trntype[a] == mjTRN_TENDON && m->tendon_limited[id]) range = m->tendon_range + 2 * id;
  if (!range) {
    why_not = "its joint or tendon has no range to inherit (MuJoCo 3 refuses the file)";
    return std::nullopt;
  }
  double middle = (range[0] + range[1]) / 2, half = scale * (range[1] - range[0]) / 2;
  return std::array<double, 2>{middle - half, middle + half};
}

}  // namespace eomgen
