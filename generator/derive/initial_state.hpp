/// @file The initial state x0 = [q0; v0] of derived equations for given parameter
/// values: the model file's initial values are expressions in the parameters
/// (`initial = "l0 + m*g/k"`), so an overridden parameter moves them; for Appell's
/// equations v0 are the pseudo-velocities their definitions give at (q0, q0').
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

/// x0 with `parameters` in parameter_names order; the name of the first value that is
/// not a finite real number is put in `failed` and nothing is returned.
std::optional<std::vector<double>> initial_state(const Equations& e, const std::vector<double>& parameters,
                                                 std::string& failed);

}  // namespace eomgen
