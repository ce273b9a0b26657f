/// @file How much of a Newton step the equilibrium searches take (equilibrium.cpp,
/// first_order_equilibrium.cpp).
#pragma once

#include <cmath>

namespace eomgen::runtime {

/// The part of a Newton step to take: all of it when it all but solves the equations (the largest
/// residual after it below a thousandth of before: a linear problem, or one near its root, in any
/// units), else at most half a unit (half a radian for an angle, half the configuration's size for a
/// length: `largest` is in the coordinates' sizes), so that the search stays near where it started.
/// Limited alone, a spring of 1e-6 N/m, whose mass hangs 9.81e6 m down, was out of reach.
template <class Residual>
double step_fraction(double largest, double residual, const Residual& residual_after_whole_step) {
  if (largest <= 0.5) return 1.0;
  double after = residual_after_whole_step();
  return std::isfinite(after) && after <= 1e-3 * residual ? 1.0 : 0.5 / largest;
}

/// The largest of 1, 1/2, 1/4, … (down to 2^-60) of a Newton step after which the residual is
/// smaller than before: steps in the solution's own scale, where half a unit is none (a top's
/// precession at 4e3 rad/s from 2e3)
template <class Residual>
double backtracked_fraction(double residual, const Residual& residual_after) {
  double fraction = 1;
  for (int halvings = 0; halvings < 60 && !(residual_after(fraction) < residual); ++halvings) fraction /= 2;
  return fraction;
}

}  // namespace eomgen::runtime
