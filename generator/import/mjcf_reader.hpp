/// @file MJCF read by MuJoCo's own compiler (mj_loadXML): defaults and classes, angles in degrees,
/// every orientation form, <include>, inertias from geoms are then what MuJoCo makes of them.
#pragma once

#include <string>
#include <variant>

#include "import/mujoco_loading.hpp"
#include "import/robot.hpp"

namespace eomgen {

/// The robot of an MJCF or URDF file, or why MuJoCo cannot read it.
std::variant<Robot, UnreadableRobot> read_with_mujoco(const std::string& path, RobotReading reading = {});

/// The MuJoCo that reads the files, e.g. "2.2.2".
std::string mj_version_text();

/// Whether the file is URDF: named .urdf, or its first element <robot> (a URDF saved as .xml, a
/// xacro file).
bool is_urdf_file(const std::string& path);

}  // namespace eomgen
