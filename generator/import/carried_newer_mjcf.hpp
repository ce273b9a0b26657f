/// @file MuJoCo 3's attributes that eomgen carries by writing them as MuJoCo 2.2.2 reads them, where
/// 2.2.2's schema refuses them: the spring and damper flags (passive_flags.hpp), a position servo's kv
/// and a joint's actuatorfrcrange read through user values (servo_damping.hpp, joint_force_limits.hpp)
/// and a position servo's inheritrange through its group (inherited_ranges.hpp); a body's gravcomp
/// is read from the text and then left out (gravity_compensation.hpp); and MuJoCo 3's default
/// autolimits="true", set where 2.2.2 refuses a range without `limited` (automatic_limits.hpp); and the
/// <frame> element, written as a welded <body> (frame_elements.hpp). Every other newer attribute is
/// left out with a warning (newer_mjcf.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "import/mujoco_loading.hpp"

namespace eomgen {

/// Whether MuJoCo's error refuses one of them.
bool refuses_carried_attribute(const std::string& mujoco_error);

/// `sources` (each file's path and text) rewritten for the attribute MuJoCo's error refuses, and what
/// that takes recorded in `left_out`; false where they cannot be (the file's own user values, say):
/// the attribute is then left out as any newer one.
bool translate_carried_attribute(const std::string& mujoco_error, std::vector<std::pair<std::string, std::string>>& sources,
                                 LeftOut& left_out);

}  // namespace eomgen
