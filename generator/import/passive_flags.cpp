#include "import/passive_flags.hpp"

#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_passive_flag(const std::string& mujoco_error) {
  bool flag = mujoco_error.find("Element 'flag'") != std::string::npos;
  return flag && (mujoco_error.find("unrecognized attribute: 'spring'") != std::string::npos ||
                  mujoco_error.find("unrecognized attribute: 'damper'") != std::string::npos);
}

PassiveSwitches translate_passive_flags(std::string& mjcf) {
  PassiveSwitches switches;
  std::size_t first = std::string::npos;  // the first <flag> that states either, for passive="disable"
  for (std::size_t at = element_start(mjcf, "flag"); at != std::string::npos; at = element_start(mjcf, "flag", at + 1)) {
    std::size_t end = past_tag(mjcf, at);
    if (end == std::string::npos) break;
    for (const char* name : {"spring", "damper"}) {
      auto value = attribute(mjcf, at, end, name);
      auto span = attribute_span(mjcf, at, end, name);
      if (!value || !span) continue;
      if (*value == "disable") (std::string(name) == "spring" ? switches.springs_off : switches.dampers_off) = true;
      mjcf.erase(span->first, span->second - span->first);
      end -= span->second - span->first;
      if (first == std::string::npos) first = at;
    }
  }
  if (switches.all_off() && first != std::string::npos) mjcf.insert(first + 5, " passive=\"disable\"");
  return switches;
}

}  // namespace eomgen
