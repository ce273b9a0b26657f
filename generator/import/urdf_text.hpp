/// @file A URDF's text before MuJoCo's compiler reads it: its links fixed to their parents kept as
/// bodies of their own, the mistakes its reader would crash on found first, and what it ignores
/// read here (a joint's <mimic>). Fixed links: MuJoCo's URDF reader
/// fuses such a link into its parent (compiler fusestatic, on by default for URDF), and its name
/// goes with it: a tool flange or a camera mount a user would want as a frame and a point.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace eomgen {

/// The URDF text with `<mujoco><compiler fusestatic="false"/></mujoco>` in its <robot> (or the
/// attribute added to the file's own <mujoco><compiler>), unless the file sets fusestatic itself
/// or has a floating joint: MuJoCo puts a free joint at the top level only, so the massless link
/// a floating base hangs from must be fused into the world.
/// Nothing is inserted on a new line, so MuJoCo's line numbers stay those of the file.
std::string with_static_links_kept(const std::string& urdf);

/// The URDF text with a `fusestatic="true"` of its own <mujoco><compiler> turned to "false", on the
/// same line: a robot set free at import (free_base.hpp) is read on its fixed base, where MuJoCo
/// would fuse its root link into the world, and the free joint then has no body to move; eomgen
/// folds fixed links itself, so the dynamics are the same.
std::string with_own_fusestatic_off(const std::string& urdf);

/// The URDF text with MuJoCo's compiler told to take no mass from geometry (inertiafromgeom
/// "false", added as with_static_links_kept() adds its attribute), unless the file sets it itself.
/// URDF gives a link without <inertial> no mass (urdfdom, KDL, Pinocchio, Drake); MuJoCo's default
/// gives it the mass of its collision shapes at the density of water (a force-torque sensor's
/// cylinder of 4 cm by 6 cm weighs 0.30 kg), which were only meant to collide.
std::string without_masses_from_geometry(const std::string& urdf);

/// The links of the URDF text without an <inertial> but with a <collision> shape: those whose mass
/// MuJoCo alone would take from their shapes (it discards a URDF's <visual> ones).
std::vector<std::string> colliding_links_without_inertial(const std::string& urdf);

/// The URDF text without the <visual> and <collision> elements whose geometry is a <mesh>, each
/// replaced by the line breaks it had (so that line numbers stay the file's), and how many went:
/// for a URDF whose meshes MuJoCo 2.2.2 cannot read (COLLADA .dae, package:// paths, files not
/// beside it). The dynamics come from each link's <inertial>; the shapes only draw and collide.
std::string without_mesh_geometry(const std::string& urdf, int& left_out);

/// A mistake MuJoCo 2.2.2's URDF reader does not survive, found in the text before it reads it:
/// xacro's macros (`<xacro:property>`, `${l/2}`: ROS's macro language, which a URDF reader does not
/// expand), a <joint> whose type is none of URDF's (the reader crashes on it), a negative mass and a
/// cycle of joints (which it reports without a line, or misnamed). Line and message, or line 0 when
/// there is none; `file` names the file in a hint.
struct UrdfTextMistake {
  int line = 0;
  std::string message;
  std::string hint;  // when MuJoCo's own words would not help
};
UrdfTextMistake urdf_text_mistake(const std::string& urdf, const std::string& file);

/// A joint that follows another, <mimic joint="K" multiplier="m" offset="o"/>: q = m q_K + o
/// (MuJoCo 2.2.2's URDF reader ignores it). `line` is the joint's.
struct UrdfMimic {
  std::string joint, mimicked;
  double multiplier = 1, offset = 0;
  int line = 0;
};
std::vector<UrdfMimic> urdf_mimics(const std::string& urdf);

/// A <joint> of the robot (one with a <parent> and a <child>; a <transmission>'s <joint> only names
/// one): its name, type, parent and child links ("" where the text has none) and its line.
struct UrdfJoint {
  std::string name, type, parent, child;
  int line = 0;
  std::array<double, 3> xyz{0, 0, 0}, rpy{0, 0, 0};  // its <origin>: the child's frame in the parent's
  std::optional<double> effort;                      // its <limit effort>: the largest torque or force
};
std::vector<UrdfJoint> urdf_joints(const std::string& urdf);

/// How many of the URDF's joints are of this type ("floating", "fixed", ...).
int urdf_joint_count(const std::string& urdf, const std::string& type);

/// Whether the path names a URDF file (.urdf, any case).
bool is_urdf_path(const std::string& path);

/// Whether the text's first element is <robot>: URDF, whatever the file is called (MuJoCo's
/// compiler tells the two apart by it too), a xacro file among them.
bool has_robot_root(const std::string& text);

}  // namespace eomgen
