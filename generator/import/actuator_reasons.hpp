/// @file Why an actuator of a MuJoCo model cannot be carried. eomgen's actuator is a force affine in
/// the control, the driven coordinate and its rate (a motor, or a servo with kp and kv) on a hinge, a
/// slide or a fixed tendon of them; MuJoCo's may add states of its own (activation dynamics), take
/// its gain or bias from a muscle's curves or from user callbacks, or act through a site, a
/// slider-crank, a spatial tendon or a body's contacts. The warning names the one reason that
/// applies, so that the user knows what to rewrite.
#pragma once

#include <string>

#include <mujoco/mujoco.h>

namespace eomgen {

/// Why actuator `a` of `m` is left out, as a clause ("its activation dynamics, ..., add a state ..."),
/// or empty when it is carried.
std::string actuator_left_out_because(const mjModel* m, int a);

}  // namespace eomgen
