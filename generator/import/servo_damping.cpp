#include "import/servo_damping.hpp"

#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_position_kv(const std::string& mujoco_error) {
  return mujoco_error.find("unrecognized attribute: 'kv'") != std::string::npos &&
         mujoco_error.find("Element 'position'") != std::string::npos;
}

bool has_actuator_user_values(const std::string& mjcf) {
  return any_tag_sets(mjcf, mjcf_actuator_elements(), "user");
}

std::string with_kv_as_user(const std::string& mjcf) { return with_attribute_renamed(mjcf, "position", "kv", "user"); }

}  // namespace eomgen
