/// @file Moving bodies without mass or inertia: a URDF's dummy link between the joints of a two- or
/// three-axis hip or wrist, an MJCF body that only carries a joint. MuJoCo's compiler refuses them
/// ("mass and inertia of moving bodies must be larger than mjMINVAL"), though the robot's M is
/// regular when bodies with mass hang below them, as eomgen's recursions take it. Such a file is read
/// again with MuJoCo's compiler raising every mass and principal moment of inertia to a bound no
/// real body has (boundmass, boundinertia), and what was raised to it is taken back to exactly 0.
#pragma once

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "import/robot.hpp"

namespace eomgen {

/// Just above MuJoCo's mjMINVAL (1e-15), so that the raised bodies pass its check.
inline constexpr double massless_bound = 2e-15;

/// Whether MuJoCo's message is its refusal of a moving body without mass or inertia, and the robot's
/// `texts` (an MJCF file's own and those it includes) give no mass or density below zero (which the
/// bounds would hide: that refusal stands).
bool refuses_massless_bodies(const std::string& message, const std::vector<std::string>& texts);

/// The file's text with its compiler's boundmass and boundinertia set to massless_bound: in its
/// <compiler>, or a <compiler> added first in its <mujoco> (a URDF: a <mujoco> added first in <robot>).
/// The text unchanged when it sets either bound itself.
std::string with_mass_bounds(const std::string& text);

/// A joint that, with the bounds taken back, moves nothing with mass or inertia (its diagonal entry
/// of M at qpos0 is of the bounds' size): its name, or empty when every joint moves some mass. M
/// would be singular; such a robot stays refused.
std::string joint_moving_no_mass(const mjModel* model);

/// The 1-based line of the file's `text` where an element named `name` stands (0: not found).
int line_naming(const std::string& text, const std::string& name);

/// The bodies' masses and principal moments at the bound back to 0; the names of the moving bodies
/// (with joints) that had one there.
std::vector<std::string> without_mass_bounds(std::vector<RobotBody>& bodies);

}  // namespace eomgen
