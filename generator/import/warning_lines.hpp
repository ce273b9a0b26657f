/// @file Where in the robot file a warning's subject is: MuJoCo's compiled model keeps no
/// source lines, so the element a warning is about (an actuator by its name or place, an
/// equality constraint, the tendons) is found in the file's text. Elements that come from an
/// `<include>`d file are not found there; their warnings stay unlocated.
#pragma once

#include <string>

#include "import/robot.hpp"

namespace eomgen {

/// The 1-based line of `xml` where the subject of `warning` is written, or 0 when it cannot
/// be told.
int warning_line(const std::string& xml, const RobotWarning& warning);

}  // namespace eomgen
