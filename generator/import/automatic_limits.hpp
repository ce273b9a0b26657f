/// @file MuJoCo 3's default of autolimits="true" (MuJoCo 2.2.2's was "false"): a joint's or tendon's
/// range, an actuator's ctrlrange or forcerange without `limited`, `ctrllimited` or `forcelimited`
/// limits, where MuJoCo 2.2.2 refuses the file ("joint has `range` but not `limited`"). Unitree's
/// files rely on it. Such a file is read with autolimits="true" put in its <compiler>, as MuJoCo 3
/// reads it, unless one of its files sets autolimits itself (then MuJoCo's error stands, as in 3).
/// Of the limits, the import carries the clamps of the controls and actuator forces; a joint's range is
/// a constraint, not carried (mjcf_reader.cpp warns of it).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "import/robot.hpp"

namespace eomgen {

/// Whether MuJoCo's error refuses a range without its `limited` attribute, naming autolimits.
bool refuses_range_without_limited(const std::string& mujoco_error);

/// `sources` (each file's path and text; the robot's file first) with autolimits="true" in the
/// first one's <compiler>; false, and unchanged, where a file sets autolimits itself.
bool with_automatic_limits(std::vector<std::pair<std::string, std::string>>& sources);

/// The note that says so, into `r`.
void note_automatic_limits(Robot& r);

}  // namespace eomgen
