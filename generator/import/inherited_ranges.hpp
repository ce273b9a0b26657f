/// @file MuJoCo 3's inheritrange on a <position> actuator: its control range taken from its joint's or
/// fixed tendon's range, about that range's middle and scaled by the value (1: the same range), which
/// MuJoCo 2.2.2's schema refuses. The file is read with each value written as the actuator's group,
/// which MuJoCo 2.2.2 resolves through defaults and classes as MuJoCo 3 resolves inheritrange and
/// which enters nothing but MuJoCo's viewer (a position servo's user values carry its kv:
/// servo_damping.hpp), and the import forms the range from it (mjcf_reader.cpp). A group is a whole
/// number: a fractional inheritrange, or a file that groups its actuators itself, leaves inheritrange
/// out with a warning (newer_mjcf.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>

#include <mujoco/mujoco.h>

namespace eomgen {

/// Whether MuJoCo's error is its schema refusing inheritrange on a <position> actuator (or its default).
bool refuses_inheritrange(const std::string& mujoco_error);

/// The text with inheritrange="n" of every <position> tag written as group="n"; nothing where the text
/// cannot be read so (see above).
std::optional<std::string> with_inheritrange_as_group(const std::string& mjcf);

/// Actuator a's control range inherited from its joint's or fixed tendon's range, by the value MuJoCo
/// read as its group; nothing where it inherits none. `why_not` says why a value above zero gives none
/// (a joint or tendon without a range).
std::optional<std::array<double, 2>> inherited_control_range(const mjModel* m, int a, std::string& why_not);

}  // namespace eomgen
