/// @file MJCF read by MuJoCo's own compiler (mj_loadXML): defaults and classes, angles in degrees,
/// every orientation form, <include>, inertias from geoms are then what MuJoCo makes of them.
#pragma once

#include <string>
#include <variant>

#include "import/robot.hpp"

namespace eomgen {

/// Why MuJoCo cannot read the file: its message, and the line it names (0: none).
struct UnreadableRobot {
  int line = 0;
  std::string message;
  std::string hint;  // what to do; empty: that the file must be one MuJoCo's compiler accepts
};

/// The robot of an MJCF file, or why MuJoCo cannot read it.
std::variant<Robot, UnreadableRobot> read_with_mujoco(const std::string& path);

/// The MuJoCo that reads the files, e.g. "2.2.2".
std::string mj_version_text();

/// MuJoCo's error text as a message and a line ("line = 9", "Line number=5").
UnreadableRobot unreadable_robot(const std::string& mujoco_error);

}  // namespace eomgen
