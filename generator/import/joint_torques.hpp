/// @file Inputs for a robot's joints at import (`eomgen import --joint-torques`): a URDF robot has
/// no actuators that MuJoCo reads (`<transmission>` is not read), so its model would have no
/// inputs; a torque or force on every hinge and slide, as Pinocchio's τ, makes it one to control.
#pragma once

#include <string>

#include "import/robot.hpp"

namespace eomgen {

/// A motor of gain 1 on every hinge and slide of `r`, named tau_JOINT, after the robot's own
/// actuators. `urdf` (empty for MJCF): its joints that mimic another get none (they have no
/// coordinate of their own), and a joint's `<limit effort>` is said beside its input, not enforced.
void add_joint_torques(const std::string& urdf, Robot& r);

}  // namespace eomgen
