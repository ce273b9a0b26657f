/// @file One step of the two-stage Gauss–Legendre collocation method (order 4).
/// Implicit, A-stable and symplectic: on Hamilton's equations it keeps the energy
/// error bounded over arbitrarily long runs (Hairer, Lubich, Wanner, Geometric
/// Numerical Integration, §II.1.3 and §IX.3), where explicit Runge–Kutta drifts.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "integrate/stepper.hpp"

namespace eomgen::runtime {

class GaussLegendreStep {
 public:
  explicit GaussLegendreStep(std::size_t size) : n_(size) {}
  /// x ← x(t + h); false when the right-hand side is not finite or Newton's method
  /// on the stage equations does not converge.
  bool step(RightHandSide& f, double t, double h, std::vector<double>& x);
  long jacobian_evaluations() const { return jacobians_; }

 private:
  std::size_t n_;
  long jacobians_ = 0;
  Eigen::VectorXd z_;  // the stage increments of the last step, the next step's first guess
};

}  // namespace eomgen::runtime
