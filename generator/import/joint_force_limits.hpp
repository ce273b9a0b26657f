/// @file MuJoCo 3's actuatorfrcrange on a joint (with actuatorfrclimited): the total generalized force
/// of the actuators on the joint clamped to a range, which MuJoCo 2.2.2's schema refuses. The file is
/// read with each range written as the joint's `user` values, which MuJoCo 2.2.2 resolves through
/// defaults, classes and childclass as MuJoCo 3 resolves the range, and the import clamps the sum
/// of the actuators' generalized forces on each hinge and slide so limited (transmission_text.cpp).
/// A joint that says actuatorfrclimited="false" itself (Unitree's free joints do) gets user values of
/// zero, no range, whatever its class gives. Not where the file has joint user values of its own,
/// sets actuatorfrclimited="false" in a default class or turns autolimits off: there both attributes
/// are left out with a warning (newer_mjcf.hpp).
#pragma once

#include <optional>
#include <string>

#include <mujoco/mujoco.h>

#include "import/robot.hpp"

namespace eomgen {

/// Whether MuJoCo's error is its schema refusing actuatorfrcrange or actuatorfrclimited on a joint.
bool refuses_joint_force_range(const std::string& mujoco_error);

/// The text with every joint's actuatorfrcrange written as its user values (zeros where the joint
/// says actuatorfrclimited="false") and actuatorfrclimited left out; nothing where the text cannot be
/// read so (see above).
std::optional<std::string> with_force_range_as_user(const std::string& mjcf);

/// `r`'s hinges and slides with the ranges MuJoCo read as their user values (two numbers, not both
/// zero: a joint without a range has zeros); a warning for a ball or free joint with one.
void read_joint_force_ranges(const mjModel* m, Robot& r);

}  // namespace eomgen
