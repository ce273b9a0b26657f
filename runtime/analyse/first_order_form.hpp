/// @file The first-order form x' = F(x) for models whose equations are not of
/// second order in the coordinates: Appell's equations with pseudo-velocities,
/// where q' = W(q) s. Their steady motions and linearization come from the
/// generated jacobian_state, on the state without the cyclic coordinates.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

/// Appell and Hamilton models: the state holds pseudo-velocities or momenta, not q'.
bool has_pseudo_velocities(const eomgen_model_abi& m);

/// Indices into x of the reduced state: the non-cyclic coordinates, then all velocities.
std::vector<int> reduced_state(const eomgen_model_abi& m);

/// The cyclic coordinates whose momentum p_q is one of the model's first integrals (no applied
/// force, dissipation or constraint on them at zero inputs): each leaves a zero eigenvalue that the
/// verdicts leave out. A cyclic coordinate under drag is not one (a car's x under c x'|x'|).
int conserved_cyclic_momenta(const eomgen_model_abi& m);

/// ∂x'/∂x at (t, x), the whole state, from the generated jacobian_state (inputs at t).
Eigen::MatrixXd state_jacobian(const Problem& p, double t, const std::vector<double>& x);

/// x' at x, and ∂x'/∂x, both restricted to the reduced state (rows and columns).
Eigen::VectorXd reduced_rate(const Problem& p, const std::vector<double>& x);
Eigen::MatrixXd reduced_jacobian(const Problem& p, const std::vector<double>& x);
/// ∂x'/∂u on the rows of the reduced state.
Eigen::MatrixXd reduced_input_jacobian(const Problem& p, const std::vector<double>& x);

}  // namespace eomgen::runtime
