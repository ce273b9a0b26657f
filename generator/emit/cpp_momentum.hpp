/// @file Hamilton's equations in mass-matrix form in the generated header, x = [q; p], with der(q)
/// solving M der(q) = p − b in the code (Equations::solves_for_velocities): their Jacobian and
/// linearization, which the general forms would write through M⁻¹.
#pragma once

#include <string>

#include "derive/equations.hpp"

namespace eomgen {

/// jacobian_state of such equations.
std::string momentum_jacobian_state_function(const Equations& e);

/// linearization of such equations, read off their Jacobians.
std::string momentum_linearization_function(const Equations& e);

}  // namespace eomgen
