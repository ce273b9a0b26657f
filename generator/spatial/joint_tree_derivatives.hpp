/// @file ∂τ/∂q and ∂τ/∂q' of a joint tree's bodies in closed form (the analytic derivatives of the
/// recursive Newton–Euler algorithm of Carpentier and Mansard, RSS 2018, derived here in world
/// coordinates), for jacobian_state and linearization. "World" is any frame at rest at this
/// instant: the straight-line form writes them in the axes of the link (about its root's origin)
/// where they take the fewest operations, or the world's (spatial/gradient_frame.hpp).
///
/// In world Plücker coordinates a joint j's motion subspace S_j turns with every joint above it, and
/// a change of q_j moves its whole subtree Φ_j rigidly, by the twist S_j. Whatever turns with Φ_j
/// has the derivative S_j × (·); the parent's velocity v_λ and acceleration a_λ (gravity included)
/// do not turn, and τ_k = S_k·F_k is invariant under turning all of them together. What is left,
/// with Ψ'_j = v_λ × S_j, Ψ''_j = a_λ × S_j + v_λ × Ψ'_j and, for each link, the composite inertia
/// I^C, force F and B^C = Σ B_l with B_l x = I_l (x × v_l) + x ×* (I_l v_l) + v_l ×* (I_l x):
///   ∂τ_k/∂q_j  = S_k·(I^C_k Ψ''_j + B^C_k Ψ'_j)         for k in Φ_j,
///              = S_k·(S_j ×* F_j + I^C_j Ψ''_j + B^C_j Ψ'_j)   for k above j;
///   ∂τ_k/∂q'_j = S_k·(2 I^C_k Ψ'_j + B^C_k S_j)          for k in Φ_j,
///              = S_k·(2 I^C_j Ψ'_j + B^C_j S_j)          for k above j.
/// Per link a fixed cost; per pair of a joint and one it carries, two dot products of six-vectors
/// (with I^C_k S_k and B^C_kᵀ S_k formed once per link), where the tangent sweep through the
/// recursion in joint frames transports tangents of forces and moments for each pair.
/// The same quantities give M and τ at q'' = 0, so that jacobian_state solves for q'' inside the
/// gradient: M_kj = S_k·I^C_k S_j (I^C_k S_k is formed anyway), and with a = a⁰ + α, α = Σ S q''
/// over the joints up to the root, F = F⁰ + Y (F⁰ of a⁰ and the bodies' v ×* I v, Y = Σ I α over
/// the subtree), τ⁰_k = S_k·F⁰_k; the quantities that hold q'' (α, a, Y, F, Ψ'', G) come after.
///
/// A joint of several velocities (ball, free) has one S per velocity. Those that keep the parent's
/// axes (a free joint's position) do not turn when the joint's coordinates change: with w = v_λ + V_p
/// (V_p their part of the joint's velocity) and W = a_λ + A_p + v_λ × V_p (A_p = Σ S s' over them),
/// a coordinate whose unit change is the twist T has Ψ' = w × T and Ψ'' = W × T + w × Ψ', and its
/// own velocity c has 2Ψ' replaced by (w + u_c) × S_c, u_c = v_j for a turning column, v_λ for
/// one that keeps the parent's axes; rows of the joint's own non-turning columns take the formula
/// "above j" (for a hinge, w = v_λ, W = a_λ and T = S: the formulas above). A quaternion component's
/// T is Σ_k Y_kc S_k over the turning columns, Y = ∂s/∂q' (spatial/joint_velocities.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace eomgen {

