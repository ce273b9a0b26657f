/// @file The symbolic model: a checked model file with every expression
/// parsed into GiNaC. Nothing here is derived yet.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/expression_parser.hpp"
#include "model/symbols.hpp"

namespace eomgen {

using Vector3 = std::array<GiNaC::ex, 3>;

/// A quantity of the recursive kinematics (a frame's rotation entry, its origin, a partial
/// velocity, …): a symbol in the derived expressions, computed from its definition (in model
/// symbols and earlier intermediates) at the top of the generated code.
struct Intermediate {
  GiNaC::symbol symbol;  // a plain symbol, as the generated code's temporaries are
  GiNaC::ex definition;
  std::string cpp_name;
};

/// With recursive kinematics (joints, or frames composed link by link), a frame in its parent:
/// rotation and origin relative to the parent (in q), and the symbols (or constants) of its
/// rotation to inertial components and its inertial origin.
struct FrameLink {
  /// How the frame moves in its parent when it is placed by constants and moved by one joint
  /// (FrameEntry::joint; a frame placed by constants alone is fixed): what the spatial
  /// algorithms over the tree (generator/spatial/) take.
  struct Joint {
    enum class Type { fixed, revolute, prismatic, ball, free };
    Type type = Type::fixed;
    int coordinate = -1;              // revolute, prismatic: index into the coordinates; else -1
    /// the joint turns or slides by multiplier·q + offset (constants): 1 and 0 but for a joint
    /// that follows another's coordinate (URDF's mimic)
    GiNaC::ex multiplier = 1, offset = 0;
    Vector3 axis{0, 0, 0};            // e, a unit vector in the frame's coordinates
    Vector3 anchor{0, 0, 0};          // a point of a revolute joint's axis, frame coordinates
    GiNaC::matrix placement{3, 3};    // R_p: the frame at the joint's zero, parent coordinates
    Vector3 placement_origin{0, 0, 0};
    /// ball and free: R = R_p·R(w, x, y, z) by the quaternion's coordinates (indices), normalized in
    /// R itself; the velocities are ω in the frame's coordinates (pseudo-velocities, Hiller §4.4).
    /// A ball turns about the anchor; a free joint about the origin, which it moves by `position`
    /// in the placement's axes, o = o_p + R_p·(x, y, z).
    std::array<int, 4> quaternion{-1, -1, -1, -1};
    std::array<int, 3> position{-1, -1, -1};
    std::vector<GiNaC::realsymbol> angular_velocity;
    bool spherical() const { return type == Type::ball || type == Type::free; }
  };
  std::optional<Joint> joint;
  std::string name;
  int parent = -1;  // index into Model::frame_links; -1: the inertial frame
  std::vector<ElementaryRotation> sequence;  // the relative rotation as a product, when it is one
  GiNaC::matrix relative_rotation{3, 3};
  Vector3 relative_origin{0, 0, 0};  // parent coordinates
  GiNaC::matrix rotation{3, 3};      // body components to inertial: symbols or constants
  Vector3 origin{0, 0, 0};           // inertial: symbols or constants
};

/// Where a body is placed with recursive kinematics: in frame `frame` at `local` (frame
/// coordinates), turned by `relative` (a rigid body) from the frame; frame -1: not in a frame.
struct FramePlacement {
  int frame = -1;
  Vector3 local{0, 0, 0};
  std::vector<ElementaryRotation> sequence;
  GiNaC::matrix relative{3, 3};
};

struct Particle {
  std::string name;
  GiNaC::ex mass;
  Vector3 position;  // inertial frame
  FramePlacement placement = {};
};

/// R = R1·R2·…·Rk maps body components to inertial ones (r_I = R·r_B).
struct Rotation {
  std::vector<ElementaryRotation> sequence;  // when given as a product; empty otherwise
  GiNaC::matrix matrix{3, 3};                // always the full R
};

struct RigidBody {
  std::string name;
  GiNaC::ex mass;
  Vector3 center;  // centre of mass, inertial frame
  Rotation rotation;
  GiNaC::matrix inertia{3, 3};  // about the centre of mass, body frame
  FramePlacement placement = {};
};

struct PointForce {
  Vector3 at;     // point of application, inertial
  Vector3 force;  // inertial components
};

struct BodyTorque {
  std::size_t body;  // index into rigid_bodies
  Vector3 torque;
  bool inertial_frame = false;
};

struct Constraint {
  bool holonomic = true;
  GiNaC::ex expression;  // = 0
  std::string key;
  std::string name;  // the file's name, or c1, c2, … in file order
};

struct NamedSymbolic {
  std::string name;
  GiNaC::ex expression;
};

/// A scene (DESIGN.md, [scenes.NAME]): what to simulate and which outputs, to what accuracy.
struct Scene {
  std::string name;
  double t_end = 10, dt_out = 0.05;
  std::vector<std::pair<std::string, double>> initial;  // state names (q or der(q)) = value
  std::vector<std::pair<std::size_t, double>> set;      // parameter index = value
  std::vector<std::pair<std::size_t, GiNaC::ex>> inputs;  // input index = u(t, parameters)
  std::vector<std::string> outputs;                     // output, coordinate or der(q) names
  double accuracy = 1e-3, absolute = 0;
};

/// A variant (DESIGN.md, [variants.NAME]): a simpler model declared by the user.
struct Variant {
  std::string name;
  std::vector<std::size_t> neglect;                     // parameters set to zero
  std::vector<std::size_t> freeze;                      // coordinates held at their initial values
  std::vector<std::pair<std::size_t, GiNaC::ex>> tie;   // coordinate = expression of the others (removed)
  std::vector<std::pair<std::size_t, bool>> small_angle;  // coordinate, cos → 1 − φ²/2 (true) or 1
  std::vector<std::pair<std::size_t, GiNaC::ex>> replace;  // parameter = expression
};

/// A shape the animation draws (ShapeEntry), in its body's axes. Sizes: sphere [radius, 0, 0], box
/// [x, y, z] side lengths, capsule and cylinder [radius, length, 0] along `axis`, ellipsoid [a, b, c]
/// radii. A zero size means "the viewer chooses" (a particle's sphere). `rotation`: the shape's
/// axes in the body's (a capsule's axis is turned by it too).
struct Shape {
  enum class Type { sphere, box, capsule, cylinder, ellipsoid };
  Type type = Type::sphere;
  Vector3 size{0, 0, 0};
  Vector3 offset{0, 0, 0};
  Vector3 axis{0, 0, 1};
  GiNaC::matrix rotation = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
};

/// What `eomgen animate` draws of a frame, particle, rigid body or point (model/drawing.hpp): where
/// it is and how it is turned (its axes to inertial ones), in the model's symbols, its parent in
/// the drawing (what a rod joins it to) and its shapes.
struct DrawnBody {
  enum class Kind { frame, particle, rigid_body, point };
  std::string name;
  Kind kind = Kind::frame;
  Vector3 position{0, 0, 0};
  GiNaC::matrix rotation{3, 3};
  int parent = -1;  // index into Model::drawing; -1: the ground
  std::vector<Shape> shapes;
};

/// How the header's rhs solves for q'': eomgen's choice (the articulated-body recursion for a tree
/// of particles from articulated_crossover coordinates on, and for a tree of joints
/// articulated_mean_depth deep on average where its code is shorter, M = L D Lᵀ otherwise), or one
/// form asked for, to compare the two (tests, benchmarks: `eomgen generate --forward-dynamics`).
enum class ForwardDynamics { chosen, mass_matrix, articulated };

/// From this many coordinates on, eomgen solves a particle tree by the
/// recursion: tests/benchmarks/rhs_benchmark.cpp times both forms of the planar chain in one
/// process (tests/benchmarks/README.md, "Against SymPy, MuJoCo and hand-written code"). On 2026-11-25 (an Intel Xeon,
/// sin and cos from the C library) the unrolled LDLᵀ of M took 157 ns against the recursion's 163
/// at n = 8 and 196 against 186 at n = 9; on 2026-11-26 (an AMD EPYC, sin and cos by
/// detail::sin_cos) 155 against 142 at n = 7, 196 against 160 at n = 8, 257 against 190 at n = 9.
/// The batched sin and cos took 14 ns off the recursion at n = 8 and nothing measurable off the
/// LDLᵀ form, so n = 8 is the smallest size at which the recursion is the faster on both machines.
inline constexpr std::size_t articulated_crossover = 8;

/// A tree of joints whose velocities have this many velocities above them and themselves on
/// average, or more, has its rhs by the articulated-body algorithm where that is code of fewer
/// operations than M's (measured in spatial/joint_tree_forward_dynamics.cpp).
inline constexpr double articulated_mean_depth = 4.5;

struct Model {
  std::string name, title, method;
  std::string source;  // the model file's path as given
  Symbols symbols;
  std::vector<Particle> particles;
  std::vector<RigidBody> rigid_bodies;
  Vector3 gravity{0, 0, 0};
  GiNaC::ex kinetic = 0, potential = 0, dissipation = 0;  // the [energy] section
  std::vector<GiNaC::ex> generalized_force;               // one per coordinate
  std::vector<PointForce> point_forces;
  std::vector<BodyTorque> torques;
  std::vector<Constraint> constraints;
  std::vector<NamedSymbolic> pseudo_velocities;
  std::vector<NamedSymbolic> outputs;
  std::vector<Scene> scenes;
  std::vector<Variant> variants;
  bool recursive_kinematics = false;
  ForwardDynamics forward_dynamics = ForwardDynamics::chosen;
  std::vector<FrameLink> frame_links;        // recursive kinematics: the frames, parents first
  std::vector<Intermediate> intermediates;   // the frames' rotations and origins, in order
  std::vector<DrawnBody> drawing;            // frames, particles, rigid bodies and points, in that order
};

/// The derivation methods a model file may name, in the order documented.
const std::vector<std::string>& known_methods();

/// Checks a parsed model file and builds its symbolic model.
/// Mistakes go to `diagnostics`; the result is meaningful only when it stays empty.
/// When the file leaves kinematics out, frames and bodies that read as joints make the model a tree
/// of joints (model/frame_joints.hpp), as frames that carry joints do; `written_out` multiplies
/// every position and rotation out in q instead (but for ball and free joints), as Routh's
/// reduction, another method, diff and the symbolic analyses need.
Model build_model(const ModelFile& file, Diagnostics& diagnostics, bool written_out = false);

/// Checks a form of forward dynamics asked for instead of eomgen's choice (ModelChoice, `generate
/// --forward-dynamics`): the articulated-body recursion needs a tree of particles solved by
/// Lagrange II. Mistakes are located at `where`, the file's start.
void check_forward_dynamics(const Model& model, SourceLocation where, Diagnostics& diagnostics);

/// Checks the [scenes] and [variants] of a file against the model's symbols.
void build_scenes_and_variants(const ModelFile& file, Model& model, Diagnostics& diagnostics);

/// Elementary rotation matrices of the book: rot_x, rot_y, rot_z (axis 0, 1, 2).
GiNaC::matrix elementary_rotation(int axis, const GiNaC::ex& angle);

/// The matrix of one factor of a product: elementary, Rodrigues' formula
/// R = cos φ·I + sin φ·[e]× + (1 − cos φ)·e eᵀ for a turn about the unit vector e, or the constant.
GiNaC::matrix rotation_matrix(const ElementaryRotation& r);

/// The matrix of a product of factors, the identity for none.
GiNaC::matrix rotation_product(const std::vector<ElementaryRotation>& factors);

/// The factor's axis in its own frame (ω_rel = axis·φ'); zero for a constant rotation.
Vector3 rotation_axis(const ElementaryRotation& r);

}  // namespace eomgen
