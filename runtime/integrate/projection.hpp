/// @file Projection of a state onto the constraint manifold: positions onto
/// g(q,t) = 0, then (Lagrange I) velocities onto C q' + b = 0; and the quaternions
/// of ball and free joints onto |q| = 1.
#pragma once

#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

class ConstraintProjection {
 public:
  explicit ConstraintProjection(const Problem& problem) : p_(problem) {}
  /// Projects x in place; false when Newton's method on g(q) = 0 does not converge
  /// or the constraint Jacobian is rank deficient there. Quaternions are divided by
  /// their lengths (their rotation is that of q/|q|, so the mechanics do not change).
  bool project(double t, double* x);
  /// A consistent initial state: the first coordinates and velocities (in file order)
  /// are kept as given, the last ones that the constraints determine are solved for;
  /// entries marked in `given` (num_states, or empty) are solved for only when the
  /// constraints cannot be met otherwise.
  bool make_consistent(double t, double* x, const std::vector<bool>& given = {});
  long projections() const { return projections_; }
  /// The largest | |q| − 1 | of a quaternion that project() corrected.
  double largest_quaternion_correction() const { return largest_quaternion_correction_; }
  /// Largest |g| and |C q' + b| at x.
  std::pair<double, double> residuals(double t, const double* x) const;

 private:
  bool project_positions(double t, double* x);
  bool project_velocities(double t, double* x);
  const Problem& p_;
  long projections_ = 0;
  double largest_quaternion_correction_ = 0;
};

}  // namespace eomgen::runtime
