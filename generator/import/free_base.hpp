/// @file A URDF or MJCF robot given a floating base at import (`eomgen import --free-base`): URDF
/// describes a robot fixed to the world by its root link, and a floating base (a humanoid, a
/// quadruped, a drone) is what the reader adds, as Pinocchio's JointModelFreeFlyer does; an MJCF
/// file written for a fixed base (its base a body without joints) floats the same way, without
/// editing it to add <freejoint/>. The free joint has MuJoCo's layout (position, unit quaternion,
/// angular velocity).
#pragma once

#include <optional>
#include <string>

#include "import/robot.hpp"

namespace eomgen {

/// The link of a URDF robot that floats, and the name of its free joint: the root link (the one
/// link that is no joint's child), its joint named `root` (or `root_2`, … when a joint has that
/// name). A robot mounted on a link named world by one fixed joint (a UR arm's world -> base_link)
/// floats by that joint: the mounted link, the joint's name, and a note saying so. Or the located
/// reason it cannot be: a robot that already has a floating joint, or whose world holds several
/// links or one by a joint that moves, or that has no single root link.
///
/// The text itself is read as it is, on its fixed base: MuJoCo's reader would fuse every fixed
/// link of a robot with a floating joint (it puts a free joint at the top level only, so the link
/// the joint hangs from must join the world), and a quadruped's feet, a tool flange or a sensor
/// mount would lose their names. The import gives the floating link's body the free joint after.
struct FreeBase {
  std::string link;   // the link that floats
  int link_line = 0;  // where the file writes it
  std::string joint;  // its free joint's name
  int line = 0;       // where the problem is, when there is one
  std::string problem, hint;
  std::string note;   // how the base was set free, when not by a new joint
};
FreeBase free_base_of(const std::string& urdf);

/// The body of an MJCF robot that floats, as MuJoCo read it (`r`, `mjcf` the file's text for the
/// lines): the one body in <worldbody> without joints that carries bodies with joints (the robot's
/// base; a lone body without joints when none carries any), its free joint named as free_base_of
/// names it. Or the located reason it cannot be: a body there that floats already, a base that a
/// joint holds to the world, several bases.
FreeBase free_base_of_mjcf(const Robot& r, const std::string& mjcf);

/// The floating link's body, at the top of the robot as read on its fixed base, given the free joint
/// first, starting where the body sits (as MuJoCo's free joints start at their body's place, qpos0);
/// false when no body at the top has the link's name.
bool set_free(Robot& r, const FreeBase& freed);

/// Why the robot set free has a singular M, or nothing: its floating link, with the links fixed to
/// it, has neither mass nor moment of inertia and carries one link by a joint, which then turns or
/// slides that link as the free joint does, so that the free joint's motion along it moves nothing
/// (a massless pelvis link above a single hip). With more links below, their joints' axes differ.
std::optional<std::string> massless_free_base(const Robot& r, const FreeBase& freed);

}  // namespace eomgen
