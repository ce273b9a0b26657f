/// @file The generated header's functions for a model whose rhs solves for q'' by the
/// articulated-body recursion (Equations::articulated): the rhs itself, O(n) code
/// without M; M and ∂τ/∂(q, q', u) of τ = M q'' − f as loops over the coupled pairs of coordinates
/// (∂τ/∂x written once, for linearization); and jacobian_input, which applies M⁻¹ by the same
/// recursion, a block of columns at a time (jacobian_state: emit/cpp_articulated_jacobian.hpp).
#pragma once

#include <string>

#include "derive/equations.hpp"

namespace eomgen {

std::string articulated_rhs_function(const Equations& e);
/// mass_matrix from the recursion's quantities: M_jl = m̄ S_j · S_l in a loop.
std::string articulated_mass_matrix_function(const Equations& e);
/// detail::inverse_dynamics_gradient (∂τ/∂(q, q', u) of τ = M q'' − f, for linearization); the
/// articulated jacobian_state is in emit/cpp_articulated_jacobian.hpp.
std::string articulated_inverse_dynamics_gradient_function(const Equations& e);
/// jacobian_input from the input columns of ∂τ/∂(q, q', u) alone, M⁻¹ by the recursion.
std::string articulated_jacobian_input_function(const Equations& e);
std::string articulated_linearization_function(const Equations& e);

}  // namespace eomgen
