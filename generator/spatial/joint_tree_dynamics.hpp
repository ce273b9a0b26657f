/// @file The dynamics of a tree of frames joined by joints, by the recursions of multibody
/// codes in each frame's own coordinates (Featherstone's recursive Newton–Euler and
/// composite-rigid-body algorithms, in 3-vector form; Hiller §3.9 for the kinematics).
///
/// It applies when every frame is placed in its parent by constants and moved by one joint
/// (revolute or prismatic about its unit axis e, through its anchor a; ball or free, whose three
/// angular velocities are three such axes e_k of the frame, and a free joint's position three
/// slides along the parent's axes; or fixed), every
/// coordinate moves exactly one joint, and every body sits still in a frame. A link i with
/// parent p then has, in its own coordinates (E_i: i's components to p's, r_i: its origin in p):
///   ω_i = E_iᵀ ω_p + e q̇
///   α_i = E_iᵀ α_p + e q̈ + (E_iᵀ ω_p) × e q̇
///   a_i = E_iᵀ (a_p + α_p × r_i + ω_p × (ω_p × r_i)) + 2 (E_iᵀ ω_p) × u q̇ + u q̈ + q̇² e × u
/// with u = a × e for a revolute joint (the origin's velocity per q̇), u = e for a prismatic one,
/// and the base accelerating at −g, so that gravity needs no term of its own. Backward, each
/// subtree's force F and moment N about the frame's origin, and τ = e·N + u·F. The mass matrix
/// from each subtree's mass m, first moment h and inertia J about the origin: the momentum
/// p = m u + e × h and angular momentum L = J e + h × u that q̇_i = 1 gives it, carried up the
/// tree, M_ji = e_j·L + u_j·p. Every quantity is an intermediate, so the code is O(n) for τ
/// and O(n·depth) for M, where the partial velocities of every frame are O(n²).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"
#include "spatial/joint_tree_derivatives.hpp"
#include "spatial/joint_velocities.hpp"

namespace eomgen {

/// In the tree's velocities s (spatial/joint_velocities.hpp): q' but for ball and free joints.
struct JointTreeDynamics {
  GiNaC::matrix mass_matrix;
  std::vector<GiNaC::ex> bias_forces;       // −τ(q, s, s' = 0): as f takes the bodies' forces, gravity included
  std::vector<GiNaC::ex> inverse_dynamics;  // τ(q, s, s') of the bodies, in the acceleration symbols
  std::vector<int> velocity_parents;        // Equations::coordinate_parents, or empty
  GiNaC::ex kinetic_energy;                 // the bodies' T, from the frames' velocities
  /// ∂τ/∂q and ∂τ/∂s of inverse_dynamics in closed form (spatial/joint_tree_derivatives.hpp)
  JointTreeGradient gradient;
  std::vector<TreeLink> links;  // the links as the gradient and the articulated-body algorithm take them
};

/// Why the model is not such a tree (for a note in the header), or nothing when it is.
std::optional<std::string> why_not_a_joint_tree(const Model& model);

/// The dynamics above; its quantities are appended to `intermediates` (those of q̈ = 0 and of M)
/// and to `acceleration_intermediates` (those of the pass with q̈ = `accelerations`, and of the
/// gradient).
JointTreeDynamics joint_tree_dynamics(const Model& model, const JointVelocities& velocities,
                                      const std::vector<GiNaC::symbol>& accelerations,
                                      std::vector<Intermediate>& intermediates,
                                      std::vector<Intermediate>& acceleration_intermediates);

}  // namespace eomgen
