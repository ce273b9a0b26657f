/// @file MuJoCo's actuators as the robot's: motors and servos (a force affine in the control, the
/// driven coordinate and its rate) on a hinge, a slide or a fixed tendon of them, with their gear,
/// control and force ranges; MuJoCo 3's servo damping (kv, dampratio; servo_damping.hpp) and
/// inherited ranges (inherited_ranges.hpp) as the file was read for them. Every other actuator is
/// left out with a warning that says why (actuator_reasons.hpp).
#pragma once

#include <mujoco/mujoco.h>

#include "import/mujoco_loading.hpp"
#include "import/robot.hpp"

namespace eomgen {

/// The actuators of `m` into r.actuators, and what was left out or read otherwise into r.warnings
/// and r.notes; `left_out` says how the file was rewritten for MuJoCo 2.2.2.
void read_actuators(const mjModel* m, const LeftOut& left_out, Robot& r);

}  // namespace eomgen
