/// @file MuJoCo 3's kv on a <position> actuator: its velocity gain, the servo's force then
/// kp (u − q) − kv q' (MuJoCo 2.2.2's position servo has kp alone, and its schema refuses kv). The file
/// is read with each kv written as the actuator's `user` value, which MuJoCo 2.2.2 resolves through
/// defaults and classes as MuJoCo 3 resolves kv, and the import takes it from actuator_user
/// (mjcf_reader.cpp). A file with user values of its own keeps them: its kv is then left out with a
/// warning (newer_mjcf.hpp).
#pragma once

#include <string>

namespace eomgen {

/// Whether MuJoCo's error is its schema refusing kv on a <position> actuator (or its default).
bool refuses_position_kv(const std::string& mujoco_error);

/// Whether an actuator of the text (or an actuator default) sets `user`: then kv cannot borrow it.
bool has_actuator_user_values(const std::string& mjcf);

/// The text with kv="..." of every <position> tag (outside comments) written as user="...".
std::string with_kv_as_user(const std::string& mjcf);

}  // namespace eomgen
