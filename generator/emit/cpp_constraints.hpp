/// @file The constraint part of the generated header: constraint residuals and
/// Jacobian for every model that has constraints, and for Lagrange I the
/// accelerations and multipliers from the augmented (KKT) system with Baumgarte's
/// stabilization. Headers of unconstrained models carry the same names, empty.
#pragma once

#include <string>

#include "derive/equations.hpp"

namespace eomgen {

/// num_constraints, num_multipliers, their names, and the default Baumgarte gains.
std::string constraint_declarations(const Equations& e);
/// detail::ConstrainedSolver (Lagrange I only; empty otherwise).
std::string constrained_solver(const Equations& e);
/// rhs, jacobian_state and jacobian_input of Lagrange I.
std::string constrained_rhs_function(const Equations& e);
std::string constrained_jacobian_state_function(const Equations& e);
std::string constrained_jacobian_input_function(const Equations& e);
/// constraint_jacobian, constraint_residuals, multipliers, rhs_stabilized, jacobian_state_stabilized.
std::string constraint_functions(const Equations& e);

}  // namespace eomgen