/// A link of the tree in its parent's joint frame (spatial/joint_tree_dynamics.hpp): its turn E
/// (own components to the parent's), the offset r of its origin, its joint's velocities and the
/// coordinates that move it, and its bodies in its own coordinates.
struct TreeLink {
  std::string name;
  int parent = -1;
  GiNaC::matrix turn{3, 3};
  Vector3 offset{0, 0, 0};
  /// One velocity of the joint: the link's ω (axis) and its origin's velocity per unit rate, in the
  /// link's coordinates; `turns_with_link` unless it keeps the parent's axes (a free joint's position)
  struct Column {
    int velocity = -1;
    GiNaC::ex rate = 0;
    Vector3 axis{0, 0, 0}, origin_velocity{0, 0, 0};
    bool turns_with_link = true;
  };
  std::vector<Column> columns;
  /// A coordinate of the joint and the twist its unit change gives the link, as weights of the
  /// columns: 1 on its own column (a hinge's angle, a slide's or free joint's position), or a
  /// quaternion component's angular velocity per unit rate on the three turning columns
  struct Direction {
    int coordinate = -1;
    std::vector<std::pair<std::size_t, GiNaC::ex>> weights;
  };
  std::vector<Direction> directions;
  struct Body {
    GiNaC::ex mass;
    Vector3 center;
    GiNaC::matrix inertia{3, 3};  // about the centre
  };
  std::vector<Body> bodies;
  /// A root hinge's or slide's turn and offset at its coordinate's zero (their values at q for any
  /// other link): the pose its subtree's quantities may be formed in where the coordinate is
  /// cyclic for the bodies' forces (joint_tree_derivatives.cpp)
  std::optional<std::pair<GiNaC::matrix, Vector3>> rest_pose;
};

/// A root joint of several velocities (a floating base's free joint, a ball; the joint of `link`, one
/// without a parent) in world Plücker coordinates, for the loops below: its motion depends on its own
/// coordinates and velocities alone, so it is straight-line code, and the loops add what needs the
/// composite quantities.
/// Per column (a velocity) its S and A = (w + u) × S, and whether it turns with the link; per
/// direction (a coordinate) its twist T, Ψ' and Ψ''; the link's v and a (gravity included).
struct JointedRoot {
  std::size_t link = 0;
  std::vector<int> velocity;
  std::vector<bool> turns;
  std::vector<std::array<GiNaC::ex, 6>> S, A;
  std::vector<int> coordinate;
  std::vector<std::array<GiNaC::ex, 6>> twist, dS, ddS;
  std::array<GiNaC::ex, 6> v, a;
};

/// The derivatives above for a long tree of joints whose velocities all turn with their links
/// (hinges, slides, ball joints), as loops over its links in the header
/// (emit/cpp_tree_gradient_loops.hpp), from each link's data in its parent's joint frame: its
/// parent; per column of its joint (none for a fixed link) its velocity, its twist in the link's
/// own coordinates (axis; origin velocity) and its rate; per direction its coordinate and its
/// twist's weights over the link's columns (a hinge's or slide's 1 on its one column, a quaternion
/// component's Y = ∂s/∂q'); its turn E (row-major) and offset r; and its bodies' spatial inertia
/// about its origin in its own coordinates (m, h = Σ m c, J's xx xy xz yy yz zz). The loops form the
/// world poses, twists and inertias, v, a, Ψ', Ψ'', the composite quantities and the pairs from
/// them. A root link's joint (one without a parent) may be of any kind (`roots`: a floating base, a
/// free object beside it, whose columns keep the parent's axes; its table entries are then a fixed
/// link's, with its turn and offset those of its current pose).
struct TreeLinkTables {
  std::vector<int> parent;
  std::vector<std::vector<int>> velocity;    // per link, per column
  std::vector<std::vector<int>> coordinate;  // per link, per direction
  std::vector<std::array<GiNaC::ex, 9>> turn;
  std::vector<Vector3> offset;
  std::vector<std::vector<std::array<GiNaC::ex, 6>>> column;  // per link, per column
  std::vector<std::vector<GiNaC::ex>> rate;                   // per link, per column
  std::vector<std::vector<std::vector<GiNaC::ex>>> weight;    // per link, per direction, over its columns
  std::vector<std::array<GiNaC::ex, 10>> inertia;
  Vector3 gravity{0, 0, 0};
  std::vector<JointedRoot> roots;
  /// the most columns and directions of one link: 1 and 1 for a tree of hinges and slides, whose
  /// loops take each direction's twist as its column's
  std::size_t most_columns() const;
  std::size_t most_directions() const;
};

