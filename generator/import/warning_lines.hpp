/// @file Where in the robot file a warning's subject is: MuJoCo's compiled model keeps no
/// source lines, so the named element (an actuator by its name, the k-th equality constraint,
/// the tendons, the actuators) is found in the file's text. Elements that come from an
/// `<include>`d file or from defaults are not found there; their warnings stay unlocated.
#pragma once

#include <string>

namespace eomgen {

/// The 1-based line of `xml` where the subject of `warning` (as mjcf_reader words it) is
/// written, or 0 when it cannot be told.
int warning_line(const std::string& xml, const std::string& warning);

}  // namespace eomgen
