/// @file Where in the robot file a warning's subject is: MuJoCo's compiled model keeps no
/// source lines, so the element a warning is about (an actuator by its name or place, an
/// equality constraint, the tendons) is found in the file's text, or in a file it `<include>`s.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "import/robot.hpp"

namespace eomgen {

/// The 1-based line of `xml` where the subject of `warning` is written, or 0 when it cannot
/// be told.
int warning_line(const std::string& xml, const RobotWarning& warning);

/// A file and a 1-based line in it; line 0: no one place.
struct WarningPlace {
  std::string file;
  int line = 0;
};

/// Where the subject of `warning` is written among `sources`, the robot file first and then the
/// files it includes (path and text, as import/mujoco_loading.hpp's mjcf_sources gives them).
/// The robot file is searched first. An included file is searched for an element by its name, for
/// a section as a whole, and for an unnamed element by its place only when that file alone has
/// the section (the place counts across files otherwise, which the texts cannot tell).
WarningPlace warning_place(const std::vector<std::pair<std::string, std::string>>& sources, const RobotWarning& warning);

}  // namespace eomgen
