#include "import/servo_damping.hpp"

#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_position_kv(const std::string& mujoco_error) {
  return mujoco_error.find("unrecognized attribute: 'kv'") != std::string::npos &&
         mujoco_error.find("Element 'position'") != std::string::npos;
}

bool has_user_values(const std::string& mjcf) {
  for (std::size_t at = mjcf.find('<'); at != std::string::npos; at = mjcf.find('<', at + 1)) {
    if (mjcf.compare(at, 4, "<!--") == 0) {
      at = mjcf.find("-->", at);
      if (at == std::string::npos) break;
      continue;
    }
    std::size_t end = past_tag(mjcf, at);
    if (end == std::string::npos) break;
    if (attribute_span(mjcf, at, end, "user")) return true;
  }
  return false;
}

std::string with_kv_as_user(const std::string& mjcf) {
  std::string text = mjcf;
  for (std::size_t at = element_start(text, "position"); at != std::string::npos; at = element_start(text, "position", at + 1)) {
    std::size_t end = past_tag(text, at);
    if (end == std::string::npos) break;
    if (auto span = attribute_span(text, at, end, "kv")) text.replace(span->first, 2, "user");
  }
  return text;
}

}  // namespace eomgen
