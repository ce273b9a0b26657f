/// @file The expanded derivation as the oracle of a tree's recursions: the same model with its
/// positions and rotations multiplied out (ModelChoice::written_out) gives M, f, T and, by
/// symbolic differentiation of M q'' − f, the derivatives that the spatial algorithms write in
/// closed form. Shared by the tests of joint trees however their frames are written.
#pragma once

#include <map>
#include <random>
#include <string>

#include "derive/equations.hpp"
#include "model/model.hpp"

namespace eomgen::test {

/// The model of a file's text; fails the test on any diagnostic.
Model built(const std::string& text);

/// Parameters (0.5 to 2), coordinates (−2 to 2), their rates and one acceleration ddqK per
/// coordinate (−3 to 3), by name.
std::map<std::string, double> random_point(const Equations& e, std::mt19937& random);

/// M, f, τ and T of `tree_text`, which must build a joint tree, against the same model written out
/// in q at random states, to 1e-11; `n` coordinates.
void expect_expanded_equations(const std::string& tree_text, unsigned n);

/// The bodies' ∂τ/∂q and ∂τ/∂q' in closed form (spatial/joint_tree_derivatives.hpp), plus the
/// derivatives of the applied part, against those of M q'' − f of the expanded derivation,
/// written out in q, differentiated symbolically, at random states, to 1e-11.
void expect_expanded_derivatives(const std::string& tree_text, unsigned n);

}  // namespace eomgen::test
