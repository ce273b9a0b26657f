/// @file The checked build of a parsed model file (build_model, model.hpp): one ModelBuilder with a
/// member per section of the file, each reporting what is wrong where it was written. Its members
/// are defined in build_model.cpp (the header, symbols, definitions, initial state and outputs),
/// build_frames.cpp (frames and points), build_bodies.cpp (particles and rigid bodies: masses,
/// rotations, inertias) and build_forces.cpp (energies, forces, constraints, rolling contact).
#pragma once

#include <map>
#include <set>
#include <optional>
#include <string>
#include <vector>

#include "model/frames.hpp"
#include "model/frame_joints.hpp"
#include "model/model.hpp"

namespace eomgen {

/// The value of a constant expression with parameters at their defaults.
std::optional<double> constant_value(const GiNaC::ex& e, const Symbols& symbols);

/// Whether an expression or a rotation depends on the coordinates or on time (build_joints.cpp).
bool moves_with(const GiNaC::ex& x, const Symbols& s);
bool moves_with(const GiNaC::matrix& R, const Symbols& s);

class ModelBuilder {
 public:
  /// How the frames that the coordinates move are read (build_model() chooses): `as_written`, a
  /// tree of joints when they carry joints, multiplied out in q otherwise; `tree`, also those that
  /// turn and slide by the coordinates (model/frame_joints.hpp; tried first); `composed`, frames
  /// that are no tree of joints composed link by link (kinematics/recursive_kinematics.hpp; tried
  /// next for deep chains); `written_out`, every position and rotation multiplied out in q, but
  /// for ball and free joints
  enum class FrameReading { as_written, tree, composed, written_out };
  ModelBuilder(const ModelFile& file, Diagnostics& d, FrameReading reading = FrameReading::as_written)
      : f_(file), d_(d), reading_(reading) {}
  Model build();

 private:
  // The file's header, symbols, definitions, initial state and outputs (build_model.cpp)
  std::optional<GiNaC::ex> parse(const ExpressionText& text, unsigned allowed, const char* context);
  void check_header();
  void check_spherical_joints();
  void declare(const std::string& name, SourceLocation where, const std::string& key,
               SymbolKind kind, std::size_t index, const char* what);
  void declare_symbols();
  double constant(const ExpressionText& text, const char* context, GiNaC::ex* expression = nullptr);
  // in file order: each may use the symbols and the definitions before it
  void read_definitions();
  void define(const std::string& name, SourceLocation where, const std::string& key, const GiNaC::ex& value);
  // NAME names a vector or a matrix as a whole (to refuse it as a scalar); its components,
  // named as component_name or entry_name give them, are definitions
  void define_whole(const std::string& name, SourceLocation where, const std::string& key, const std::vector<GiNaC::ex>& values);
  void read_initial_state();
  void read_outputs();
  void check_complete();

  // Frames and points (build_frames.cpp)
  // [[frames]] in file order: a parent comes before its children
  void read_frames();
  // the frame link of a frame name for recursive kinematics; -1: the inertial frame (or none)
  int link_of(const std::string& name) const;
  // the links of a frame or a body read as joints (model/frame_joints.hpp), the last named `name`
  PlacedFrame place_joint_links(const std::string& name, int parent_link, const std::vector<JointLink>& links);
  // `name`, or a variant of it, that no frame or link has
  std::string unused_link_name(std::string name) const;
  // a body placed in its frame by the coordinates as the link it reads as (model/frame_joints.hpp),
  // in which it then sits still: its frame's name, or its own when it moves
  std::string body_frame(const std::string& name, const std::string& frame, Vector3& local, Rotation& relative);
  // where a body is, for recursive kinematics; a body outside the frames must not be placed
  // through them (by a point): only the recursion knows how such a position moves
  FramePlacement placement(const std::string& frame_name, const Vector3& local, const Rotation& relative,
                           const SourceLocation& where, const std::string& key);
  // the frame named `name` (the inertial frame when empty), or nothing after an error
  const PlacedFrame* frame(const std::string& name, const SourceLocation& where, const std::string& key);
  void read_points();
  // a frame's joint moves its placement (build_joints.cpp)
  // (what the spatial algorithms need of it; nothing after a mistake)
  std::optional<FrameLink::Joint> move_by_joint(const JointEntry& joint, Rotation& relative, Vector3& origin);
  bool is_constant_placement(const Rotation& rotation, const Vector3& origin) const;
  std::optional<GiNaC::ex> joint_coordinate(const JointEntry& joint);
  std::optional<Vector3> joint_axis(const JointEntry& joint);
  bool follow(const JointEntry& joint, FrameLink::Joint& out);
  // ball and free joints (build_spherical_joints.cpp)
  std::optional<FrameLink::Joint> turn_by_quaternion(const JointEntry& joint, Rotation& relative, Vector3& origin);
  std::optional<std::vector<int>> joint_coordinates(const std::vector<std::string>& names, const SourceLocation& where,
                                                    const std::string& key);
  bool name_angular_velocity(const JointEntry& joint, FrameLink::Joint& out);
  void set_quaternion_rates(const JointEntry& joint, const std::array<int, 4>& quaternion);

