/// @file A URDF robot given a floating base at import (`eomgen import --free-base`): URDF
/// describes a robot fixed to the world by its root link, and a floating base (a humanoid, a
/// quadruped, a drone) is what the reader adds, as Pinocchio's JointModelFreeFlyer does. MuJoCo's
/// URDF reader makes a `floating` joint from a link named `world` a free joint (position, unit
/// quaternion, angular velocity), so the root link is hung from such a joint in the text.
#pragma once

#include <string>

namespace eomgen {

/// The URDF text with `<link name="world"/>` and a floating joint from it to the root link (the
/// one link that is no joint's child), inserted just after the <robot> tag on its line, so that
/// every line keeps its number; the joint is named `root` (or `root_2`, … when a joint has that
/// name). A robot whose root is the world itself and which hangs from it by one fixed joint (a
/// UR arm's world -> base_link) gets that joint made floating instead, with a note saying so. Or,
/// with the text unchanged, the located reason it cannot be: a robot that already has a floating
/// joint, or whose world holds several links or one by a joint that moves, or that has no single
/// root link.
struct FreeBase {
  std::string text;
  std::string joint;  // the floating joint's name
  int line = 0;       // where the problem is, when there is one
  std::string problem, hint;
  std::string note;   // how the base was set free, when not by a new joint
};
FreeBase with_free_base(const std::string& urdf);

}  // namespace eomgen
