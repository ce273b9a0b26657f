#include "import/carried_newer_mjcf.hpp"

#include <algorithm>
#include <optional>

#include "import/automatic_limits.hpp"
#include "import/frame_elements.hpp"
#include "import/gravity_compensation.hpp"
#include "import/inherited_ranges.hpp"
#include "import/joint_force_limits.hpp"
#include "import/passive_flags.hpp"
#include "import/servo_damping.hpp"
#include "import/xml_text.hpp"

namespace eomgen {

namespace {

// every text rewritten by `rewrite`, or none where it cannot rewrite one
template <class Rewrite>
bool rewrite_every_source(std::vector<std::pair<std::string, std::string>>& sources, Rewrite rewrite) {
  std::vector<std::optional<std::string>> texts;
  for (const auto& source : sources) texts.push_back(rewrite(source.second));
  if (!std::all_of(texts.begin(), texts.end(), [](const auto& t) { return t.has_value(); })) return false;
  for (std::size_t k = 0; k < sources.size(); ++k) sources[k].second = *texts[k];
  return true;
}

bool translate_flags_of_every_source(std::vector<std::pair<std::string, std::string>>& sources, PassiveSwitches& switches) {
  bool edited = false;
  for (auto& source : sources) {
    std::string before = source.second;
    PassiveSwitches found = translate_passive_flags(source.second);
    edited = edited || source.second != before;
    switches.springs_off = switches.springs_off || found.springs_off;
    switches.dampers_off = switches.dampers_off || found.dampers_off;
  }
  return edited;
}

// the bodies' parts read, then the attribute left out of every <body>
bool read_and_leave_out_gravcomp(std::vector<std::pair<std::string, std::string>>& sources, GravityCompensations& found) {
  bool edited = false;
  for (std::size_t k = 0; k < sources.size(); ++k) {
    std::string& text = sources[k].second;
    read_gravity_compensations(text, k, found);
    std::string without = with_attribute_removed(text, "body", "gravcomp");
    edited = edited || without != text;
    text = without;
  }
  return edited;
}

}  // namespace

bool refuses_carried_attribute(const std::string& mujoco_error) {
  return refuses_passive_flag(mujoco_error) || refuses_position_damping(mujoco_error) || refuses_joint_force_range(mujoco_error) ||
         refuses_inheritrange(mujoco_error) || refuses_gravcomp(mujoco_error) || refuses_range_without_limited(mujoco_error) ||
         refuses_frame_element(mujoco_error);
}

bool translate_carried_attribute(const std::string& mujoco_error, std::vector<std::pair<std::string, std::string>>& sources,
                                 LeftOut& left_out) {
  if (refuses_passive_flag(mujoco_error)) return translate_flags_of_every_source(sources, left_out.passive_flags);
  if (refuses_position_damping(mujoco_error) && !left_out.servo_damping_as_user) {
    auto damping = [](const std::string& text) -> std::optional<std::string> {
      if (has_actuator_user_values(text)) return std::nullopt;
      return with_servo_damping_as_user(text);
    };
    return left_out.servo_damping_as_user = rewrite_every_source(sources, damping);
  }
  // once the ranges cannot be read, neither attribute is (actuatorfrclimited="false" in a class, say)
  if (refuses_joint_force_range(mujoco_error) && !left_out.force_range_as_user && !left_out.force_range_left_out) {
    left_out.force_range_as_user = rewrite_every_source(sources, with_force_range_as_user);
    left_out.force_range_left_out = !left_out.force_range_as_user;
    return left_out.force_range_as_user;
  }
  if (refuses_gravcomp(mujoco_error)) return read_and_leave_out_gravcomp(sources, left_out.gravity_compensation);
  if (refuses_inheritrange(mujoco_error) && !left_out.inheritrange_as_group)
    return left_out.inheritrange_as_group = rewrite_every_source(sources, with_inheritrange_as_group);
  if (refuses_range_without_limited(mujoco_error) && !left_out.automatic_limits)
    return left_out.automatic_limits = with_automatic_limits(sources);
  if (refuses_frame_element(mujoco_error) && left_out.frames_as_bodies == 0) {
    int frames = 0;
    for (const auto& source : sources) frames += frame_elements(source.second);
    if (frames == 0 || !rewrite_every_source(sources, with_frames_as_bodies)) return false;
    left_out.frames_as_bodies = frames;
    return true;
  }
  return false;
}

}  // namespace eomgen
