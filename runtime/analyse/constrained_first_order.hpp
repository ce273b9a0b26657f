/// @file Lagrange I models linearized on their constraint manifold. The state x = [q; q']
/// of such a model must satisfy Φ(x) = [g(q); C(q) q' + b(q)] = 0 (the holonomic
/// constraints, and every constraint at velocity level). The tangent space of that
/// manifold is invariant under the linearized flow, so the stability of a steady motion
/// is that of A restricted to it: the constraint directions, which the full A would show
/// as extra zero eigenvalues (Jordan blocks, spread by rounding), do not take part.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

/// Lagrange I: the model's coordinates are tied by multipliers.
bool has_multipliers(const eomgen_model_abi& m);

/// x' and ∂x'/∂x of a Lagrange I model with Baumgarte's gains at zero: the mechanics alone, on the
/// system's own scale (the gains are rates in 1/s of the model's, 10 unless set, which a model
/// scaled in time keeps).
Eigen::VectorXd unstabilized_rate(const Problem& problem, const std::vector<double>& x);
Eigen::MatrixXd unstabilized_jacobian(const Problem& problem, const std::vector<double>& x);

struct ManifoldLinearization {
  std::vector<int> kept;       // the state components that parametrize the tangent space, cyclic positions left out
  Eigen::MatrixXd A, B;        // x_kept' = A x_kept + B u on the tangent space
  Eigen::MatrixXd basis;       // δx = basis · δx_kept (columns: the kept components, the dependent ones solved)
  std::vector<int> dependent;  // the components the constraints determine, in state order
  /// Components no rate depends on (a zero column of A: the heading of a vehicle, its speed),
  /// left out like cyclic coordinates; each would add one zero eigenvalue
  std::vector<int> neutral;
};

/// The tangent space at x (which must satisfy the constraints) in the components of x: the
/// dependent ones are the last in state order that keep the constraint Jacobian of full
/// rank (as for the consistent initial state), the positions by g, the velocities by C. ∂(C q' + b)/∂q comes from the generated Jacobians at two Baumgarte
/// gains: their difference is −2 M⁻¹Cᵀ(C M⁻¹Cᵀ)⁻¹ ∂(C q' + b)/∂x on the manifold.
ManifoldLinearization manifold_linearization(const Problem& problem, const std::vector<double>& x);

}  // namespace eomgen::runtime
