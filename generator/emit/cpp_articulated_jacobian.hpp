/// @file jacobian_state of a model solved by the articulated-body recursion, entry by entry: every
/// column of ∂τ/∂x of a tree of particles is a uniform field on a subtree plus a force at its top,
/// and the recursion's factors carry its response to each coordinate in O(1) operations, so the
/// 2n² entries cost O(n²) without forming M⁻¹ or solving for it column by column.
#pragma once

#include <string>

#include "derive/equations.hpp"

namespace eomgen {

/// detail::inverse_dynamics_gradient (for linearization), then jacobian_state.
std::string articulated_jacobian_state_function(const Equations& e);

}  // namespace eomgen
