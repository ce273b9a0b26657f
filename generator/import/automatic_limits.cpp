#include "import/automatic_limits.hpp"

#include <algorithm>

#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_range_without_limited(const std::string& mujoco_error) {
  return mujoco_error.find("autolimits=\"true\"") != std::string::npos && mujoco_error.find("but not") != std::string::npos;
}

bool with_automatic_limits(std::vector<std::pair<std::string, std::string>>& sources) {
  if (sources.empty() || std::any_of(sources.begin(), sources.end(), [](const auto& source) {
        return any_tag_sets(source.second, {"compiler"}, "autolimits");
      }))
    return false;
  std::string with = with_compiler_attributes(sources[0].second, " autolimits=\"true\"", {"autolimits"});
  if (with == sources[0].second) return false;
  sources[0].second = with;
  return true;
}

void note_automatic_limits(Robot& r) {
  r.notes.push_back("ranges without `limited`, `ctrllimited` or `forcelimited` limit, as MuJoCo 3 reads them (its default "
                    "autolimits=\"true\", which MuJoCo 2.2.2 lacks, set in the <compiler>): the controls and actuator forces "
                    "so ranged are clamped");
}

}  // namespace eomgen
