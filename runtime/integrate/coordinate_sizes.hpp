/// @file The size of each coordinate at a configuration, for the tolerances of the equilibrium
/// checks. An angle's (`is_angle`) and a quaternion component's is one radian, whatever the units;
/// every other coordinate's is the configuration's size in its units: the largest |q| among the
/// non-cyclic coordinates that are neither. One size for all had mixed the two: a spring pendulum
/// of 1e12 m at 0.5 rad passed for an equilibrium, its torque weighed against its stiffness times
/// 1e12 m, and one of 1e-12 m, its torque of 5e-24 N m against the spring's force.
#pragma once

#include <vector>

#include "model_abi.h"

namespace eomgen::runtime {

/// Each coordinate's size at the state x: one for an angle or a quaternion component, else the largest
/// non-cyclic such |q| at x (and in the model's default state where `with_default_state`), or
/// `when_zero` where all of those are zero.
std::vector<double> coordinate_sizes(const eomgen_model_abi& m, const double* x, bool with_default_state,
                                     double when_zero);

}  // namespace eomgen::runtime
