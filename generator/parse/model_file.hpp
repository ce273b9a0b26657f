/// @file The model file as written: every value still text, each with the
/// place it came from, so that later stages can point at mistakes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/diagnostic.hpp"

namespace eomgen {

/// An expression as written, with the location of its first character.
struct ExpressionText {
  std::string text;
  SourceLocation where;
  std::string key;  // key path, e.g. particles[0].position[1]
};

/// The names under which a named vector's components and a named 3×3 matrix's entries are
/// used in expressions: NAME.x, NAME.y, NAME.z and NAME.xx, NAME.xy, … NAME.zz (row, column).
inline std::string component_name(const std::string& name, std::size_t i) { return name + "." + "xyz"[i]; }
inline std::string entry_name(const std::string& name, std::size_t i, std::size_t j) {
  return component_name(name, i) + "xyz"[j];
}

struct ParameterEntry {
  std::string name;
  double value = 0;
  SourceLocation where;
  std::string key;
};

struct CoordinateEntry {
  std::string name;
  ExpressionText initial;  // a constant expression
  ExpressionText rate;     // a constant expression
  SourceLocation where;
  std::string key;
};

/// `rotation`: either a product such as "rot_z(psi)*rot_x(theta)" or a 3×3 array.
struct RotationEntry {
  std::optional<ExpressionText> product;
  std::vector<std::vector<ExpressionText>> matrix;  // rows, when given as an array
  SourceLocation where;
  std::string key;
};

/// `shape`: what `eomgen animate` draws for a body or frame, in its own axes (parse/parse_shapes.hpp).
/// sphere: size = [radius]; box: size = [x, y, z] side lengths; ellipsoid: size = [a, b, c] radii;
/// capsule and cylinder: size = [radius, length] along `axis` (z unless given). Centred at
/// `offset`, turned by `rotation` (the shape's axes in the body's; after `axis`). Constant expressions.
struct ShapeEntry {
  std::string type;
  std::vector<ExpressionText> size, offset, axis;
  std::optional<RotationEntry> rotation;  // its axes in the body's, when given
  SourceLocation where;
  std::string key;
};

struct ParticleEntry {
  std::string name;
  ExpressionText mass;
  std::vector<ExpressionText> position;  // three components, in `frame` (inertial when empty)
  std::string frame;
  SourceLocation frame_where;
  std::vector<ShapeEntry> shapes;
  SourceLocation where;
  std::string key;
};

struct RigidBodyEntry {
  std::string name;
  ExpressionText mass;
  std::vector<ExpressionText> center;               // three components, in `frame` (inertial when empty)
  std::optional<RotationEntry> rotation;            // relative to `frame`; identity when absent
  std::string frame;
  SourceLocation frame_where;
  std::vector<ExpressionText> principal_inertia;    // three moments, or empty
  std::vector<std::vector<ExpressionText>> inertia; // 3×3 body-frame tensor, or empty
  std::optional<ExpressionText> inertia_name;       // when the tensor is a matrix definition
  /// unphysical_inertia = true: an inertia that breaks the triangle inequality, or has a negative
  /// principal moment, is taken as given (a robot file's values, as `eomgen import` writes them)
  /// instead of refused as a mistake
  bool unphysical_inertia = false;
  std::vector<ShapeEntry> shapes;
  SourceLocation where;
  std::string key;
};

/// [[frames]]: a frame placed in its parent by a rotation and an origin in parent coordinates.
/// A frame's joint: how it moves in its parent beyond its placement (see FrameEntry).
struct JointEntry {
  std::string type;  // revolute, prismatic, fixed, ball or free
  SourceLocation type_where;
  std::vector<ExpressionText> axis;    // in the frame's own coordinates at the joint's zero
  std::vector<ExpressionText> anchor;  // revolute, ball: a point of the axis (the centre), frame coordinates; empty: the origin
  std::string coordinate;              // the coordinate that moves it (revolute, prismatic)
  SourceLocation coordinate_where;
  /// A joint that follows another's coordinate (URDF's mimic, a gear): it turns or slides by
  /// multiplier·q + offset; absent: by q
  std::optional<ExpressionText> multiplier, offset;
  /// ball and free: the coordinates of the unit quaternion w, x, y, z (MJCF's order), the names of the
  /// angular velocity's components in the frame (the velocities), and their initial values;
  /// free: also the coordinates of the origin's position in the parent's axes
  std::vector<std::string> quaternion, position, angular_velocity;
  SourceLocation quaternion_where, position_where, angular_velocity_where;
  std::vector<ExpressionText> initial_angular_velocity;
  SourceLocation where;
  std::string key;
};

/// [[frames]]: a frame placed in its parent by `rotation` and `origin`, then moved by its
/// joint, if it has one: turned about the joint's axis through the anchor, or slid along it,
/// by the coordinate (MJCF's hinge and slide: axis and anchor in the body's own frame).
struct FrameEntry {
  std::string name;
  std::string parent;  // empty: the inertial frame
  SourceLocation parent_where;
  std::optional<RotationEntry> rotation;  // identity when absent
  std::vector<ExpressionText> origin;     // empty: the parent's origin
  std::optional<JointEntry> joint;
  std::vector<ShapeEntry> shapes;
  SourceLocation where;
  std::string key;
};

/// [[points]]: a named point fixed in a frame, usable as a vector (P.x, P.y, P.z; at = "P").
struct PointEntry {
  std::string name;
  std::string frame;  // empty: the inertial frame
  SourceLocation frame_where;
  std::vector<ExpressionText> position;
  SourceLocation where;
  std::string key;
};

/// [definitions]: one expression (a scalar), three (a vector, used as NAME.x, NAME.y, NAME.z) or
/// nine (a 3×3 matrix row by row, used as NAME.xx, NAME.xy, ... NAME.zz).
struct DefinitionEntry {
  std::string name;
  std::vector<ExpressionText> components;
  SourceLocation where;  // of the name
};

struct NamedExpression {
  std::string name;
  ExpressionText expression;
  SourceLocation where;  // of the name
};

struct ForceEntry {
  enum class Kind { generalized, point, torque };
  Kind kind = Kind::generalized;
  std::vector<NamedExpression> generalized;  // coordinate name = expression
  std::vector<ExpressionText> at, force;     // point of application and force, inertial
  std::string body;                          // torque: the rigid body
  SourceLocation body_where;
  std::vector<ExpressionText> torque;
  bool inertial_frame = false;               // torque components in the inertial frame
  SourceLocation where;
  std::string key;
};

struct ConstraintEntry {
  enum class Kind { holonomic, nonholonomic, rolls };
  Kind kind = Kind::holonomic;
  ExpressionText expression;
  // rolls = { body, radius, axis }: a thin disk rolling without slipping on the plane z = 0
  std::string body;
  SourceLocation body_where;
  ExpressionText radius;
  std::vector<ExpressionText> axis;  // the disk's axis in the body frame
  SourceLocation where;
  std::string key;
  std::string name;  // optional; names the multiplier lambda_NAME
  SourceLocation name_where;
};

/// A name as written, with where it was written (an output of a scene, a parameter of a variant).
struct NameText {
  std::string name;
  SourceLocation where;
};

/// [scenes.NAME]: a question asked of the model (what to simulate, what matters, how accurately).
struct SceneEntry {
  std::string name;
  SourceLocation where;
  double t_end = 10, dt_out = 0;  // dt_out 0: t_end / 200
  std::vector<ParameterEntry> initial;  // coordinate or der(coordinate) = number
  std::vector<ParameterEntry> set;      // parameter = number
  std::vector<NamedExpression> inputs;  // input = expression of t
  std::vector<NameText> outputs;        // outputs or coordinates; empty: every coordinate
  double accuracy = 1e-3;               // largest error relative to each output's range
  double absolute = 0;                  // plus this absolute error
};

/// [variants.NAME]: a simpler model the user declares.
struct VariantEntry {
  std::string name;
  SourceLocation where;
  std::vector<NameText> neglect;          // parameters set to zero
  std::vector<NameText> freeze;           // coordinates held at their initial values
  std::vector<NamedExpression> tie;       // coordinate = expression of the other coordinates (a rigid link)
  std::vector<NamedExpression> small_angle;  // coordinate = "quadratic" (cos → 1 − φ²/2) or "one" (cos → 1)
  std::vector<NamedExpression> replace;   // parameter = expression
};

struct ModelFile {
  std::string path;
  /// Every mistake found while reading is a value replaced by a stand-in: the model can
  /// still be built to report the mistakes in names too (but not derived).
  bool only_stand_in_mistakes = false;
  std::string name, title, method = "lagrange2";
  /// The retired keys kinematics and forward_dynamics, when a file still has them (refused with a
  /// hint: eomgen chooses how frames are derived, build_model(), and how the rhs solves for q'',
  /// model.hpp's ForwardDynamics)
  SourceLocation name_where, method_where, kinematics_where, forward_dynamics_where;
  std::vector<ParameterEntry> parameters;
  std::vector<CoordinateEntry> coordinates;
  std::optional<SourceLocation> coordinates_where;  // the [coordinates] section, when there is one
  std::vector<ParameterEntry> inputs;
  std::vector<FrameEntry> frames;
  std::vector<PointEntry> points;
  std::vector<ParticleEntry> particles;
  std::vector<RigidBodyEntry> rigid_bodies;
  std::vector<ExpressionText> gravity;  // empty when there is no [gravity]
  std::optional<ExpressionText> kinetic, potential, dissipation;
  std::vector<ForceEntry> forces;
  std::vector<ConstraintEntry> constraints;
  std::vector<DefinitionEntry> definitions;  // [definitions]: named expressions, in file order
  std::vector<NamedExpression> pseudo_velocities;
  std::vector<NamedExpression> outputs;
  std::vector<SceneEntry> scenes;
  std::vector<VariantEntry> variants;
};

/// Largest model file accepted; anything bigger is refused before parsing.
inline constexpr std::size_t max_model_file_bytes = 1 << 20;

/// Reads and checks the structure of a model file (types, keys, lengths).
/// Mistakes go to `diagnostics`; the result is meaningful only when it stays empty.
ModelFile parse_model_file(const std::string& path, Diagnostics& diagnostics);

/// Same, from text already in memory; `path` names it in diagnostics.
ModelFile parse_model_text(const std::string& text, const std::string& path,
                           Diagnostics& diagnostics);

}  // namespace eomgen
