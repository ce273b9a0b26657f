/// @file How a generated header computes q'' and its derivatives: one choice per model, the
/// alternative of Equations::dynamics that the derivation set (derive/equations.hpp), that every
/// function of the header then follows.
#pragma once

#include "derive/equations.hpp"

namespace eomgen {

enum class DynamicsForm {
  /// M and f written out, q'' = M⁻¹ f by the LDLᵀ of M, the derivatives entry by entry
  mass_matrix,
  /// Hamilton's equations of a larger model: der(q) solves M der(q) = p − bias in the code
  /// (MomentumSolve), the rest as mass_matrix
  momentum,
  /// recursive kinematics: M and f once by the recursions (detail::mass_matrix_and_forcing),
  /// the derivatives from the Newton–Euler τ = M q'' − f (NewtonEulerRecursion, emit/cpp_joint_tree.hpp)
  newton_euler,
  /// a tree of particles: q'', M, f and the derivatives by its articulated-body recursion
  /// (ArticulatedForwardDynamics, emit/cpp_articulated.hpp)
  particle_tree,
};

/// The form of e's header. Lagrange I's multipliers (Equations::has_multipliers) come on top:
/// rhs and the Jacobians solve with the constraints, mass_matrix, forcing and linearization
/// follow the form.
DynamicsForm dynamics_form(const Equations& e);

}  // namespace eomgen