  // Particles and rigid bodies (build_bodies.cpp)
  GiNaC::ex mass(const ExpressionText& text, bool rigid_body = false, bool may_be_zero = false);
  Vector3 vector(const std::vector<ExpressionText>& texts, unsigned allowed, const char* context);
  // NAME when the components were read from one string "NAME" (NAME.x, NAME.y, NAME.z)
  static std::string vector_name(const std::vector<ExpressionText>& texts);
  void check_body_name(const std::string& name, const SourceLocation& where, const std::string& key);
  void read_bodies();
  Rotation rotation(const std::optional<RotationEntry>& given);
  bool names_matrix(const std::string& text) const;
  // R^T R = I at the initial state, a cheap guard against a mistyped entry
  void check_orthogonal(const GiNaC::matrix& R, const RotationEntry& where);
  GiNaC::matrix inertia(const RigidBodyEntry& b);
  // A body's second moments J = Σ m r rᵀ = tr(I)/2·E − I are positive semidefinite: in
  // principal axes, every moment is at most the sum of the other two (the triangle
  // inequality, equal for a flat body). Checked with the default parameters.
  void check_realizable(const GiNaC::matrix& I, const RigidBodyEntry& b);

  // What the animation draws (build_drawing.cpp): frames, particles, rigid bodies, points
  void read_drawing();
  std::vector<Shape> shapes(const std::vector<ShapeEntry>& entries);
  // a rigid body without a shape: the box of its mass and inertia
  Shape inertia_box(const RigidBody& body);

  // Energies, forces and constraints (build_forces.cpp)
  std::optional<std::size_t> coordinate_index(const NamedExpression& g, const std::string& key);
  void read_energies_and_forces();
  void read_torque(const ForceEntry& f);
  void read_constraints();
  void add_constraint(const ConstraintEntry& c, bool holonomic, const GiNaC::ex& e, const std::string& name);
  // rolls: the contact condition (unless the coordinates keep it already) and two no-slip conditions
  void read_rolling(const ConstraintEntry& c);
  // a(q,t)·der(q) + b(q,t): every second derivative in the velocities vanishes
  void check_linear_in_velocities(const GiNaC::ex& e, const ExpressionText& text, const char* what);

  const ModelFile& f_;
  Diagnostics& d_;
  FrameReading reading_ = FrameReading::as_written;
  Model m_;
  std::map<std::string, SourceLocation> declared_at_;
  std::map<std::string, int> body_names_;
  std::map<std::string, PlacedFrame> frames_;
  std::map<std::string, int> frame_index_;  // recursive kinematics: a frame's index in m_.frame_links
  // the [[points]] as read_points placed them, for the drawing
  struct PlacedPoint {
    std::string name;
    Vector3 position;
    GiNaC::matrix rotation;
    std::string frame;
  };
  std::vector<PlacedPoint> placed_points_;
  std::set<std::string> angular_velocity_names_;  // of the ball and free joints so far
};

}  // namespace eomgen