/// The closed form as expressions, for straight-line code: ∂τ/∂q and ∂τ/∂s, and from the same
/// quantities the bodies' M = ∂τ/∂q'' (M_kj = S_k·I^C_k S_j) and τ at q'' = 0 (S_k·F⁰_k), so that
/// jacobian_state may solve for q'' without forming M and f a second time.
struct InverseDynamicsGradient {
  GiNaC::matrix coordinates;  // ∂τ_i/∂q_j, velocities × coordinates
  GiNaC::matrix velocities;   // ∂τ_i/∂s_j, velocities × velocities
  GiNaC::matrix mass_matrix;  // velocities × velocities
  std::vector<GiNaC::ex> bias;
};

/// A joint tree's closed form: as expressions, or, for a long tree whose joints turn with their
/// links, as the inputs of the header's loops over its links, which form the same quantities at run
/// time.
using JointTreeGradient = std::variant<InverseDynamicsGradient, TreeLinkTables>;

/// A joint tree's τ in two parts for its derivatives: the bodies', whose ∂τ/∂(q, s) are the
/// closed form above, and the rest (applied forces, [energy], dissipation), whose derivatives the
/// header's tangent sweep takes.
struct BodiesGradient {
  std::vector<GiNaC::ex> applied_inverse_dynamics;
  JointTreeGradient closed_form;
  /// the closed form's expressions, or null where the loops take it
  const InverseDynamicsGradient* expressions() const { return std::get_if<InverseDynamicsGradient>(&closed_form); }
  /// the loops' inputs, or null where the closed form is expressions
  const TreeLinkTables* loops() const { return std::get_if<TreeLinkTables>(&closed_form); }
};

/// Every expression of g that the header writes (the applied τ, the closed form's entries, the
/// loops' tables and root motion): what the intermediates kept for the header must cover.
std::vector<GiNaC::ex> written_expressions(const BodiesGradient& g);

/// The derivatives above, of τ at the accelerations `ddq`, for the tree's velocities and
/// coordinates (links parents first); their quantities are appended to `out` as intermediates.
/// Straight-line code for them grows with the tree's pairs of joints, loops do not: a tree of
/// more than 8 velocities and more than 32 pairs of a joint and one at or above it, counted by
/// velocities (200 pairs for a tree that moves in one plane, spatial/planar_tree.hpp; the measured
/// crossovers, in gradient_form.cpp), whose joints
/// are hinges, slides and ball joints, those that follow another's coordinate too, below root
/// joints of any kind (a floating base, free objects beside it), gets the loops' inputs instead,
/// unless its straight-line gradient folds to no more operations than a seven-joint arm's (a few
/// axes along the links' own, slides).
JointTreeGradient joint_tree_gradient(const std::vector<TreeLink>& links, const Vector3& gravity,
                                      const std::vector<GiNaC::ex>& ddq, std::size_t velocities, std::size_t coordinates,
                                      std::vector<Intermediate>& out);

/// The closed form above in the axes of link `reference` about its root's origin (none: the
/// world's), which written_out_gradient (spatial/gradient_frame.hpp) chooses among by their
/// operations: the same entries in every frame, since each is a product of a motion and a force.
InverseDynamicsGradient gradient_in(const std::vector<TreeLink>& links, const Vector3& gravity, const std::vector<GiNaC::ex>& ddq,
                                    std::size_t velocities, std::size_t coordinates, std::vector<Intermediate>& out,
                                    std::optional<std::size_t> reference);

}  // namespace eomgen
