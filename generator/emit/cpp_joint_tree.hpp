/// @file The generated header's functions for a tree whose τ = M q'' − f comes from the
/// Newton–Euler recursion (recursive kinematics, joint trees): M and f written once
/// (detail::mass_matrix_and_forcing), the factored accelerations that rhs and jacobian_state call,
/// and ∂τ/∂(q, q') (detail::inverse_dynamics_gradient) by a tangent sweep or, for a joint tree,
/// the bodies' part in closed form, whichever has fewer operations; for a long tree of hinges and
/// slides the closed form's loops (emit/cpp_tree_gradient_loops.hpp).
#pragma once

#include <cstddef>
#include <string>

#include "derive/equations.hpp"
#include "emit/cpp_body_writer.hpp"

namespace eomgen {

/// q'' and the factors of M into local arrays ddq, L, D by detail::factored_accelerations.
void call_factored_accelerations(BodyWriter& w, std::size_t n);

/// rhs of a joint tree solved by the articulated-body algorithm (NewtonEulerRecursion::joint_tree_accelerations).
std::string joint_tree_rhs_function(const Equations& e);

/// Whether the header's rhs takes NewtonEulerRecursion::joint_tree_accelerations: where asked for, or where
/// its code has fewer operations than forming M and f, factoring M and solving (emit/operation_count.hpp):
/// oblique joints make turning an articulated inertia dear, so the tree's depth alone does not decide.
bool rhs_takes_articulated_bodies(const Equations& e);

/// detail::mass_matrix_and_forcing, detail::factored_accelerations and
/// detail::inverse_dynamics_gradient, for DynamicsForm::newton_euler: ∂τ/∂(q, q') at a given q''
/// is written once, for jacobian_state (q'' from the solve) and linearization (q'' = 0), and M and
/// f once. (∂τ/∂u = −∂f/∂u is short, and only linearization needs it: jacobian_state's rows are
/// then the gradient's, written in place.) Each "" for the other forms.
std::string factored_accelerations_function(const Equations& e);
std::string newton_euler_gradient_function(const Equations& e);

/// detail::mass_matrix_and_forcing (the other forms: empty), straight-line or, for a long tree of
/// hinges and slides where the straight-line code would take longer, the world pass's loops
/// (emit/cpp_tree_gradient_loops.hpp); its operations, for choosing what calls it (the loops'
/// time counted in operations of straight-line code), and the straight-line code's.
struct MassMatrixAndForcing {
  std::string function;
  long operations = 0, straight_line_operations = 0;
  bool by_loops = false;
};
MassMatrixAndForcing mass_matrix_and_forcing_code(const Equations& e);

/// Whether jacobian_state of a long tree of hinges and slides (below a root joint of any kind) forms M and f
/// from the world pass that its derivatives go on from (detail::tree_acceleration_gradient) rather
/// than by factored_accelerations' straight-line code, whose operations (counted in
/// detail::mass_matrix_and_forcing) decide: a third of a 21-joint tree's jacobian_state.
bool jacobian_takes_tree_pass(const Equations& e, long mass_matrix_and_forcing_operations);
/// detail::tree_acceleration_gradient, for jacobian_takes_tree_pass.
std::string tree_acceleration_gradient_function(const Equations& e);
/// detail::tree_acceleration_gradient in straight-line code for a tree whose bodies' gradient is in
/// closed form (not the loops): M and f from the gradient's own composite inertias and forces at
/// q'' = 0, the solve, and the gradient at the solved q'' (or at given q''), with
/// detail::inverse_dynamics_gradient calling it; to replace `gradient_function` (that function by
/// itself), or "" where it would not have fewer operations than `factored_operations` (M and f,
/// counted in detail::mass_matrix_and_forcing), the factorization and `gradient_function` together.
std::string closed_form_acceleration_gradient_functions(const Equations& e, long factored_operations,
                                                        const std::string& gradient_function);

}  // namespace eomgen
