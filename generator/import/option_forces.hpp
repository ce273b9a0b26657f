/// @file What a file's <option> says of the forces (MuJoCo's mjOption): its flags switch gravity,
/// the passive forces (the joints' and tendons' springs and dampers, the medium's; since MuJoCo
/// 3.3.6 the springs and the dampers each by a flag of its own) and actuation off,
/// or the clamping of controls to their ranges; its density and viscosity fill the world with a
/// medium whose drag eomgen does not carry. The robot as read holds every force; this takes off
/// what the file switched off, so that the model moves as MuJoCo's mj_forward says.
#pragma once

#include <mujoco/mujoco.h>

#include "import/passive_flags.hpp"
#include "import/robot.hpp"

namespace eomgen {

/// `r` with the forces that `m`'s flags and MuJoCo 3.3.6's spring and damper flags (`passive`, which
/// 2.2.2 does not read) switch off taken away, each with a note, and a warning for a medium (density
/// or viscosity above zero while the passive forces are on).
void apply_option_forces(const mjModel* m, const PassiveSwitches& passive, Robot& r);

}  // namespace eomgen
