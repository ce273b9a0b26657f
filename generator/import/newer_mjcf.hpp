/// @file MJCF written for a later MuJoCo than the 2.2.2 that reads it (mujoco_menagerie's files are
/// MuJoCo 3's): the attributes 2.2.2's schema refuses that are known, left out one by one with
/// what that costs, so that the rest of the robot is still read. An attribute not in the list (a
/// typo, say) stays MuJoCo's error.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace eomgen {

struct NewerAttribute {
  std::string name;          // e.g. "actuatorfrcrange"; "implicitfast" for that integrator
  bool enters_equations;     // false: a solver or integrator setting of MuJoCo's own
  std::string consequence;   // what leaving it out means, for the warning
};

/// The newer attribute that MuJoCo's error names ("unrecognized attribute: 'X'", "invalid keyword:
/// 'implicitfast'"), when it is one of the known ones.
std::optional<NewerAttribute> newer_attribute_refused(const std::string& mujoco_error);

/// The MJCF text without the attribute wherever it is set (integrator="implicitfast" becomes
/// MuJoCo 2.2.2's "implicit"); nothing else moves, line breaks included.
std::string without_newer_attribute(const std::string& mjcf, const NewerAttribute& attribute);

/// The files an MJCF text includes (<include file="..."/>, outside comments), as written, in order.
std::vector<std::string> included_files(const std::string& mjcf);

}  // namespace eomgen
