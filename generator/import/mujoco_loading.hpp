/// @file Loading a robot file with MuJoCo 2.2.2's compiler (mj_loadXML), read again from memory
/// with the changes a file needs first, each recorded for a warning or a note: MuJoCo 3's attributes
/// left out (newer_mjcf.hpp) or written as 2.2.2 reads them (carried_newer_mjcf.hpp: the spring and
/// damper flags, position servos' kv and inheritrange, joints' actuator force ranges), placeholders for mesh files it
/// cannot read (missing_meshes.hpp), mass bounds for moving bodies without mass (massless_bodies.hpp),
/// a URDF's fixed links kept and its unreadable meshes left out (urdf_text.hpp).
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <mujoco/mujoco.h>

#include "import/gravity_compensation.hpp"
#include "import/newer_mjcf.hpp"
#include "import/passive_flags.hpp"

namespace eomgen {

/// Why MuJoCo cannot read the file: its message, and the line it names (0: none).
struct UnreadableRobot {
  UnreadableRobot() = default;
  UnreadableRobot(int line_, std::string message_, std::string hint_)
      : line(line_), message(std::move(message_)), hint(std::move(hint_)) {}
  int line = 0;
  std::string message;
  std::string hint;    // what to do; empty: that the file must be one MuJoCo's compiler accepts
  std::string file;    // the file of the line when it is one the file includes; empty: the file itself
  std::string object;  // the name of the object MuJoCo's message is about, if it names one
  bool moves_no_mass = false;  // a joint moves only massless bodies (without_massless_joints)
};

/// MuJoCo's error text as a message and a line ("line = 9", "Line number=5").
UnreadableRobot unreadable_robot(const std::string& mujoco_error);

/// As unreadable_robot, for the MJCF file at `path`: where MuJoCo gives no line (an element of an
/// included file), the first line in the file or those it includes that names its object.
UnreadableRobot unreadable_mjcf(const std::string& mujoco_error, const std::string& path);

/// What was left out of or changed in the file so that MuJoCo 2.2.2 could read it.
struct LeftOut {
  int meshes = 0;
  std::string mesh_error;                // why: MuJoCo's message about the first mesh
  int unread_mesh_files = 0;             // MJCF: mesh files read as placeholders (missing_meshes.hpp)
  std::string unread_mesh_names;         // the first of them
  std::vector<int> mesh_sized_geoms;     // geoms that a placeholder sized: not drawn
  std::vector<std::string> unread_drawing_files;  // texture and skin files MuJoCo cannot read (missing_textures.hpp)
  bool mass_bounds = false;              // read with massless_bodies.hpp's bounds
  bool balanced_inertias = false;        // a URDF read with balanceinertia (unbalanced_inertias.hpp)
  bool positive_moments = false;         // a URDF read with its links of moments not above zero restated (the same)
  std::vector<NewerMjcf> newer;     // attributes and sensors of later MuJoCo versions (newer_mjcf.hpp)
  PassiveSwitches passive_flags;         // MuJoCo 3.3.6's spring and damper flags (passive_flags.hpp)
  GravityCompensations gravity_compensation;  // the bodies' gravcomp, read before it is left out
  bool servo_damping_as_user = false;    // <position kv, dampratio> read as the actuators' user values (servo_damping.hpp)
  bool force_range_as_user = false;      // joints' actuatorfrcrange read as their user values (joint_force_limits.hpp)
  bool force_range_left_out = false;     // or, where they cannot be, left out with actuatorfrclimited
  bool inheritrange_as_group = false;    // <position inheritrange> read as the actuators' group (inherited_ranges.hpp)
  bool automatic_limits = false;         // read with MuJoCo 3's default autolimits="true" (automatic_limits.hpp)
  int frames_as_bodies = 0;              // <frame> elements read as welded bodies (frame_elements.hpp)
};

/// The model of the file at `path` (a URDF's `urdf` text, empty for MJCF), with what was changed in
/// `left_out`; nullptr with MuJoCo's message in `error` (of `size` bytes), or why it is refused.
std::variant<mjModel*, UnreadableRobot> loaded_model(const std::string& path, const std::string& urdf, char* error, int size,
                                                     LeftOut& left_out);

/// The file's bytes, or nothing when it cannot be read (MuJoCo says so then).
std::string text_of_file(const std::string& path);

/// The MJCF file at `path` and, after it, every file it includes however deep, each by its path
/// (MuJoCo takes an included name relative to the first file's folder) and its text.
std::vector<std::pair<std::string, std::string>> mjcf_sources(const std::string& path);

}  // namespace eomgen
