/// @file MJCF written for a later MuJoCo than the 2.2.2 that reads it (mujoco_menagerie's and
/// Unitree's files are MuJoCo 3's): the attributes and sensors 2.2.2's schema refuses that are
/// known, left out one by one with what that costs, so that the rest of the robot is still read.
/// An attribute or element not in the lists (a typo, say) stays MuJoCo's error.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace eomgen {

struct NewerMjcf {
  std::string name;          // e.g. "actuatorfrcrange"; "implicitfast" for that integrator; a sensor's element
  bool enters_equations;     // false: a solver or integrator setting of MuJoCo's own, or a sensor
  std::string consequence;   // what leaving it out means, for the warning
  bool sensor = false;       // an element of <sensor>, not an attribute
  std::string element = {};  // the one element whose attribute it is ("light" for its type), or any
};

/// The newer attribute or sensor that MuJoCo's error names ("unrecognized attribute: 'X'", "invalid
/// keyword: 'implicitfast'", "unrecognized element" of Element 'X'), when it is one of the known ones.
std::optional<NewerMjcf> newer_mjcf_refused(const std::string& mujoco_error);

/// The MJCF text without the attribute wherever it is set (integrator="implicitfast" becomes
/// MuJoCo 2.2.2's "implicit"), or without every such sensor of its <sensor> sections; nothing else
/// moves, line breaks included.
std::string without_newer_mjcf(const std::string& mjcf, const NewerMjcf& attribute);

/// What to do about an element of a later MuJoCo that MuJoCo's error refuses and that eomgen does not
/// carry (<replicate>, <attach>, flexes, plugins; a <frame> that holds a joint), for the error's hint;
/// nothing for any other error.
std::optional<std::string> newer_element_hint(const std::string& mujoco_error);

/// The files an MJCF text includes (<include file="..."/>, outside comments), as written, in order.
std::vector<std::string> included_files(const std::string& mjcf);

}  // namespace eomgen
