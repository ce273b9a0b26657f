/// @file A robot as a robot description gives it (MJCF, URDF), before it is a model file: bodies
/// in a tree, each placed in its parent and moved by its joints, with its inertia; actuators,
/// sites, gravity, the initial state, and what eomgen cannot carry. Plain data between the reader
/// (mjcf_reader.hpp) and the writer (model_writer.hpp).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace eomgen {

using Triple = std::array<double, 3>;
using Quaternion = std::array<double, 4>;  // w, x, y, z

struct RobotJoint {
  std::string name;
  std::string type;  // hinge, slide, ball or free (MJCF's words)
  Triple axis{0, 0, 1}, anchor{0, 0, 0};  // in the body's frame
  double armature = 0, damping = 0, stiffness = 0;
  std::vector<double> spring_reference;    // the joint's qpos at which the spring is slack
  double reference = 0;                    // a hinge's or slide's qpos0 (MJCF ref): the body's place is at it
  std::vector<double> initial_position;    // its part of qpos
  std::vector<double> initial_velocity;    // its part of qvel
  bool limited = false;
  std::array<double, 2> range{0, 0};
  /// MuJoCo 3's actuatorfrcrange: the actuators' total generalized force on the joint is clamped to it
  bool actuator_force_limited = false;
  std::array<double, 2> actuator_force_range{0, 0};
};

/// A geom that draws the body (MJCF geom: type, half sizes as MuJoCo keeps them, placement in the body).
struct RobotGeom {
  std::string type;  // sphere, capsule, cylinder, box, ellipsoid, mesh, …
  Triple size{0, 0, 0};
  Triple position{0, 0, 0};
  Quaternion orientation{1, 0, 0, 0};
};

struct RobotBody {
  std::string name;
  int parent = -1;  // index into Robot::bodies; −1: the world
  Triple position{0, 0, 0};
  Quaternion orientation{1, 0, 0, 0};  // in the parent's frame
  std::vector<RobotJoint> joints;      // applied in order, each in the frame the previous one left
  double mass = 0;
  Triple center{0, 0, 0};              // centre of mass in the body's frame
  Quaternion inertia_axes{1, 0, 0, 0};  // principal axes of inertia in the body's frame
  Triple principal_inertia{0, 0, 0};
  std::vector<RobotGeom> geoms;  // what `eomgen animate` draws of it
  double gravity_compensation = 0;  // MJCF gravcomp c: a force −c m g at the centre of mass
};

/// One joint of a fixed tendon (MJCF's <fixed>): its length is Σ coefficient × the joint's qpos.
struct TendonJoint {
  int body = -1, joint = -1;
  double coefficient = 1;
};

struct RobotActuator {
  std::string name;
  int body = -1, joint = -1;  // the joint it drives: index into that body's joints (or `tendon`)
  double gain = 1;            // generalized force = gain × control + ... (MJCF: gear × gainprm[0])
  bool limited = false;       // the control is clamped to `range` (MJCF ctrllimited)
  std::array<double, 2> range{0, 0};
  /// A servo (MJCF position and velocity actuators, `general` with an affine bias): the force
  /// along the transmission is gainprm·u + bias[0] + bias[1]·gear·q + bias[2]·gear·q', and the
  /// generalized force gear times it
  std::array<double, 3> bias{0, 0, 0};
  double gear = 1;
  bool force_limited = false;  // the force along the transmission is clamped to `force_range`
  std::array<double, 2> force_range{0, 0};
  /// or the fixed tendon it pulls (then body and joint are −1): its force F along the tendon is
  /// the generalized force coefficient × F on each of the tendon's joints, and its position above
  /// is the tendon's length
  std::vector<TendonJoint> tendon{};
  std::string remark{};  // written beside the input when it has no range (a URDF joint's effort limit)
};

struct RobotSite {
  std::string name;
  int body = -1;
  Triple position{0, 0, 0};
};

/// A named state of the whole robot (an MJCF keyframe): qpos and qvel in MuJoCo's layout.
struct RobotKeyframe {
  std::string name;
  std::vector<double> positions, velocities;
};

/// What the model cannot carry, and the element of the file it is about: `section` (actuator,
/// equality, tendon) and the element's `name`, or its 1-based `ordinal` there when it has none;
/// an empty section for what has no one place (contacts of many geoms).
struct RobotWarning {
  std::string text;
  std::string section;
  std::string name;
  int ordinal = 0;
};

/// A loop closed by an MJCF equality connect, or one of the three a weld is: the point at anchor1 of
/// body1 stays on the point at anchor2 of body2 (−1: the world; anchor2 is then a world point). `kept` are the components, x,
/// y, z in the world, whose rows of the constraint Jacobian are independent at the initial state
/// (a planar loop closes with two).
struct RobotLoop {
  std::string name;
  int body1 = -1, body2 = -1;
  Triple anchor1{0, 0, 0}, anchor2{0, 0, 0};
  std::array<bool, 3> kept{true, true, true};
};

/// Joints coupled by an MJCF equality joint: q1 − ref1 = c0 + c1 d + c2 d² + c3 d³ + c4 d⁴ with
/// d = q2 − ref2 (q1 − ref1 = c0 alone without a second joint); refs are qpos0, joints hinges or slides.
struct RobotCoupling {
  std::string name;
  int body1 = -1, joint1 = -1, body2 = -1, joint2 = -1;  // a body's index and its joint's index in it
  double reference1 = 0, reference2 = 0;
  std::array<double, 5> coefficients{0, 0, 0, 0, 0};
  int equality = -1;  // its place among the file's equality constraints
};

/// A fixed tendon's spring and damper (MJCF's stiffness, damping, springlength): the force
/// −stiffness (L − rest_length) − damping L' along its length L = Σ cᵢ qᵢ.
struct RobotTendonSpring {
  std::string name;
  std::vector<TendonJoint> joints;
  double stiffness = 0, damping = 0, rest_length = 0;
};

struct Robot {
  std::string name;
  std::string reader;  // what read the file, e.g. "MuJoCo 2.2.2's compiler"
  std::string initial_state;  // where the initial state comes from
  Triple gravity{0, 0, -9.81};
  std::vector<RobotBody> bodies;
  std::vector<RobotActuator> actuators;
  std::vector<RobotSite> sites;
  std::vector<RobotKeyframe> keyframes;
  std::vector<RobotLoop> loops;        // Lagrange I constraints of the model
  std::vector<RobotCoupling> couplings;  // the same
  std::vector<RobotTendonSpring> tendon_springs;
  std::vector<RobotWarning> warnings;  // what the model cannot carry, each naming it
  std::vector<std::string> notes;      // how the file was read where that is not plain (carried nonetheless)
};

/// How a robot file is read: a URDF's root link hung from the world by a free joint
/// (free_base.hpp), its links without an <inertial> weighed by their shapes as MuJoCo weighs them,
/// where URDF has them massless (urdf_text.hpp's without_masses_from_geometry); and, for either
/// format, turns within `right_angles_within` radians of a right angle written as exact right
/// angles (right_angles.hpp's rounded_right_angles; 0: only those a unit of rounding off); and
/// `joint_torques`: every hinge and slide driven by an input of its own, a torque or force on its
/// coordinate (Pinocchio's τ; a URDF robot has no actuators MuJoCo reads), besides the file's.
/// read_with_mujoco() takes it.
struct RobotReading {
  bool free_base = false;
  bool masses_from_shapes = false;
  double right_angles_within = 0;
  bool joint_torques = false;
};

}  // namespace eomgen
